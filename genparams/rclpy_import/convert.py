"""A node's declarations -> a genparams schema, as plain data, with what could not be kept.

Each declaration is imported *exactly* (every descriptor field and the value
kept), *approximately* (imported, but part of it could not be read: a warning
says which) or *left out* (a warning says why). Nothing is dropped without a
warning at its FILE:LINE:COL.
"""

from __future__ import annotations

import ast
import math
import re
from dataclasses import dataclass, field
from typing import Any

from genparams.rclpy_import.features import awaiting_feature
from genparams.rclpy_import.scan import Found, Unit, descriptor_of
from genparams.rclpy_import.values import DescriptorValue, RangeValue, TypeMarker
from genparams.runtime.naming import NODE_PARAMETERS, SCHEMA_NAME, is_ros_name
from genparams.runtime.types import INT64_MAX, INT64_MIN
from genparams.schema.errors import Location, SchemaProblem

EXACT = "exact"
APPROXIMATE = "approximate"
LEFT_OUT = "left out"


@dataclass
class Imported:
    name: str
    data: dict[str, Any]
    warnings: list[SchemaProblem] = field(default_factory=list)
    notes: list[SchemaProblem] = field(default_factory=list)
    outcome: list[tuple[Found, str]] = field(default_factory=list)  # each declaration's fate

    def count(self, outcome: str) -> int:
        return sum(1 for _, o in self.outcome if o == outcome)

    @property
    def imported_names(self) -> set[str]:
        return {f.name.value for f, o in self.outcome if o != LEFT_OUT}


def schema_name(unit_name: str, file_stem: str) -> str:
    """``KeyTeleopNode`` -> ``key_teleop``; a file's own functions take the file's name."""
    base = unit_name or file_stem
    if unit_name.endswith("Node") and len(unit_name) > len("Node"):
        base = unit_name[: -len("Node")]
    name = re.sub(r"(?<=[a-z0-9])([A-Z])|(?<=[A-Z])([A-Z])(?=[a-z])", r"_\1\2", base).lower()
    name = re.sub(r"[^a-z0-9_]+", "_", name).strip("_")
    return name if SCHEMA_NAME.fullmatch(name) else f"node_{name}".rstrip("_")


def convert(unit: Unit, file: str, lines: list[str], name: str) -> Imported:
    return _Converter(unit, file, lines, name).run()


