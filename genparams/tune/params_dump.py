"""A node's current values as a params file: the parameters its schema owns, nested by dots."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import yaml

from genparams.runtime.core.entries import map_places


def owned_names(schema: Mapping[str, Any], values: Mapping[str, Any]) -> set[str]:
    """The full names a schema message covers: its parameters, and each mapped entry where
    the runtime's own place mapping puts it on the node (open groups and groups in entries
    included)."""
    names: set[str] = set()
    for described in schema.get("classes", []):
        names.update(p["name"] for p in described["parameters"])
        for place in map_places(described["maps"], values):
            names.update(name for name, _ in place.entries())
    return names


def nested(flat: Iterable[tuple[str, Any]]) -> dict[str, Any]:
    """Values nested by the dots of their names. A name below another's value (``a.b`` beside
    ``a``) keeps the rest of its name as one dotted key, which ROS reads back the same."""
    tree: dict[str, Any] = {}
    for name, value in sorted(flat):
        *heads, leaf = name.split(".")
        level = tree
        for depth, head in enumerate(heads):
            below = level.setdefault(head, {})
            if not isinstance(below, dict):
                leaf = ".".join([*heads[depth:], leaf])
                break
            level = below
        level[leaf] = value
    return tree


def params_file_text(
    node_name: str, parameters: Iterable[Mapping[str, Any]], schema: Mapping[str, Any] | None
) -> str:
    """YAML for ``--params-file``; with a schema, only the parameters it owns."""
    values = {p["name"]: p["value"] for p in parameters if p["type"] != "unset"}
    if schema is not None:
        keep = owned_names(schema, values)
        values = {name: value for name, value in values.items() if name in keep}
    document = {node_name: {"ros__parameters": nested(values.items())}}
    return yaml.safe_dump(document, sort_keys=True, default_flow_style=None, allow_unicode=True)
