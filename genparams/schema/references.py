"""Checks of schema names that point at other names: ``for_each`` targets and ``aliases``.

They run once the whole tree is built, since a reference may point anywhere in it.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Protocol

from genparams.runtime.core import naming
from genparams.runtime.core.conditions import NOT_KEY, NoneOf, tested_values
from genparams.runtime.core.suggest import did_you_mean
from genparams.runtime.core.types import ValueTypeError
from genparams.schema.loader import Path
from genparams.schema.model import Group, Parameter


class Report(Protocol):
    def __call__(self, path: Path, message: str, *, at_key: bool = False) -> None: ...


def _inside(parts: tuple[str, ...], template: tuple[str, ...]) -> bool:
    """``parts`` equals or lies under ``template``; ``*`` in a template matches any token."""
    if len(parts) < len(template):
        return False
    return all(t in (p, naming.ENTRY_KEY) for p, t in zip(parts, template, strict=False))


def _overlap(a: tuple[str, ...], b: tuple[str, ...]) -> bool:
    """One name equals the other or lies under it; ``*`` (an entry key) matches any token."""
    return all(x == y or naming.ENTRY_KEY in (x, y) for x, y in zip(a, b, strict=False))


def check_maps(
    root: Group,
    mapped: Sequence[tuple[Group, Path]],
    leaf_paths: dict[str, Path],
    report: Report,
    unbuilt: Callable[[str], bool] = lambda name: False,
) -> None:
    """Each ``for_each`` names a fixed string_array parameter whose default keys entries.

    ``unbuilt``: whether a name was left out for a problem of its own, already reported.
    """
    fixed = {p.ros_name: p for p in root.walk_parameters() if naming.ENTRY_KEY not in p.path}
    # In-place maps are left out: their entries sit beside fixed names, none "inside" them.
    map_paths = [(group.path, group.ros_name) for group, _ in mapped if not group.in_place]
    for group, doc_path in mapped:
        where = (*doc_path, "for_each")
        target = group.mapped_over
        if target == naming.OVERRIDE_KEYS:
            if naming.FROM_OVERRIDES in fixed:
                report(
                    where,
                    f"for_each: {naming.FROM_OVERRIDES} takes the keys from the overrides, "
                    f"but the schema also has a parameter {naming.FROM_OVERRIDES!r}: rename it",
                )
            continue
        param = fixed.get(target)
        if param is None:
            if not unbuilt(target):
                report(where, _missing_target(target, fixed, map_paths))
        elif param.type.name != "string_array":
            report(
                where,
                f"for_each names {target!r}, which is of type {param.type.name}; "
                "it must name a string_array parameter",
            )
        elif param.optional or param.when:
            report(
                where,
                f"for_each names {target!r}, an optional or conditional parameter; the "
                "items that key entries need a value: give it a default, and no when",
            )
        elif param.default is not None:  # None: required, or a bad default already reported
            reason = naming.entry_key_problem(param.default, group.ros_name)
            if reason is None and group.in_place:
                beside = _names_beside(root, group.path)
                reason = naming.entry_beside_problem(param.default, group.ros_name, beside)
            if reason is not None:
                report((*leaf_paths[target], "default"), f"default violates for_each: {reason}")


def _names_beside(root: Group, path: tuple[str, ...]) -> set[str]:
    """The fixed names of the namespace at ``path``, beside its in-place entries."""
    depth = len(path)
    return {
        p.path[depth]
        for p in root.walk_parameters()
        if p.path[:depth] == path and len(p.path) > depth and p.path[depth] != naming.ENTRY_KEY
    }


_CONDITION_TYPES = ("bool", "int", "double", "string")


def check_conditions(
    root: Group,
    conditional: Sequence[tuple[Parameter, Path]],
    report: Report,
    unbuilt: Callable[[str], bool] = lambda name: False,
) -> None:
    """Each ``when`` names a fixed, unconditional scalar parameter, with values of its type."""
    fixed = {p.ros_name: p for p in root.walk_parameters() if naming.ENTRY_KEY not in p.path}
    for param, doc_path in conditional:
        where = (*doc_path, "when")
        if naming.ENTRY_KEY in param.path or param.aliases:
            what = "inside a mapped group" if naming.ENTRY_KEY in param.path else "with aliases"
            report(where, f"when is not supported {what}", at_key=True)
        for name, test in param.when:
            target = fixed.get(name)
            at = (*where, name)
            if target is None:
                if not unbuilt(name):
                    report(
                        at,
                        f"when names {name!r}, which is not a parameter{did_you_mean(name, fixed)}",
                        at_key=True,
                    )
                continue
            if target.when or target is param or target.type.name not in _CONDITION_TYPES:
                report(
                    at,
                    f"when names {name!r}: it must name a parameter of type bool, int, "
                    "double or string that has no when itself",
                    at_key=True,
                )
                continue
            if isinstance(test, NoneOf):
                at = (*at, NOT_KEY)
            for value in tested_values(test):
                try:
                    target.type.coerce_default(value)
                except ValueTypeError as exc:
                    report(at, f"value {value!r} does not match {name!r}: {exc}")


def _missing_target(
    target: str, fixed: dict[str, Parameter], map_paths: list[tuple[tuple[str, ...], str]]
) -> str:
    if not naming.is_ros_name(target):
        return f"for_each must be a dotted parameter name, got {target!r}"
    if target == naming.FROM_OVERRIDES:
        return (
            "for_each: overrides keys the entries of a namespace; a parameter with for_each "
            "needs a string_array parameter naming its items"
        )
    parts = tuple(target.split("."))
    for path, name in map_paths:
        if _inside(parts, path) and len(parts) > len(path):
            return (
                f"for_each names {target!r}, inside mapped group {name!r}, where every "
                "entry has its own copy; it must name a parameter outside every mapped group"
            )
    if any(name.startswith(target + ".") for name in fixed):
        return f"for_each names {target!r}, a namespace; it must name a string_array parameter"
    return f"for_each names {target!r}, which is not a parameter{did_you_mean(target, fixed)}"


def check_aliases(
    root: Group, aliases: Sequence[tuple[str, Path, Parameter]], report: Report
) -> None:
    """Old names are ROS names that collide with no parameter, namespace or other old name."""
    taken = [(p.path, f"parameter {p.ros_name!r}") for p in root.walk_parameters()]
    for alias, where, param in aliases:
        if naming.ENTRY_KEY in param.path:
            report(where, f"aliases are not supported inside a mapped group ({param.ros_name!r})")
            continue
        if not naming.is_ros_name(alias):
            report(where, f"invalid alias {alias!r}: dot-separated names of {naming.NAME_RULE}")
            continue
        parts = tuple(alias.split("."))
        clash = next((_clash(alias, parts, o, w) for o, w in taken if _overlap(parts, o)), None)
        if clash is not None:
            report(where, clash)
        else:
            taken.append((parts, f"alias {alias!r} of {param.ros_name!r}"))


def _clash(alias: str, parts: tuple[str, ...], other: tuple[str, ...], what: str) -> str:
    if naming.ENTRY_KEY in other[: len(parts)]:
        mapped = ".".join(other[: other.index(naming.ENTRY_KEY)])
        return f"alias {alias!r} collides with the entries of mapped group {mapped!r}"
    if len(parts) == len(other):
        return f"alias {alias!r} collides with {what}"
    where = "lies under" if len(parts) > len(other) else "is a namespace of"
    return f"alias {alias!r} {where} {what}; a name cannot be both a value and a namespace"
