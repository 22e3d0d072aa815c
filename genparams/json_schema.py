"""A JSON Schema (2020-12) for the params files of one schema's node, for editors and CI.

Node sections (``/**``, ``/ns/name``, wildcards) hold ``ros__parameters``;
parameters may be nested or dotted (``camera: {fps: ..}`` or ``camera.fps:``);
unknown keys are errors, so a typo is flagged where ROS would ignore it.
Constraints come from the same validator objects the runtime runs, each mapped
to JSON Schema keywords where JSON Schema can say it (a custom validator
cannot be; a double's need for a decimal point cannot either, since JSON
Schema counts 30.0 as an integer: the description says it instead).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from typing import Any

from genparams.model import Group, Parameter, Schema
from genparams.params_file import parameter_comment
from genparams.ros_yaml import PARAMS_KEY
from genparams.specs import compiled_param
from genparams.validators import (
    Bounds,
    Compare,
    Length,
    NotEmpty,
    OneOf,
    Pattern,
    RosRange,
    SubsetOf,
    Unique,
    Validator,
)
from genparams.yaml_text import value_text

DRAFT = "https://json-schema.org/draft/2020-12/schema"
_TOKEN = "(\\*\\*|\\*|[A-Za-z_][A-Za-z0-9_]*)"
NODE_KEY_PATTERN = f"^/?{_TOKEN}(/{_TOKEN})*$"
# Parameters every rclpy node declares itself; a params file may set them for any node.
BUILTIN_PARAMETERS: dict[str, dict[str, Any]] = {
    "use_sim_time": {"type": "boolean", "description": "Use /clock for time (every ROS node)."},
    "start_type_description_service": {
        "type": "boolean",
        "description": "Start the type description service (every ROS node).",
    },
    "qos_overrides": {"type": "object", "description": "QoS overrides of publishers."},
}
_JSON_TYPES = {"bool": "boolean", "int": "integer", "double": "number", "string": "string"}


def params_file_schema(schema: Schema, *, partial: bool = False) -> dict[str, Any]:
    """The JSON Schema; with ``partial``, required parameters may be missing from a file."""
    definitions: dict[str, Any] = {
        "section": {
            "type": "object",
            "description": f"One node's section: its parameters go under {PARAMS_KEY}.",
            "properties": {PARAMS_KEY: {"$ref": _group_ref(schema.root)}},
            "required": [PARAMS_KEY],
            "additionalProperties": False,
        }
    }
    for group in _all_groups(schema.root):
        definitions[_group_name(group)] = _group_schema(group, required=not partial)
    for parameter in schema.parameters:
        definitions[_parameter_name(parameter)] = parameter_schema(parameter)
    return {
        "$schema": DRAFT,
        "title": f"ROS 2 params file for {schema.name}",
        "description": schema.description or f"Parameters of {schema.name}.",
        "type": "object",
        "propertyNames": {"pattern": NODE_KEY_PATTERN},
        "additionalProperties": {"$ref": "#/$defs/section"},
        "$defs": definitions,
    }


def _all_groups(group: Group) -> Iterator[Group]:
    yield group
    for child in group.groups:
        yield from _all_groups(child)


def _group_name(group: Group) -> str:
    return f"group.{group.ros_name}" if group.ros_name else "group"


def _group_ref(group: Group) -> str:
    return f"#/$defs/{_group_name(group)}"


def _parameter_name(parameter: Parameter) -> str:
    return f"param.{parameter.ros_name}"


def _descendants(group: Group) -> Iterator[tuple[tuple[str, ...], Group | Parameter]]:
    """Every parameter and group below ``group``, with its path relative to ``group``."""
    for parameter in group.parameters:
        yield (parameter.path[-1],), parameter
    for child in group.groups:
        yield (child.path[-1],), child
        for path, item in _descendants(child):
            yield (child.path[-1], *path), item


def _group_schema(group: Group, *, required: bool) -> dict[str, Any]:
    properties: dict[str, Any] = {}
    if not group.ros_name:
        properties.update(BUILTIN_PARAMETERS)
    required_here: list[str] = []
    required_below: list[dict[str, Any]] = []
    for path, item in _descendants(group):
        key = ".".join(path)
        if isinstance(item, Group):
            properties[key] = {"$ref": _group_ref(item)}
            continue
        properties[key] = {"$ref": f"#/$defs/{_parameter_name(item)}"}
        if not (required and item.required):
            continue
        if len(path) == 1:
            required_here.append(key)
        else:
            # Written whole ("a.b.c") or under one of its namespaces ("a", "a.b"), whose
            # own schema then requires the rest.
            prefixes = [".".join(path[:n]) for n in range(1, len(path) + 1)]
            required_below.append({"anyOf": [{"required": [prefix]} for prefix in prefixes]})
    result: dict[str, Any] = {
        "type": "object",
        "description": f"Parameters under {group.ros_name}." if group.ros_name else "Parameters.",
        "properties": properties,
        "additionalProperties": False,
    }
    if not group.ros_name:
        result["patternProperties"] = {"^qos_overrides\\.": {}}
    if required_here:
        result["required"] = required_here
    if required_below:
        result["allOf"] = required_below
    return result


def parameter_schema(parameter: Parameter) -> dict[str, Any]:
    """The value schema of one parameter, with hover text and its default."""
    param_type = parameter.type
    kind = param_type.scalar_kind
    if param_type.is_array:
        items: dict[str, Any] = (
            {"type": "integer", "minimum": 0, "maximum": 255}
            if kind == "byte"
            else {"type": _JSON_TYPES[kind]}
        )
        result: dict[str, Any] = {"type": "array", "items": items}
    else:
        result = {"type": _JSON_TYPES[kind]}
    for check in compiled_param(parameter).checks:
        for keyword, value in _keywords(check, is_string=param_type.name == "string"):
            _add(result, keyword, value)
    result["description"] = hover_text(parameter)
    default = _json_default(parameter)
    if default is not None:
        result["default"] = default
    if parameter.deprecated:
        result["deprecated"] = True
    if parameter.read_only:
        result["readOnly"] = True
    return result


def hover_text(parameter: Parameter) -> str:
    lines = list(parameter_comment(parameter))
    facts = [f"Type: {parameter.type.name}."]
    if parameter.type.scalar_kind == "double":
        facts.append("Write a decimal point (30.0, not 30): ROS does not convert.")
    if parameter.required:
        facts.append("Required: no default; the node does not start without it.")
    else:
        facts.append(f"Default: {value_text(parameter.default, parameter.type)}.")
    lines.append(" ".join(facts))
    return "\n".join(lines)


def _json_default(parameter: Parameter) -> Any:
    if parameter.required:
        return None
    value = parameter.default
    if isinstance(value, bytes):
        return list(value)
    if isinstance(value, tuple):
        if any(isinstance(v, float) and not math.isfinite(v) for v in value):
            return None
        return list(value)
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


# ---- validators to keywords ---------------------------------------------------------------

Keywords = list[tuple[str, Any]]
_LOWER = {"minimum", "exclusiveMinimum", "minLength", "minItems"}  # keep the larger
_UPPER = {"maximum", "exclusiveMaximum", "maxLength", "maxItems"}  # keep the smaller


def _keywords(check: Validator, *, is_string: bool) -> Keywords:
    builder = _KEYWORD_BUILDERS.get(type(check))
    return builder(check, is_string) if builder is not None else []


def _each(check: Any, keywords: Keywords) -> Keywords:
    return [("items", dict(keywords))] if check.each else keywords


def _range(check: Any, _string: bool) -> Keywords:
    keywords: Keywords = [("minimum", check.low), ("maximum", check.high)]
    if check.integer and check.step and check.low % check.step == 0:
        keywords.append(("multipleOf", check.step))
    return _each(check, keywords)


def _compare(check: Any, _string: bool) -> Keywords:
    keyword = {
        "gt": "exclusiveMinimum",
        "ge": "minimum",
        "lt": "exclusiveMaximum",
        "le": "maximum",
    }[check.rule]
    return [(keyword, check.limit)]


def _length(check: Any, is_string: bool) -> Keywords:
    low, high = ("minLength", "maxLength") if is_string else ("minItems", "maxItems")
    keywords: Keywords = []
    if check.min is not None:
        keywords.append((low, check.min))
    if check.max is not None:
        keywords.append((high, check.max))
    return keywords


_KEYWORD_BUILDERS: dict[type, Callable[[Any, bool], Keywords]] = {
    RosRange: _range,
    Bounds: lambda c, s: _each(c, [("minimum", c.low), ("maximum", c.high)]),
    Compare: _compare,
    OneOf: lambda c, s: [("enum", list(c.choices))],
    SubsetOf: lambda c, s: [("items", {"enum": list(c.choices)})],
    NotEmpty: lambda c, s: [("minLength" if s else "minItems", 1)],
    Unique: lambda c, s: [("uniqueItems", True)],
    Length: _length,
    Pattern: lambda c, s: [("pattern", c.regex)] if s else [("items", {"pattern": c.regex})],
}


def _add(target: dict[str, Any], keyword: str, value: Any) -> None:
    """Add one keyword, merging with what is there; what cannot merge goes to allOf."""
    if keyword not in target:
        target[keyword] = value
    elif keyword in _LOWER:
        target[keyword] = max(target[keyword], value)
    elif keyword in _UPPER:
        target[keyword] = min(target[keyword], value)
    elif keyword == "items":
        for key, item in value.items():
            _add(target["items"], key, item)
    elif keyword == "enum":
        target[keyword] = [v for v in target[keyword] if v in value]
    elif target[keyword] != value:
        target.setdefault("allOf", []).append({keyword: value})