class _Converter:
    def __init__(self, unit: Unit, file: str, lines: list[str], name: str) -> None:
        self.unit = unit
        self.file = file
        self.lines = lines
        self.imported = Imported(name, {})
        self.tree: dict[str, Any] = {}
        self.first: dict[str, Found] = {}

    def run(self) -> Imported:
        for option in self.unit.options:
            message = awaiting_feature(option)
            if message is not None:
                self.warn(option.at, "", message)
        for change in self.unit.afterwards:
            self.warn(change.at, "", f"{change.construct}: the schema keeps the declared one")
        for found in self.unit.found:
            self.imported.outcome.append((found, self.declaration(found)))
        self.keep_groups_whole()
        data: dict[str, Any] = {"genparams": 1, "name": self.imported.name}
        if self.unit.docstring:
            data["description"] = " ".join(self.unit.docstring.strip().split("\n\n")[0].split())
        data["parameters"] = self.tree
        self.imported.data = data
        return self.imported

    def keep_groups_whole(self) -> None:
        """One statement declaring several parameters (a loop over literal items, a
        declare_parameters list whose result is used) stays in the node whole when any
        of them is left out: the others are left out with it, or the node would declare
        them twice."""
        groups: dict[int, list[int]] = {}
        for index, (found, _) in enumerate(self.imported.outcome):
            if found.literal_loop is not None:
                groups.setdefault(id(found.literal_loop), []).append(index)
            elif found.in_list and not (
                isinstance(found.statement, ast.Expr) and found.statement.value is found.call
            ):
                groups.setdefault(id(found.call), []).append(index)
        for members in groups.values():
            outcomes = [self.imported.outcome[i] for i in members]
            if all(o != LEFT_OUT for _, o in outcomes) or all(o == LEFT_OUT for _, o in outcomes):
                continue
            for index in members:
                found, outcome = self.imported.outcome[index]
                if outcome == LEFT_OUT:
                    continue
                name = found.name.value
                self.warn(found.at, name, "declared by the same statement as a parameter left "
                          "out: left out with it")  # fmt: skip
                self.unplace(name)
                del self.first[name]
                self.imported.outcome[index] = (found, LEFT_OUT)

    def location(self, node: ast.AST) -> Location:
        line = getattr(node, "lineno", 1)
        offset = getattr(node, "col_offset", 0)
        text = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        column = len(text.encode("utf-8")[:offset].decode("utf-8", errors="replace")) + 1
        return Location(self.file, line, column)

    def warn(self, node: ast.AST, key: str, message: str) -> None:
        problem = SchemaProblem(self.location(node), key, f"warning: {message}")
        if problem not in self.imported.warnings:
            self.imported.warnings.append(problem)

    def note(self, node: ast.AST, key: str, message: str) -> None:
        problem = SchemaProblem(self.location(node), key, f"note: {message}")
        if problem not in self.imported.notes:
            self.imported.notes.append(problem)

    def declaration(self, found: Found) -> str:
        at = found.at
        if found.name.problem is not None:
            feature = awaiting_feature(found) if found.runtime_loop is not None else None
            reason = feature or f"a name computed at run time ({found.name.problem.what})"
            self.warn(at, "", f"{reason}: parameter left out")
            return LEFT_OUT
        name = found.name.value
        if not isinstance(name, str):
            self.warn(at, "", f"the name {name!r} is not a string: parameter left out")
            return LEFT_OUT
        if found.nested is not None:
            self.warn(at, name, f"declared inside {found.nested}: parameter left out")
            return LEFT_OUT
        feature = awaiting_feature(found)
        if feature is not None:
            self.warn(at, name, f"{feature}: parameter left out")
            return LEFT_OUT
        if found.value.problem is not None:
            self.warn(at, name, f"value computed at run time ({found.value.problem.what}): "
                      "parameter left out")  # fmt: skip
            return LEFT_OUT
        problem = self.name_problem(name)
        if problem is not None:
            self.warn(at, name, f"{problem}: parameter left out")
            return LEFT_OUT
        schema_type, problem = _schema_type(found.value.value)
        if schema_type is None:
            self.warn(at, name, f"{problem}: parameter left out")
            return LEFT_OUT
        leaf: dict[str, Any] = {"type": schema_type, "default": _default(found.value.value)}
        if schema_type == "byte_array":
            self.note(
                at, name, "an empty list: rclpy declares a byte_array, and so does the schema"
            )
        exact = self.descriptor(found, name, schema_type, leaf)
        if found.ignore_override.problem is not None or found.ignore_override.value:
            self.warn(at, name, "ignore_override: genparams always applies overrides: imported "
                      "without it")  # fmt: skip
            exact = False
        self.place(name, leaf)
        self.first[name] = found
        return EXACT if exact else APPROXIMATE

    def name_problem(self, name: str) -> str | None:
        if name in self.first:
            where = self.location(self.first[name].at)
            return f"declared again (first at {where.line}:{where.column}; rclpy refuses it)"
        if not is_ros_name(name):
            return "not a name genparams declares (dotted tokens of letters, digits and _)"
        if name in NODE_PARAMETERS:
            return "every node declares it already"
        parts = name.split(".")
        if len(parts) > 1 and parts[-1] == "type":
            return "a namespace cannot hold a parameter named 'type'"
        for index in range(1, len(parts)):
            if ".".join(parts[:index]) in self.first:
                return f"{'.'.join(parts[:index])!r} is a parameter, not a namespace"
        if any(other.startswith(name + ".") for other in self.first):
            return f"{name!r} is already a namespace"
        return None

    def unplace(self, name: str) -> None:
        """Take a parameter out of the tree, and the namespaces it leaves empty."""
        parts = name.split(".")
        chain = [self.tree]
        for part in parts[:-1]:
            chain.append(chain[-1][part])
        del chain[-1][parts[-1]]
        for depth in range(len(parts) - 1, 0, -1):
            if not chain[depth]:
                del chain[depth - 1][parts[depth - 1]]

    def place(self, name: str, leaf: dict[str, Any]) -> None:
        *spaces, last = name.split(".")
        node = self.tree
        for part in spaces:
            node = node.setdefault(part, {})
        node[last] = leaf

    def descriptor(self, found: Found, name: str, schema_type: str, leaf: dict[str, Any]) -> bool:
        """Copy the descriptor's fields into ``leaf``; False when part of it was lost."""
        at = found.at
        if found.descriptor.problem is not None:
            what = found.descriptor.problem.what
            self.warn(at, name, f"descriptor computed at run time ({what}): imported without it")
            return False
        descriptor = descriptor_of(found)
        if found.descriptor.given and descriptor is None and found.descriptor.value is not None:
            self.warn(at, name, "the descriptor is not a ParameterDescriptor: imported without it")
            return False
        if descriptor is None:
            return True
        exact = True
        for field_name, failure in descriptor.failed.items():
            self.warn(at, name, f"descriptor field {field_name} ({failure.what}) could not be "
                      "read: imported without it")  # fmt: skip
            exact = False
        fields = descriptor.fields
        for key in ("description", "additional_constraints"):
            text = fields.get(key)
            if isinstance(text, str) and text:
                leaf[key] = text
            elif text not in (None, ""):
                self.warn(at, name, f"descriptor field {key} is not text: imported without it")
                exact = False
        read_only = fields.get("read_only")
        if read_only:
            leaf["read_only"] = True
        return self.ranges(found, name, schema_type, descriptor, leaf) and exact

    def ranges(
        self,
        found: Found,
        name: str,
        schema_type: str,
        descriptor: DescriptorValue,
        leaf: dict[str, Any],
    ) -> bool:
        exact = True
        for key, integer in (("integer_range", True), ("floating_point_range", False)):
            ranges = descriptor.fields.get(key)
            if not ranges:
                continue
            fits = schema_type == ("int" if integer else "double")
            if not isinstance(ranges, list) or len(ranges) != 1:
                self.warn(found.at, name, f"{key} must hold one range: imported without it")
                exact = False
            elif not isinstance(ranges[0], RangeValue) or ranges[0].integer != integer:
                self.warn(found.at, name, f"{key} holds another kind of range: imported without it")
                exact = False
            elif not fits:
                self.warn(found.at, name, f"{key} on a {schema_type} parameter (rclpy does not "
                          "check it): imported without it")  # fmt: skip
                exact = False
            else:
                limits = ranges[0]
                convert = int if integer else float
                bounds: dict[str, Any] = {
                    "min": convert(limits.from_value),
                    "max": convert(limits.to_value),
                }
                if limits.step:
                    bounds["step"] = convert(limits.step)
                leaf["range"] = bounds
        return exact


