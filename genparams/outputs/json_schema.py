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

from genparams.outputs.params_file import parameter_comment
from genparams.outputs.schema_paths import (
    ENTRY_KEY_PATTERN,
    descendants,
    dotted_pattern,
    fixed_names,
    names_beside_entries,
    open_descendants,
)
from genparams.outputs.yaml_text import value_text
from genparams.paramsfile.ros_yaml import PARAMS_KEY
from genparams.runtime.core.naming import ENTRY_KEY, NODE_TOKEN
from genparams.runtime.core.spec import EntryKeys
from genparams.runtime.core.validators import (
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
from genparams.schema.model import Group, Parameter, Schema

DRAFT = "https://json-schema.org/draft/2020-12/schema"
_TOKEN = f"(\\*\\*|\\*|{NODE_TOKEN.pattern})"  # a node name token or a wildcard
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
    old_names = _OldNames(schema)
    for group in _all_groups(schema.root):
        if not group.per_item:  # its entries are values of its one parameter
            definitions[_group_name(group)] = _group_schema(group, old_names, required=not partial)
        if group.mapped_over and not group.in_place:
            definitions[_map_name(group)] = _map_schema(group)
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
    if group.in_place:  # shares its ros_name with the namespace it sits in
        return f"group.{group.spec_path}"
    return f"group.{group.ros_name}" if group.ros_name else "group"


def _def_ref(name: str) -> str:
    """A JSON Pointer to ``$defs[name]``: '~' and '/' (a name may hold '/') escaped."""
    return "#/$defs/" + name.replace("~", "~0").replace("/", "~1")


def _group_ref(group: Group) -> str:
    return _def_ref(_group_name(group))


def _parameter_name(parameter: Parameter) -> str:
    return f"param.{parameter.ros_name}"


def _article(words: str) -> str:
    return f"an {words}" if words[:1] in "aeiou" else f"a {words}"


def _map_name(group: Group) -> str:
    return f"map.{group.ros_name}"


def _map_schema(group: Group) -> dict[str, Any]:
    """A mapped group: entries keyed by items of its for_each parameter, nested or dotted."""
    if group.per_item:  # each entry is a value of the one parameter, named by its item
        return {
            "type": "object",
            "description": f"One parameter per item of {group.mapped_over}, named by the item.",
            "patternProperties": {ENTRY_KEY_PATTERN: {"$ref": _parameter_ref(group.parameters[0])}},
            "additionalProperties": False,
        }
    patterns = {ENTRY_KEY_PATTERN: {"$ref": _group_ref(group)}}
    for path, item in descendants(group):
        patterns[dotted_pattern((ENTRY_KEY, *path))] = {"$ref": _ref(item, path)}
    return {
        "type": "object",
        "description": f"One entry per {group.keyed_by}.",
        "patternProperties": patterns,
        "additionalProperties": False,
    }


def _group_schema(group: Group, old_names: _OldNames, *, required: bool) -> dict[str, Any]:
    properties: dict[str, Any] = {}
    patterns: dict[str, Any] = {}
    if not group.ros_name:
        properties.update(BUILTIN_PARAMETERS)
        patterns["^qos_overrides\\."] = {}
    required_here: list[str] = []
    required_below: list[dict[str, Any]] = []
    beside = fixed_names(group)
    if not group.ros_name and not group.in_place:
        beside.update(BUILTIN_PARAMETERS, ["qos_overrides"])
    for path, item in descendants(group):
        key = ".".join(path)
        ref = {"$ref": _ref(item, path)}
        if ENTRY_KEY in path:
            names = beside if path[0] == ENTRY_KEY else names_beside_entries(group, path)
            patterns[dotted_pattern(path, names)] = ref
            continue
        properties[key] = ref
        if isinstance(item, Group) or not (required and item.required):
            continue
        if len(path) == 1:
            required_here.append(key)
        else:
            # Written whole ("a.b.c") or under one of its namespaces ("a", "a.b"), whose
            # own schema then requires the rest.
            prefixes = [".".join(path[:n]) for n in range(1, len(path) + 1)]
            required_below.append({"anyOf": [{"required": [prefix]} for prefix in prefixes]})
    for path, namespace in open_descendants(group):
        # Other code declares what lies here: any value, nested or dotted.
        if ENTRY_KEY not in path:
            properties[".".join(path)] = {"description": namespace.description or "Open namespace."}
        patterns[dotted_pattern(path)] = {"description": namespace.description}
        patterns[dotted_pattern(path)[:-1] + "\\."] = {}
    properties.update(old_names.properties(group))
    result: dict[str, Any] = {
        "type": "object",
        "description": f"Parameters under {group.ros_name}." if group.ros_name else "Parameters.",
        "properties": properties,
        "additionalProperties": False,
    }
    if group.mapped_over:
        result["description"] = f"One entry of {group.ros_name}, for {_article(group.keyed_by)}."
    if patterns:
        result["patternProperties"] = patterns
    if required_here:
        result["required"] = required_here
    if required_below:
        result["allOf"] = required_below
    return result


def _ref(item: Group | Parameter, path: tuple[str, ...]) -> str:
    """What a key at ``path`` holds: a parameter, a namespace, a map, or one map entry."""
    if isinstance(item, Parameter):
        return _parameter_ref(item)
    if item.mapped_over and path[-1] != ENTRY_KEY:
        return _def_ref(_map_name(item))
    return _group_ref(item)


def _parameter_ref(parameter: Parameter) -> str:
    return _def_ref(_parameter_name(parameter))


class _OldNames:
    """Old names (aliases) a params file may still use, placed in the namespaces they name.

    An old name may lie in a namespace the schema no longer has (``limits.speed``):
    that namespace is described here, holding only old names.
    """

    def __init__(self, schema: Schema) -> None:
        self.names = [
            (tuple(alias.split(".")), parameter)
            for parameter in schema.parameters
            for alias in parameter.aliases
        ]
        self.groups = {g.path for g in _all_groups(schema.root) if not g.mapped_over}

    def properties(self, group: Group) -> dict[str, Any]:
        if group.path not in self.groups:
            return {}  # inside a mapped group: no old names there
        depth = len(group.path)
        below = [
            (n[depth:], p) for n, p in self.names if n[:depth] == group.path and len(n) > depth
        ]
        return self._namespace(below, group.path)

    def _namespace(
        self, names: list[tuple[tuple[str, ...], Parameter]], at: tuple[str, ...]
    ) -> dict[str, Any]:
        """Properties for ``names`` (relative to ``at``), nested and dotted, as ROS reads both."""
        properties: dict[str, Any] = {}
        for path, parameter in names:
            properties[".".join(path)] = {
                "$ref": _parameter_ref(parameter),
                "deprecated": True,
                "description": f"Old name of {parameter.ros_name}: write {parameter.ros_name}.",
            }
            for n in range(1, len(path)):
                prefix = path[:n]
                if (*at, *prefix) in self.groups:
                    continue  # an existing namespace lists the old names inside it
                tails = [(p[n:], q) for p, q in names if p[:n] == prefix and len(p) > n]
                properties[".".join(prefix)] = {
                    "type": "object",
                    "description": "Old names.",
                    "properties": self._namespace(tails, (*at, *prefix)),
                    "additionalProperties": False,
                }
        return properties


def parameter_schema(parameter: Parameter) -> dict[str, Any]:
    """The value schema of one parameter, with hover text and its default."""
    param_type = parameter.type
    kind = param_type.scalar_kind
    result: dict[str, Any]
    if param_type.is_dynamic:  # any of the nine types: a scalar, or a list of scalars
        scalars = [_JSON_TYPES[k] for k in ("bool", "int", "double", "string")]
        result = {"type": [*scalars, "array"], "items": {"type": scalars}}
    elif param_type.is_array:
        items: dict[str, Any] = (
            {"type": "integer", "minimum": 0, "maximum": 255}
            if kind == "byte"
            else {"type": _JSON_TYPES[kind]}
        )
        result = {"type": "array", "items": items}
    else:
        result = {"type": _JSON_TYPES[kind]}
    for check in parameter.compiled.checks:
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
    facts = [parameter.stated("type")]
    if parameter.type.scalar_kind == "double":
        facts.append("Write a decimal point (30.0, not 30): ROS does not convert.")
    if parameter.required:
        facts.append("Required: no default; the node does not start without it.")
    elif parameter.optional:
        facts.append("Optional: not set by default; the node tests whether it is.")
    else:
        facts.append(f"Default: {value_text(parameter.default, parameter.type)}.")
    lines.append(" ".join(facts))
    return "\n".join(lines)


def _json_default(parameter: Parameter) -> Any:
    if parameter.required or parameter.optional:
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
    OneOf: lambda c, s: _enum(c.choices),
    SubsetOf: lambda c, s: [("items", dict(_enum(c.choices)))],
    NotEmpty: lambda c, s: [("minLength" if s else "minItems", 1)],
    Unique: lambda c, s: [("uniqueItems", True)],
    Length: _length,
    Pattern: lambda c, s: [("pattern", c.regex)] if s else [("items", {"pattern": c.regex})],
    EntryKeys: lambda c, s: [("items", {"pattern": ENTRY_KEY_PATTERN}), ("uniqueItems", True)],
}


def _non_finite(value: Any) -> bool:
    return isinstance(value, float) and not math.isfinite(value)


def _enum(choices: Any) -> Keywords:
    """JSON has no NaN or infinity: choices holding one are left unchecked, never narrowed."""
    if any(_non_finite(choice) for choice in choices):
        return []
    return [("enum", list(choices))]


def _add(target: dict[str, Any], keyword: str, value: Any) -> None:
    """Add one keyword, merging with what is there; what cannot merge goes to allOf."""
    if (keyword in _LOWER or keyword in _UPPER) and _non_finite(value):
        return  # JSON has no infinity: an infinite bound is no bound
    if keyword == "items":
        items = target.setdefault("items", {})
        for key, item in value.items():
            _add(items, key, item)
    elif keyword not in target:
        target[keyword] = value
    elif keyword in _LOWER:
        target[keyword] = max(target[keyword], value)
    elif keyword in _UPPER:
        target[keyword] = min(target[keyword], value)
    elif keyword == "enum":
        target[keyword] = [v for v in target[keyword] if v in value]
    elif target[keyword] != value:
        target.setdefault("allOf", []).append({keyword: value})
