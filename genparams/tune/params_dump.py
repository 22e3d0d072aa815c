"""A node's current values as a params file: the parameters its schema owns, nested by dots."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import yaml


def owned_names(schema: Mapping[str, Any], values: Mapping[str, Any]) -> set[str]:
    """The full names a schema message covers, mapped entries expanded with the live keys."""
    names: set[str] = set()
    for described in schema.get("classes", []):
        names.update(p["name"] for p in described["parameters"])
        for group in described["maps"]:
            keys = values.get(group["for_each"]) or []
            for key in keys:
                names.update(
                    ".".join(p for p in (group["path"], key, f["name"]) if p)
                    for f in group["fields"]  # a field named "" is the entry itself (per item)
                )
    return names


def nested(flat: Iterable[tuple[str, Any]]) -> dict[str, Any]:
    tree: dict[str, Any] = {}
    for name, value in sorted(flat):
        *heads, leaf = name.split(".")
        level = tree
        for head in heads:
            level = level.setdefault(head, {})
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
