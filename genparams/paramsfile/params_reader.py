"""Read a params file the way ROS does, keeping where every key and value was written.

The result is what each node section hands a node: dotted parameter names and
values typed by ROS's rules (ros_yaml). What ROS refuses outright (aliases, a
value where a node name or ``ros__parameters`` belongs, an empty value, a list
mixing types) is reported as a problem with its place, as is what ROS accepts
silently but cannot be meant (a parameter set twice in one section).
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass, field
from typing import Any

import yaml

from genparams.paramsfile.rcl_lists import contains_mapping, read_list
from genparams.paramsfile.ros_yaml import (
    PARAMS_KEY,
    NoValue,
    absolute,
    node_pattern_problem,
    ros_scalar,
    ros_type_name,
)
from genparams.schema.errors import Location, SchemaError, SchemaProblem
from genparams.schema.loader import LoadedDocument, Path, compose_yaml, dotted, yaml_events


@dataclass(frozen=True)
class ParamEntry:
    name: str  # dotted, as ROS joins nested keys
    value: Any  # what rclpy hands the node: bool, int, float, str, a list; None for "not set"
    key_location: Location
    value_location: Location
    written_empty: bool = False  # [] or {}: ROS reads "not set"


@dataclass(frozen=True)
class Section:
    node: str  # the section's node name or pattern, absolute: "/**", "/ns/camera"
    node_location: Location
    params_location: Location  # of the ros__parameters key
    entries: tuple[ParamEntry, ...]


@dataclass(frozen=True)
class ParamsDocument:
    file: str
    sections: tuple[Section, ...]
    problems: tuple[SchemaProblem, ...]


def read_params_file(text: str, file: str) -> ParamsDocument:
    """Every section and parameter of a params file, and what ROS would refuse.

    A YAML syntax error leaves nothing to read and is returned as the only problem.
    """
    try:
        document, problems = compose_yaml(text, file, scalar=_ros_scalar)
        aliases = _aliases(text, file)
    except SchemaError as exc:
        return ParamsDocument(file, (), exc.problems)
    reader = _Reader(document)
    duplicates = set(document.duplicate_keys)
    reader.problems.extend(_as_parameter_problem(p, p in duplicates) for p in problems)
    reader.problems.extend(aliases)
    reader.read()
    return ParamsDocument(file, tuple(reader.sections), tuple(reader.problems))


def _as_parameter_problem(problem: SchemaProblem, duplicate: bool) -> SchemaProblem:
    """A problem of the YAML named as ROS names the parameter; a duplicate key also says
    what ROS does about it (other problems, such as an unsupported tag, do not)."""
    _, marker, name = problem.key.partition(f".{PARAMS_KEY}.")
    key = name if marker else problem.key
    message = f"{problem.message}; ROS keeps the later value" if duplicate else problem.message
    return SchemaProblem(problem.location, key, message)


def _ros_scalar(node: yaml.ScalarNode) -> Any:
    return ros_scalar(node.value, node.style)


def _aliases(text: str, file: str) -> list[SchemaProblem]:
    problems = []
    for event in yaml_events(text):
        if isinstance(event, yaml.AliasEvent):
            mark = event.start_mark
            line, column = (mark.line + 1, mark.column + 1) if mark is not None else (1, 1)
            problems.append(
                SchemaProblem(
                    Location(file, line, column),
                    "",
                    f"alias *{event.anchor}: ROS refuses params files with aliases",
                )
            )
    return problems


@dataclass
class _Reader:
    document: LoadedDocument
    sections: list[Section] = field(default_factory=list)
    problems: list[SchemaProblem] = field(default_factory=list)
    # In the section being read: (entries before and with it, where, name) of each {}.
    empty_mappings: list[tuple[int, Location, str]] = field(default_factory=list)

    def problem(self, location: Location, key: str, message: str) -> None:
        self.problems.append(SchemaProblem(location, key, message))

    def read(self) -> None:
        data = self.document.data
        if data is None:
            return
        if not isinstance(data, dict):
            self.problem(
                self.document.value_location(()),
                "",
                "a params file is a mapping of node names to sections "
                f"(/node_name: {{{PARAMS_KEY}: {{...}}}})",
            )
            return
        self.node_level(data, (), ())

    def node_level(self, mapping: dict[str, Any], path: Path, names: tuple[str, ...]) -> None:
        params_seen = False
        for key, value in mapping.items():
            key_path = (*path, key)
            where = self.document.key_location(key_path)
            # ROS compares only the start of the key with ros__parameters.
            if key.startswith(PARAMS_KEY):
                self.section(key_path, names, value)
                params_seen = True
                continue
            if params_seen and isinstance(value, dict):
                # rcl closes the node name at ros__parameters: a node nested after it
                # loses its namespace, and rcl fails on its first parameter.
                self.problem(
                    where,
                    key,
                    f"a node nested after {PARAMS_KEY} of {absolute('/'.join(names))}: "
                    f"ROS refuses the file (write the nested nodes before {PARAMS_KEY})",
                )
            if _looks_like_params_key(key):
                self.problem(
                    where,
                    key,
                    f"unknown key {key!r} (did you mean {PARAMS_KEY!r}?): ROS refuses the file",
                )
            elif isinstance(value, dict):
                self.node_level(value, key_path, (*names, key))
            else:
                where_to = (
                    f"under {absolute('/'.join(names))}: {{{PARAMS_KEY}: ...}}"
                    if names
                    else f"under /node_name: {{{PARAMS_KEY}: ...}}"
                )
                self.problem(
                    self.document.value_location(key_path),
                    dotted(key_path),
                    f"a value outside {PARAMS_KEY}: ROS refuses the file "
                    f"(parameters go {where_to})",
                )

    def section(self, key_path: Path, names: tuple[str, ...], value: Any) -> None:
        where = self.document.key_location(key_path)
        if not names:
            self.problem(where, PARAMS_KEY, "no node name above it: ROS refuses the file")
            return
        node = absolute("/".join(names))
        node_location = self.document.key_location(key_path[:1])
        problem = node_pattern_problem(node)
        if problem is not None:
            self.problem(node_location, node, f"invalid node name: {problem}")
            return
        if not isinstance(value, dict):
            self.problem(
                self.document.value_location(key_path),
                PARAMS_KEY,
                f"{PARAMS_KEY} must hold a mapping of parameter names to values",
            )
            return
        entries: list[ParamEntry] = []
        self.empty_mappings = []
        self.parameters(value, key_path, "", entries)
        for count, where, name in self.empty_mappings:
            if count < len(entries):
                # rcl closes one namespace too many at "{}": the keys after it land
                # outside ros__parameters, where rcl refuses values.
                self.problem(
                    where,
                    name,
                    "an empty mapping {} before other keys: ROS refuses the file "
                    "(leave the key out, or move it last)",
                )
        self.sections.append(Section(node, node_location, where, tuple(entries)))
        self.check_repeats(entries)

    def parameters(
        self, mapping: dict[str, Any], path: Path, prefix: str, entries: list[ParamEntry]
    ) -> None:
        meant = prefix  # the namespace a reader expects; rcl's may drift from it
        for key, value in mapping.items():
            key_path = (*path, key)
            name = f"{prefix}.{key}" if prefix else key
            if prefix != meant:
                expected = f"{meant}.{key}"
                self.problem(
                    self.document.key_location(key_path),
                    expected,
                    f"ROS reads this key as {name!r}: a dotted key holding a mapping above "
                    "it shifts the names after it (nest the keys instead of dotting them)",
                )
            if isinstance(value, dict) and value:
                self.parameters(value, key_path, name, entries)
                # rcl leaves a nested mapping by dropping the last dotted token of its
                # name: after "b.c: {...}" under "a", the next key is "a.b.<key>".
                if prefix:
                    prefix = name.rpartition(".")[0]
                continue
            key_location = self.document.key_location(key_path)
            value_location = self.document.value_location(key_path)
            if contains_mapping(value):
                self.rcl_list(name, key_path, value, prefix, entries)
            elif isinstance(value, (dict, list)) and not value:
                entries.append(ParamEntry(name, None, key_location, value_location, True))
                if isinstance(value, dict):
                    self.empty_mappings.append((len(entries), value_location, name))
            elif isinstance(value, list):
                items = self.list_items(value, key_path, name)
                if items is not None:
                    entries.append(ParamEntry(name, items, key_location, value_location))
            elif isinstance(value, NoValue):
                self.problem(
                    value_location,
                    name,
                    'no value: ROS refuses the file (write a value; an empty string is "")',
                )
            else:
                entries.append(ParamEntry(name, value, key_location, value_location))

    def rcl_list(
        self, name: str, path: Path, items: list[Any], prefix: str, entries: list[ParamEntry]
    ) -> None:
        """A list holding mappings: read as rcl reads it (see rcl_lists), not as YAML does."""
        records, problems = read_list(name, path, items, prefix)
        for where, message in problems:
            self.problem(self.document.value_location(where), name, message)
        for record in records:
            value_path = record.value_path if record.value_path is not None else record.key_path
            entries.append(
                ParamEntry(
                    record.name,
                    record.value,
                    self.document.key_location(record.key_path),
                    self.document.value_location(value_path),
                )
            )

    def list_items(self, items: list[Any], path: Path, name: str) -> list[Any] | None:
        kinds: list[str] = []
        for index, item in enumerate(items):
            where = self.document.value_location((*path, index))
            if isinstance(item, (list, dict)):
                self.problem(where, name, f"item {index}: ROS parameters are flat lists of values")
                return None
            if isinstance(item, NoValue):
                self.problem(where, name, f"item {index}: no value: ROS refuses the file")
                return None
            kinds.append(ros_type_name(item))
            if kinds[-1] != kinds[0]:
                self.problem(
                    where,
                    name,
                    f"item {index} is {_article(kinds[-1])} but item 0 is {_article(kinds[0])}: "
                    f"ROS refuses lists that mix types{_mix_hint(kinds[0], kinds[-1])}",
                )
                return None
        return list(items)

    def check_repeats(self, entries: list[ParamEntry]) -> None:
        seen: dict[str, ParamEntry] = {}
        for entry in entries:
            first = seen.setdefault(entry.name, entry)
            if first is not entry:
                where = first.key_location
                self.problem(
                    entry.key_location,
                    entry.name,
                    f"set twice in this section (first at line {where.line}, column "
                    f"{where.column}); ROS keeps the later value",
                )


def _looks_like_params_key(key: str) -> bool:
    return difflib.SequenceMatcher(None, key, PARAMS_KEY).ratio() >= 0.8


def _article(kind: str) -> str:
    return f"an {kind}" if kind[0] in "aeiou" else f"a {kind}"


def _mix_hint(first: str, other: str) -> str:
    if {first, other} == {"integer", "double"}:
        return " (write every item with a decimal point, 2.0 not 2)"
    return ""
