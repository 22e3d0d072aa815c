"""Immutable value trees: generated group classes, built and updated by path copying.

An update copies only the groups on the path to each changed leaf, so a
snapshot is just a reference to the current root (O(1), never torn, never
shared mutable state) and one set costs O(depth x group width), not O(N).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any, TypeVar

from genparams.naming import attribute_name

_READ_ONLY = (
    "{cls}.{name} is read-only: change parameters through the node "
    "(set_parameters, ros2 param set), and read them here"
)


class Group:
    """Base of every generated class. Instances are read-only values."""

    __slots__ = ()

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(_READ_ONLY.format(cls=type(self).__name__, name=name))

    def __delattr__(self, name: str) -> None:
        raise AttributeError(_READ_ONLY.format(cls=type(self).__name__, name=name))

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return all(getattr(self, f) == getattr(other, f) for f in field_names(type(self)))

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        fields = ", ".join(f"{f}={getattr(self, f)!r}" for f in field_names(type(self)))
        return f"{type(self).__name__}({fields})"


G = TypeVar("G", bound=Group)

_FIELDS: dict[type[Group], tuple[str, ...]] = {}


def field_names(cls: type[Group]) -> tuple[str, ...]:
    """The value attributes a generated class declares in its own ``__slots__``."""
    names = _FIELDS.get(cls)
    if names is None:
        names = tuple(cls.__dict__.get("__slots__", ()))
        _FIELDS[cls] = names
    return names


def build_tree(
    root_cls: type[G],
    groups: Mapping[str, type[Group]],
    values: Mapping[str, Any],
    extra: Mapping[str, Any] | None = None,
) -> G:
    """A new tree from dotted ROS names -> typed values. ``extra`` fills non-field slots."""
    nested: dict[str, Any] = {}
    for name, value in values.items():
        parts = name.split(".")
        level = nested
        for part in parts[:-1]:
            level = level.setdefault(part, {})
        level[parts[-1]] = value

    def make(cls: type[Group], path: str, level: dict[str, Any]) -> Group:
        node = object.__new__(cls)
        for key, value in level.items():
            child_path = f"{path}.{key}" if path else key
            if child_path in groups:
                value = make(groups[child_path], child_path, value)
            object.__setattr__(node, attribute_name(key), value)
        return node

    root = make(root_cls, "", nested)
    for name, value in (extra or {}).items():
        object.__setattr__(root, name, value)
    return root  # type: ignore[return-value]


def copy_node(node: G, extra: Iterable[str] = ()) -> G:
    new = object.__new__(type(node))
    for name in (*field_names(type(node)), *extra):
        object.__setattr__(new, name, getattr(node, name))
    return new


def replace_values(root: G, updates: Mapping[tuple[str, ...], Any], extra: Iterable[str] = ()) -> G:
    """A new root with the leaves at the attribute paths replaced, sharing everything else."""
    by_head: dict[str, dict[tuple[str, ...], Any]] = {}
    leaves: dict[str, Any] = {}
    for path, value in updates.items():
        if len(path) == 1:
            leaves[path[0]] = value
        else:
            by_head.setdefault(path[0], {})[path[1:]] = value
    new = copy_node(root, extra)
    for name, value in leaves.items():
        object.__setattr__(new, name, value)
    for name, sub_updates in by_head.items():
        object.__setattr__(new, name, replace_values(getattr(root, name), sub_updates))
    return new


def get_path(root: Group, path: tuple[str, ...]) -> Any:
    node: Any = root
    for name in path:
        node = getattr(node, name)
    return node


def to_dict(node: Group) -> dict[str, Any]:
    """Nested dict keyed by ROS names (``from`` rather than the attribute ``from_``)."""
    out: dict[str, Any] = {}
    for attr in field_names(type(node)):
        value = getattr(node, attr)
        key = attr[:-1] if attr.endswith("_") and attribute_name(attr[:-1]) == attr else attr
        out[key] = to_dict(value) if isinstance(value, Group) else value
    return out
