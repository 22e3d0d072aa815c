"""Entries of mapped groups: templates (``gains.*.p``) expanded over key lists. Pure Python."""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from typing import Any

from genparams.runtime.core.conditions import controlling_names
from genparams.runtime.core.naming import ENTRY_KEY, ENTRY_KEY_RULE, OVERRIDE_KEYS, is_entry_key
from genparams.runtime.core.problems import ParameterProblem
from genparams.runtime.core.records import Record, store
from genparams.runtime.core.resolve import resolve_values
from genparams.runtime.core.spec import CompiledParam, CompiledSchema


def map_chain(template_name: str) -> tuple[str, ...]:
    """The maps a template lies in, outermost first: ``a.*.b.*.x`` -> ``a``, ``a.*.b``."""
    parts = template_name.split(".")
    return tuple(".".join(parts[:i]) for i, part in enumerate(parts) if part == ENTRY_KEY)


def _fill(parts: Sequence[str], keys: Sequence[str]) -> list[str]:
    chosen = iter(keys)
    return [next(chosen) if part == ENTRY_KEY else part for part in parts]


def template_keys(template_name: str, name: str) -> list[str] | None:
    """The keys that fill the ``*`` of a template to give ``name``, or None if it has
    another shape: ``gains.*.p`` and ``gains.elbow.p`` -> ``["elbow"]``."""
    pattern = template_name.split(".")
    parts = name.split(".")
    if len(pattern) != len(parts):
        return None
    keys = []
    for part, expected in zip(parts, pattern, strict=True):
        if expected == ENTRY_KEY:
            keys.append(part)
        elif part != expected:
            return None
    return keys


def instantiate(template: CompiledParam, keys: Sequence[str]) -> CompiledParam:
    """The parameter of one entry: each ``*`` of the template replaced by the next key."""
    name = ".".join(_fill(template.name.split("."), keys))
    path = tuple(_fill(template.attribute_path, keys))
    return template.with_path(name, path)


def key_slot(compiled: CompiledSchema, map_path: str) -> str:
    """Where ``values`` hold a map's keys: its for_each parameter, or for an open group
    (``for_each: overrides``) a name of its own that no parameter can have."""
    key_name = compiled.maps[map_path]
    return f"{OVERRIDE_KEYS}{map_path}" if key_name == OVERRIDE_KEYS else key_name


def open_maps(compiled: CompiledSchema) -> tuple[str, ...]:
    """The open groups: keyed by the names their overrides hold (``for_each: overrides``)."""
    return tuple(m for m, key_name in compiled.maps.items() if key_name == OVERRIDE_KEYS)


def keys_under(map_path: str, names: Iterable[str]) -> list[str]:
    """The keys an open group's entries have among ``names``, in order of first appearance:
    the segment after ``map_path`` of each name with more segments below it."""
    depth = len(map_path.split("."))
    found: list[str] = []
    for name in names:
        parts = name.split(".")
        if len(parts) > depth + 1 and ".".join(parts[:depth]) == map_path:
            if parts[depth] not in found:
                found.append(parts[depth])
    return found


def override_keys(
    compiled: CompiledSchema, names: Iterable[str], full_name: Callable[[str], str]
) -> tuple[dict[str, list[str]], list[ParameterProblem]]:
    """The keys of each open group, by key slot, from the relative ``names`` given
    (``sensors.front.topic`` gives ``front`` to ``sensors``), in order of first
    appearance; and a problem for each key that cannot name an entry."""
    keys: dict[str, list[str]] = {}
    problems: list[ParameterProblem] = []
    names = list(names)
    for map_path in open_maps(compiled):
        found = keys_under(map_path, names)
        for key in [k for k in found if not is_entry_key(k)]:
            found.remove(key)
            problems.append(
                ParameterProblem(
                    full_name(map_path),
                    f"key {key!r} given in the overrides cannot name an entry: "
                    f"use {ENTRY_KEY_RULE}",
                )
            )
        keys[key_slot(compiled, map_path)] = found
    return keys, problems


def expand(
    compiled: CompiledSchema,
    values: Mapping[str, Any],
    existing: Mapping[str, CompiledParam] | None = None,
) -> dict[str, CompiledParam]:
    """Every entry's parameter for the key lists in ``values`` (maps whose key is absent: none).

    Entries found in ``existing`` (by name) are reused rather than built again.
    """
    existing = existing or {}
    entries: dict[str, CompiledParam] = {}
    for template in compiled.templates.values():
        key_lists = [values.get(key_slot(compiled, m)) for m in map_chain(template.name)]
        if any(keys is None for keys in key_lists):
            continue
        parts = template.name.split(".")
        for keys in itertools.product(*key_lists):  # type: ignore[arg-type]
            name = ".".join(_fill(parts, keys))
            entry = existing.get(name)
            entries[name] = entry if entry is not None else instantiate(template, keys)
    return entries


def _controlling(compiled: CompiledSchema) -> dict[str, CompiledParam]:
    """The parameters that conditions (``when``) read."""
    names = {
        name
        for param in compiled.parameters.values()
        for name in controlling_names(param.spec.when)
    }
    return {name: compiled.parameters[name] for name in names}


