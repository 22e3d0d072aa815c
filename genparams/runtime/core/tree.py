"""Immutable value trees: generated group classes, built and updated by path copying.

An update copies only the groups on the path to each changed leaf, so a
snapshot is just a reference to the current root (O(1), never torn, never
shared mutable state) and one set costs O(depth x group width), not O(N).
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Collection, Iterable, Iterator, Mapping
from typing import Any, ClassVar, TypeGuard, TypeVar, cast, final

from genparams.runtime.core.changes import same_value
from genparams.runtime.core.naming import ENTRY_KEY, MAP_SLOT, attribute_name

_READ_ONLY = (
    "{cls}.{name} is read-only: change parameters through the node "
    "(set_parameters, ros2 param set), and read them here"
)


class Group:
    """Base of every generated class. Instances are read-only values.

    Like a tuple or a frozen dataclass they copy and pickle: a copy of a frozen
    value is the value itself, and pickling records the field values (the
    class must be importable, as any pickled class must).
    """

    __slots__ = ()
    _DETACHED: ClassVar[tuple[str, ...]] = ()  # non-field slots, None in copies
    # True when groups of one shape share this class at run time (see SchemaSpec.table):
    # its own name would then misname the others, so it shows as "Group".
    _SHARED: ClassVar[bool] = False

    def __copy__(self) -> Group:
        return self if self._is_frozen() else _rebuild(type(self), self._field_values())

    def __deepcopy__(self, memo: dict[int, Any]) -> Group:
        return self.__copy__()  # every value inside is immutable already

    def __reduce__(self) -> tuple[Any, ...]:
        return (_rebuild, (type(self), self._field_values()))

    def _is_frozen(self) -> bool:
        return all(getattr(self, name, None) is None for name in self._DETACHED)

    def _field_values(self) -> tuple[Any, ...]:
        return tuple(getattr(self, f) for f in field_names(type(self)))

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(_READ_ONLY.format(cls=_shown_name(type(self)), name=name))

    def __delattr__(self, name: str) -> None:
        raise AttributeError(_READ_ONLY.format(cls=_shown_name(type(self)), name=name))

    def __eq__(self, other: object) -> bool:
        if other is self:
            return True
        if type(other) is not type(self):
            return NotImplemented
        return all(same_value(getattr(self, f), getattr(other, f)) for f in field_names(type(self)))

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        fields = ", ".join(f"{f}={getattr(self, f)!r}" for f in field_names(type(self)))
        return f"{_shown_name(type(self))}({fields})"


def _shown_name(cls: type[Group]) -> str:
    return "Group" if cls._SHARED else cls.__name__


G = TypeVar("G", bound=Group)


@final
class GroupMap(Mapping[str, G]):
    """The entries of a mapped group (``for_each``), by key: a read-only value like a group.

    The entries of a per-item parameter (a leaf with ``for_each``) are its values.

    Keys live in a mapping, not in attributes, so no key can hide a field or
    a method, and keys need not be Python identifiers.
    """

    __slots__ = ("_entries",)
    _entries: dict[str, G]

    def __init__(self, entries: Mapping[str, G] | None = None) -> None:
        object.__setattr__(self, "_entries", dict(entries or {}))

    def __getitem__(self, key: str) -> G:
        return self._entries[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._entries)

    def __len__(self) -> int:
        return len(self._entries)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(_READ_ONLY.format(cls="GroupMap", name=name))

    def __copy__(self) -> GroupMap[G]:
        return self

    def __deepcopy__(self, memo: dict[int, Any]) -> GroupMap[G]:
        return self

    def __reduce__(self) -> tuple[Any, ...]:
        return (GroupMap, (self._entries,))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, GroupMap):
            return NotImplemented
        return self._entries == other._entries

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"GroupMap({self._entries!r})"


def _rebuild(cls: type[Group], values: tuple[Any, ...]) -> Group:
    """A frozen group of ``cls`` from its field values (copy and unpickle)."""
    node = object.__new__(cls)
    for name, value in zip(field_names(cls), values, strict=True):
        object.__setattr__(node, name, value)
    for name in cls._DETACHED:
        object.__setattr__(node, name, None)
    return node


def _is_map(node: object) -> TypeGuard[GroupMap[Any]]:
    """Exact type test: ``isinstance`` against a Mapping goes through the ABC
    machinery, a few hundred ns per test and several tests per set."""
    return type(node) is GroupMap


_FIELDS: dict[type[Group], tuple[str, ...]] = {}
# Attribute -> ROS name of each class's fields, recorded when a tree is first built:
# `lambda_` is the attribute of ROS `lambda`, but also of a ROS name `lambda_`.
_ROS_KEYS: dict[type[Group], dict[str, str]] = {}


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
    maps: Collection[str] = (),
) -> G:
    """A new tree from dotted ROS names -> typed values. ``extra`` fills non-field slots.

    ``groups`` and ``maps`` are keyed by template paths: a mapped group
    ``gains`` (in ``maps``) holds one ``groups["gains.*"]`` per key.
    """
    nested: dict[str, Any] = {}
    for name, value in values.items():
        parts = name.split(".")
        level = nested
        for part in parts[:-1]:
            level = level.setdefault(part, {})
        level[parts[-1]] = value

    # Every group and map exists even when no value lies below it (a map without keys).
    children: dict[str, list[str]] = {}
    for path in (*groups, *maps):
        parent, _, name = path.rpartition(".")
        if name and name != ENTRY_KEY:
            children.setdefault(parent, []).append(name)

    def entries(template: str, level: Mapping[str, Any]) -> GroupMap[Any]:
        entry = f"{template}.{ENTRY_KEY}" if template else ENTRY_KEY
        cls = groups.get(entry)
        if cls is None:  # one parameter per item: the entries are the values
            return GroupMap(level)
        return GroupMap({k: make(cls, entry, v) for k, v in level.items()})

    def make(cls: type[Group], template: str, level: dict[str, Any]) -> Group:
        for name in children.get(template, ()):
            level.setdefault(name, {})
        if cls not in _ROS_KEYS:  # interned: the same few names recur in every class
            _ROS_KEYS[cls] = {
                sys.intern(attribute_name(key, top_level=not template)): sys.intern(key)
                for key in level
            }
        node = object.__new__(cls)
        if template in maps and (template in groups or not template):
            # An in-place map: the names that are not fields are its entries' keys.
            fields = set(field_names(cls))
            top = not template
            keyed = {
                k: v for k, v in level.items() if attribute_name(k, top_level=top) not in fields
            }
            level = {k: v for k, v in level.items() if k not in keyed}
            object.__setattr__(node, MAP_SLOT, entries(template, keyed))
        for key, value in level.items():
            child = f"{template}.{key}" if template else key
            if child in maps and child not in groups:
                value = entries(child, value)
            elif child in groups:
                value = make(groups[child], child, value)
            object.__setattr__(node, attribute_name(key, top_level=not template), value)
        return node

    root = make(root_cls, "", nested)
    for name, value in (extra or {}).items():
        object.__setattr__(root, name, value)
    return root  # type: ignore[return-value]


_Copier = tuple[tuple[Callable[[Any], Any], Callable[[Any, Any], None]], ...]
_COPIERS: dict[type[Group] | tuple[type[Group], tuple[str, ...]], _Copier] = {}


def _copier(cls: type[Group], extra: tuple[str, ...]) -> _Copier:
    """The (read, write) functions of every slot: its descriptor's, not lookups by name.

    Copying groups is most of the cost of a set. Going through the slot
    descriptors skips the attribute lookups by name on the class; in a node's
    set path (caches cold from rclpy's own work) that measured 5-8 us faster
    per set than ``getattr`` / ``object.__setattr__`` or ``attrgetter``.
    """
    slots = tuple(_slot(cls, name) for name in (*field_names(cls), *extra))
    copier = tuple((slot.__get__, slot.__set__) for slot in slots)
    _COPIERS[(cls, extra) if extra else cls] = copier
    return copier


def _slot(cls: type[Group], name: str) -> Any:
    for klass in cls.__mro__:
        if name in klass.__dict__:
            return klass.__dict__[name]
    raise AttributeError(f"{cls.__name__} has no slot {name!r}")


def copy_node(node: G, extra: Iterable[str] = ()) -> G:
    if _is_map(node):  # entries of a mapped group stand where groups do
        return cast(G, GroupMap(node._entries))
    cls = type(node)
    extra = tuple(extra)
    copier = _COPIERS.get((cls, extra) if extra else cls) or _copier(cls, extra)
    new = object.__new__(cls)
    for read, write in copier:
        write(new, read(node))
    return new


def replace_values(root: G, updates: Mapping[tuple[str, ...], Any], extra: Iterable[str] = ()) -> G:
    """A new root with the leaves at the attribute paths replaced, sharing everything else."""
    if len(updates) == 1:  # the common case of one set: no grouping by head
        ((path, value),) = updates.items()
        return _replace_one(root, path, value, tuple(extra))
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
        child = replace_values(_child(root, name), sub_updates)
        if _is_map(new):
            new._entries[name] = child  # the copy is not shared yet
        else:
            object.__setattr__(new, name, child)
    return new


def reuse_values(root: G, updates: Mapping[tuple[str, ...], Any], extra: Iterable[str] = ()) -> G:
    """``root`` with the leaves at the attribute paths replaced, changed in place where
    nobody but its parent can see a group, copied where anyone else holds it.

    For a tree no reader can reach any more (the root a binding replaced): a group
    referenced only by its parent (``root``: only by the one attribute the caller
    passes it from, as in ``reuse_values(holder.spare, ...)``) is reachable by no
    thread but through that parent, so writing it in place is invisible, and no
    thread can start holding it meanwhile. A group anyone else holds (a snapshot,
    ``cam = cfg.camera``, an ``on_change`` record, the live view, the other root)
    has a higher reference count and is copied, as ``replace_values`` copies; so
    are its descendants on the path, whose count the copy raises. Maps of entries
    are always copied (an iterator over one holds its dict, not the map).
    """
    if _ONLY_HOLDER and sys.getrefcount(root) == _ONLY_HOLDER and not _is_map(root):
        new = root
    else:
        new = copy_node(root, extra)
    if len(updates) == 1:  # one set: no grouping by head
        for path, value in updates.items():
            _reuse_below(new, path, value)
        return new
    by_head: dict[str, dict[tuple[str, ...], Any]] = {}
    for path, value in updates.items():
        if len(path) > 1:
            by_head.setdefault(path[0], {})[path[1:]] = value
        elif _is_map(new):
            new._entries[path[0]] = value
        else:
            object.__setattr__(new, path[0], value)
    for name, sub_updates in by_head.items():
        child = reuse_values(_child(new, name), sub_updates)
        if _is_map(new):
            new._entries[name] = child
        else:
            object.__setattr__(new, name, child)
    return new


def _reuse_below(node: Any, path: tuple[str, ...], value: Any) -> None:
    """``reuse_values`` of one path below a group already written in place or copied."""
    refs = sys.getrefcount
    only = _ONLY_HOLDER
    *heads, leaf = path
    for name in heads:
        parent = node
        if type(parent) is GroupMap:
            node = parent._entries[name]
        else:
            node = getattr(parent, name)
        if refs(node) == only and type(node) is not GroupMap:
            continue  # written in place
        node = copy_node(node)
        if type(parent) is GroupMap:
            parent._entries[name] = node
        else:
            _set_slot(parent, name, node)
    if type(node) is GroupMap:
        node._entries[leaf] = value
    else:
        _set_slot(node, leaf, value)


_set_slot = object.__setattr__  # a module global: no attribute lookup on every set


class _Holder:
    __slots__ = ("node",)
    node: object


def _held_by(node: object) -> int:
    return sys.getrefcount(node)


def _only_holder_count() -> int:
    """What ``sys.getrefcount`` reads for a node that one attribute holds, inside a
    function that has it in one variable; 0 (never reuse) where counts do not tell
    (not CPython, or a free-threaded build)."""
    gil = getattr(sys, "_is_gil_enabled", lambda: True)()  # False in a free-threaded build
    if sys.implementation.name != "cpython" or not gil:
        return 0
    holder = _Holder()
    holder.node = object()
    alone = _held_by(holder.node)
    node = holder.node
    in_variable = sys.getrefcount(node)  # in a variable here, as a parameter there
    also_held = [node]
    del node
    if _held_by(holder.node) != alone + 1 or in_variable != alone or not also_held:
        return 0
    return alone


_ONLY_HOLDER = _only_holder_count()


def _child(node: Any, name: str) -> Any:
    return node[name] if _is_map(node) else getattr(node, name)


def _replace_one(root: G, path: tuple[str, ...], value: Any, extra: tuple[str, ...]) -> G:
    chain: list[Any] = [root]
    for name in path[:-1]:
        chain.append(_child(chain[-1], name))
    for depth in range(len(path) - 1, -1, -1):
        new = copy_node(chain[depth], extra if depth == 0 else ())
        if _is_map(new):
            new._entries[path[depth]] = value  # the copy is not shared yet
        else:
            object.__setattr__(new, path[depth], value)
        value = new
    return value  # type: ignore[no-any-return]


def get_path(root: Group, path: tuple[str, ...]) -> Any:
    """The value at an attribute path; through a mapped group, the path holds the key."""
    node: Any = root
    for name in path:  # _child inlined: every set reads the old value
        node = node._entries[name] if type(node) is GroupMap else getattr(node, name)
    return node


def to_dict(node: Group, *, top_level: bool = True) -> dict[str, Any]:
    """Nested dict keyed by ROS names (``from`` rather than the attribute ``from_``)."""
    out: dict[str, Any] = {}
    ros_keys = _ROS_KEYS.get(type(node), {})
    for attr in field_names(type(node)):
        value = getattr(node, attr)
        if attr == MAP_SLOT:  # in-place entries sit beside the fields, by key
            out.update((k, _entry_dict(entry)) for k, entry in value.items())
            continue
        key = ros_keys.get(attr) or _ros_key_guess(attr, top_level=top_level)
        if isinstance(value, GroupMap):
            out[key] = {k: _entry_dict(entry) for k, entry in value.items()}
        elif isinstance(value, Group):
            out[key] = to_dict(value, top_level=False)
        else:
            out[key] = value
    return out


def _entry_dict(entry: Any) -> Any:
    """An entry of a mapped group as a dict; a per-item parameter's entry is its value."""
    return to_dict(entry, top_level=False) if isinstance(entry, Group) else entry


def _ros_key_guess(attr: str, *, top_level: bool) -> str:
    """The ROS name of an attribute of a class no tree was built of: renamed ones lose the `_`."""
    ros = attr[:-1]
    renamed = attr.endswith("_") and attribute_name(ros, top_level=top_level) == attr
    return ros if renamed else attr