def _schema_type(value: Any) -> tuple[str | None, str]:
    """The type rclpy gives a declaration of this value (Parameter.Type.from_parameter_value)."""
    if value is None:
        return None, "a None value: rclpy refuses to declare it without dynamic typing"
    if isinstance(value, bool):
        return "bool", ""
    if isinstance(value, int):
        if not INT64_MIN <= value <= INT64_MAX:
            return None, f"{value} does not fit an int64"
        return "int", ""
    if isinstance(value, float):
        return "double", ""
    if isinstance(value, str):
        return "string", ""
    if isinstance(value, (list, tuple)):
        if all(isinstance(v, bytes) for v in value):
            return ("byte_array", "") if not value else (None, "a list of bytes")
        for kind, schema_type in ((bool, "bool"), (int, "int"), (float, "double"), (str, "string")):
            if all(isinstance(v, kind) for v in value):
                return f"{schema_type}_array", ""
        return None, f"the list {value!r} mixes types: rclpy refuses it"
    if isinstance(value, TypeMarker):  # pragma: no cover (awaiting_feature took it)
        return None, "a type without a value"
    return None, f"{value!r} is not a parameter value"


def _default(value: Any) -> Any:
    if isinstance(value, tuple):
        return list(value)
    if isinstance(value, float) and math.isnan(value):
        return float("nan")
    return value