def flatten(values: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    """Dotted names -> values from nested and dotted keys (no parameter value is a mapping)."""
    out: dict[str, Any] = {}
    for key, value in values.items():
        name = f"{prefix}.{key}" if prefix else str(key)
        if isinstance(value, Mapping):
            out.update(flatten(value, name))
        else:
            out[name] = value
    return out


def resolve_all(
    compiled: CompiledSchema,
    read: Callable[[Iterable[str]], Mapping[str, Any]],
    full_name: Callable[[str], str] = lambda name: name,
    source: str = "override",
    lenient: bool = False,
    given_names: Iterable[str] = (),
) -> tuple[dict[str, CompiledParam], dict[str, Any], list[ParameterProblem]]:
    """Parameters (fixed ones, then entries) with their starting values, and every problem.

    Key parameters are fixed, so their values are known before the entries
    they key are expanded. ``read`` gives the ROS-form values given for names;
    ``given_names`` are the relative names given at all, whose segments under an
    open group (``for_each: overrides``) are its keys.
    A parameter with a condition (``when``) whose condition does not hold is
    left out of the parameters, and its value is None.
    """
    parameters = dict(compiled.parameters)
    given = read(parameters)
    conditional = [name for name, param in parameters.items() if param.spec.when]
    if conditional:
        controlling, _ = resolve_values(compiled, given, parameters=_controlling(compiled))
        for name in conditional:
            if not parameters[name].spec.declared_with(controlling):
                del parameters[name]
    values, problems = resolve_values(
        compiled, given, full_name, source, parameters=parameters, lenient=lenient
    )
    values.update((name, None) for name in conditional if name not in parameters)
    if compiled.templates:
        keys, key_problems = override_keys(compiled, given_names, full_name)
        problems.extend(key_problems)
        entries = expand(compiled, {**values, **keys})
        entry_values, entry_problems = resolve_values(
            compiled, read(entries), full_name, source, parameters=entries, lenient=lenient
        )
        parameters.update(entries)
        values.update(entry_values)
        problems.extend(entry_problems)
    return parameters, values, problems


PLACES_BEYOND = 1000  # see map_places


class MapPlace(Record):
    """One mapped group of a schema message where it stands on a node: ``path`` is the
    group's place (``controllers.front.gains`` for the group ``controllers.*.gains``),
    ``keys`` its entries' keys there."""

    _fields = ("group", "path", "keys")
    __slots__ = _fields
    group: Mapping[str, Any]  # the message's map: path, for_each, fields (full names)
    path: str
    keys: tuple[str, ...]

    def __init__(self, group: Mapping[str, Any], path: str, keys: tuple[str, ...]) -> None:
        store(self, "group", group)
        store(self, "path", path)
        store(self, "keys", keys)

    @property
    def is_open(self) -> bool:
        """Keyed by the overrides (``for_each: overrides``), not by a key list."""
        return str(self.group["for_each"]).endswith(OVERRIDE_KEYS)

    @property
    def fields(self) -> list[Mapping[str, Any]]:
        """The fields of each entry (one named "" is the entry itself); those of a group
        inside the entry (``tips.*.force``) are left to that group's own places."""
        return [f for f in self.group["fields"] if ENTRY_KEY not in str(f["name"]).split(".")]

    def entries(self) -> Iterator[tuple[str, Mapping[str, Any]]]:
        """Each parameter of its entries, by full name, with its field."""
        for key in self.keys:
            for field in self.fields:
                yield ".".join(p for p in (self.path, key, field["name"]) if p), field


class _KeysIndex:
    """The keys under every namespace of ``names`` (:func:`keys_under` for any place), from
    a tree of their segments built on first use: one pass over the names."""

    def __init__(self, names: Iterable[str]) -> None:
        self.names = names
        self.tree: dict[str, Any] | None = None

    def keys(self, path: str) -> tuple[str, ...]:
        if self.tree is None:
            self.tree = {}
            for name in self.names:
                branch = self.tree
                for part in name.split("."):
                    branch = branch.setdefault(part, {})
        level: dict[str, Any] | None = self.tree
        for part in path.split("."):
            level = level.get(part) if level is not None else None
        return () if level is None else tuple(key for key, below in level.items() if below)


def map_places(maps: Iterable[Mapping[str, Any]], values: Mapping[str, Any]) -> list[MapPlace]:
    """Every place of the mapped groups of a schema message (``maps``, with full names) on a
    node whose parameters are ``values`` (by full name): a group inside an entry of another
    stands once per key of the outer one. The keys are the key list's value, or for an
    open group the names declared under it.

    A node holds a parameter in every place its own schema has (a little more for entries
    it failed to declare): places past one per parameter, plus PLACES_BEYOND, are not
    listed, so a schema message nesting groups deep over long lists cannot make the
    reader expand a product of them. Each group's places are found once, and the keys of
    open groups in one pass over the names: the work grows with the message and the
    node's names, not with a power of the nesting."""
    groups = {str(m["path"]): m for m in maps}
    budget = len(values) + PLACES_BEYOND
    declared = _KeysIndex(values)
    found_places: dict[str, list[str]] = {}

    def keys_at(group: Mapping[str, Any], path: str) -> tuple[str, ...]:
        if str(group["for_each"]).endswith(OVERRIDE_KEYS):
            return declared.keys(path)
        listed = values.get(str(group["for_each"]))
        if not isinstance(listed, (list, tuple)):
            return ()
        return tuple(k for k in listed if isinstance(k, str))

    def places(path: str) -> list[str]:
        known = found_places.get(path)
        if known is not None:
            return known
        dotted = f".{path}."
        star = dotted.rfind(f".{ENTRY_KEY}.")  # the innermost entry the group lies in
        outer, rest = dotted[1:star], dotted[star + len(ENTRY_KEY) + 2 : -1]
        if star < 0 or outer not in groups:
            found_places[path] = [path]
            return found_places[path]
        found: list[str] = []
        for place in places(outer):
            for key in keys_at(groups[outer], place):
                if len(found) >= budget:
                    break
                found.append(".".join(p for p in (place, key, rest) if p))
        found_places[path] = found
        return found

    listed: list[MapPlace] = []
    for path, group in groups.items():
        for place in places(path):
            if len(listed) >= budget:
                return listed
            listed.append(MapPlace(group, place, keys_at(group, place)))
    return listed
