"""A published schema message read back as the specs its node compiled.

``schema_topic.describe_class`` writes each class of a node: its parameters,
mapped groups and rules, every validator in its schema spelling. This module
is its inverse, for the tools that check a live node against what it published
(``genparams audit``, the tuning page): the specs it returns compile, with the
runtime's own compiler, to the checks the node runs.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from genparams.runtime.naming import ENTRY_KEY, strip_prefix
from genparams.runtime.spec import ParamSpec, RuleSpec, SchemaSpec
from genparams.runtime.tree import Group
from genparams.runtime.types import TYPES


def frozen(value: Any) -> Any:
    """JSON lists as the tuples a ParamSpec holds (dicts, such as length's, stay)."""
    if isinstance(value, list):
        return tuple(frozen(item) for item in value)
    return value


def param_from_json(described: Mapping[str, Any], name: str) -> ParamSpec:
    """One described parameter (``describe_parameter``) as its spec, under ``name``."""
    kind = TYPES[described["type"]]
    optional = described.get("optional", False)
    no_default = described["required"] or optional
    default = None if no_default else kind.coerce_default(described["default"])
    span = described.get("range")
    return ParamSpec(
        name=name,
        type=described["type"],
        default=default,
        required=described["required"],
        optional=optional,
        read_only=described["read_only"],
        range=None if span is None else (span["min"], span["max"], span["step"]),
        choices=None if described["choices"] is None else frozen(described["choices"]),
        validators=tuple((rule, frozen(arg)) for rule, arg in described["validators"]),
    )


def class_spec(described: Mapping[str, Any]) -> SchemaSpec:
    """One described class as the spec it was declared from, names relative to its prefix.

    Raises KeyError, TypeError or ValueError when ``described`` is not a class description.
    """
    prefix = described["prefix"]

    def relative(name: str) -> str:
        if name == prefix:
            return ""
        found = strip_prefix(prefix, name) if prefix else name
        if found is None:
            raise ValueError(f"{name!r} is not under the class prefix {prefix!r}")
        return found

    params = [param_from_json(p, relative(p["name"])) for p in described["parameters"]]
    groups: dict[str, type[Group]] = {}
    for param in params:  # every namespace that holds a fixed parameter
        parts = param.name.split(".")
        groups.update((".".join(parts[:i]), Group) for i in range(1, len(parts)))
    maps = {}
    for group in described["maps"]:
        path = relative(group["path"])
        maps[path] = relative(group["for_each"])
        head = f"{path}.{ENTRY_KEY}" if path else ENTRY_KEY
        groups[head] = Group
        params.extend(param_from_json(f, f"{head}.{f['name']}") for f in group["fields"])
    rules = tuple(
        RuleSpec(r["name"], r["check"], r.get("description", "")) for r in described["rules"]
    )
    return SchemaSpec(str(described["class"]), tuple(params), groups, maps, rules)
