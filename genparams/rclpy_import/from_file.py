"""A node's parameters as its params files give them: for a node that declares what its
overrides name (``automatically_declare_parameters_from_overrides=True``) or reads them
(``get_parameters_by_prefix``, ``_parameter_overrides``), the values of its section are the
types and defaults the schema states."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from genparams.rclpy_import.leaves import default_of, schema_type
from genparams.rclpy_import.placing import ItemPlace
from genparams.runtime.core.naming import NODE_PARAMETERS, is_ros_name


def file_type(values: list[Any]) -> str | None:
    """The one schema type every value has, or None (none given, mixed, not a value)."""
    kinds = {schema_type(v)[0] for v in values if v is not None}
    if len(kinds) != 1:
        return None
    kind = kinds.pop()
    return None if kind in (None, "byte_array") else kind


def entry_values(overrides: Mapping[str, Any], place: ItemPlace) -> list[Any]:
    """The values the file gives the entries of a group (``robots.<key>.battery_low``), or
    the items of a per-item parameter (``offsets.<key>``)."""
    head = f"{place.head}." if place.head else ""
    tail = f".{place.tail}" if place.tail else ""
    out = []
    for name, value in overrides.items():
        if name.startswith(head) and name.endswith(tail):
            key = name[len(head) : len(name) - len(tail)]
            if key and "." not in key:
                out.append(value)
    return out


def undeclared(
    overrides: Mapping[str, Any], placed: set[str], open_prefixes: set[str]
) -> list[tuple[str, dict[str, Any] | None, str]]:
    """The file's parameters the schema holds no place for yet: each name, with its leaf
    (type and default from the file) or None and the reason it cannot be one."""
    out: list[tuple[str, dict[str, Any] | None, str]] = []
    for name, value in overrides.items():
        if name in placed or name in NODE_PARAMETERS:
            continue
        if any(name.startswith(f"{prefix}.") for prefix in open_prefixes):
            continue  # an entry of an open group: the group states it
        if not is_ros_name(name):
            out.append((name, None, "not a name genparams declares"))
            continue
        kind, problem = schema_type(value)
        if value is None:
            out.append((name, None, "written empty ([] or {}): rclpy reads it as not set"))
        elif kind is None or kind == "byte_array":
            out.append((name, None, problem or "an empty list"))
        else:
            out.append((name, {"type": kind, "default": default_of(value)}, ""))
    return out
