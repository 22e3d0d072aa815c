"""One declaration -> its schema leaf: the type rclpy would give it, its default (or
``optional``), and the descriptor's fields genparams states."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from genparams.rclpy_import.found import Found, descriptor_of
from genparams.rclpy_import.scope import (
    DescriptorValue,
    RangeValue,
    TypeMarker,
    run_time_problem,
)
from genparams.runtime.core.types import INT64_MAX, INT64_MIN


@dataclass
class DescriptorCopy:
    """Copies a declaration's descriptor into its leaf; ``lost`` says what could not be."""

    lost: list[str] = field(default_factory=list)

    def descriptor(self, found: Found, schema_type: str, leaf: dict[str, Any]) -> bool:
        """Copy the descriptor's fields into ``leaf``; False when part of it was lost (a
        warning says what)."""
        if found.descriptor.problem is not None:
            what = run_time_problem(found.descriptor.problem, "descriptor")
            self.lost.append(f"{what}: imported without it")
            return False
        descriptor = descriptor_of(found)
        if found.descriptor.given and descriptor is None and found.descriptor.value is not None:
            self.lost.append("the descriptor is not a ParameterDescriptor: imported without it")
            return False
        if descriptor is None:
            return True
        exact = True
        for field_name, failure in descriptor.failed.items():
            self.lost.append(f"descriptor field {field_name} ({failure.what}) could not be "
                      "read: imported without it")  # fmt: skip
            exact = False
        fields = descriptor.fields
        for key in ("description", "additional_constraints"):
            text = fields.get(key)
            if isinstance(text, str) and text:
                leaf[key] = text
            elif text not in (None, ""):
                self.lost.append(f"descriptor field {key} is not text: imported without it")
                exact = False
        read_only = fields.get("read_only")
        if read_only:
            leaf["read_only"] = True
        return self.ranges(schema_type, descriptor, leaf) and exact

    def ranges(
        self,
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
                self.lost.append(f"{key} must hold one range: imported without it")
                exact = False
            elif not isinstance(ranges[0], RangeValue) or ranges[0].integer != integer:
                self.lost.append(f"{key} holds another kind of range: imported without it")
                exact = False
            elif schema_type == "any":
                self.lost.append(f"{key} on a dynamically typed parameter: imported "
                          "without it")  # fmt: skip
                exact = False
            elif not fits:
                self.lost.append(f"{key} on a {schema_type} parameter (rclpy does not "
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


def schema_type(value: Any) -> tuple[str | None, str]:
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
    if isinstance(value, TypeMarker):  # pragma: no cover (_typed_leaf took it)
        return None, "a type without a value"
    return None, f"{value!r} is not a parameter value"


_CONDITION_TYPES = ("bool", "int", "double", "string")


def typed_leaf(found: Found) -> tuple[dict[str, Any] | None, str]:
    """The leaf's type, and its default or ``optional``, as rclpy would declare it."""
    if found.read is not None:  # a parameter the node reads: it must be given
        return {"type": found.read or "any"}, ""
    descriptor = descriptor_of(found)
    value = found.value.value
    if found.value.problem is not None and found.item_value is not None:
        value = found.item_value.value  # for a sample item: typed, never kept
    dynamic = descriptor is not None and bool(descriptor.fields.get("dynamic_typing"))
    if isinstance(value, TypeMarker):
        if value.schema_type == "not_set":
            return None, "Parameter.Type.NOT_SET: rclpy refuses it as a static type"
        if dynamic:
            return None, "a type with dynamic_typing=True: rclpy refuses it"
        return {"type": value.schema_type, "optional": True}, ""
    by_name_only = found.descriptor.value is None and found.descriptor.problem is None
    if dynamic or (value is None and by_name_only):
        if value is None:  # declared by name only, or with dynamic_typing and no value
            return {"type": "any", "optional": True}, ""
        kind, problem = schema_type(value)
        if kind is None:
            return None, problem
        if kind == "byte_array":
            return None, "an empty list as a dynamically typed value: a schema cannot default to it"
        return {"type": "any", "default": default_of(value)}, ""
    kind, problem = schema_type(value)
    if kind is None:
        return None, problem
    return {"type": kind, "default": default_of(value)}, ""


def condition_value(kind: str, value: Any) -> Any:
    """``value`` as a value of the condition's parameter type, or None."""
    if kind == "bool":
        return value if isinstance(value, bool) else None
    if kind == "int":
        return value if isinstance(value, int) and not isinstance(value, bool) else None
    if kind == "double":
        ok = isinstance(value, (int, float)) and not isinstance(value, bool)
        return float(value) if ok else None
    return value if isinstance(value, str) else None


def default_of(value: Any) -> Any:
    if isinstance(value, (list, tuple)):
        return [default_of(v) for v in value]
    if isinstance(value, str):
        return str(value)  # a SharePath is written as its text
    if isinstance(value, float) and math.isnan(value):
        return float("nan")
    return value
