"""What a node declares, as the comparison of import-rclpy with real nodes reads it: each
parameter's descriptor fields and value, taken from a real rclpy node. One rule, used by
the tests on the test nodes and by ``bench.import_rates`` on public nodes."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node

from genparams.runtime.core.naming import NODE_PARAMETERS

DESCRIPTOR_FIELDS = ("name", "type", "description", "additional_constraints", "read_only",
                     "dynamic_typing")  # fmt: skip
ITEM_RULE = "each item names an entry of "

Declared = dict[str, tuple[tuple[Any, ...], Any]]


def declared(node: Node) -> Declared:
    """Every parameter the node's code declared: its descriptor as a tuple, and its value."""
    names = [n for n in node.list_parameters([], 0).names if n not in NODE_PARAMETERS]
    descriptors = node.describe_parameters(names)
    # not get_parameter: it raises for a parameter declared by type only and never set
    values = [node._parameters[n].value for n in names]
    return {n: (fields(d), plain(v)) for n, d, v in zip(names, descriptors, values, strict=True)}


def fields(descriptor: ParameterDescriptor) -> tuple[Any, ...]:
    ranges = tuple(
        (kind, r.from_value, r.to_value, r.step)
        for kind in ("floating_point_range", "integer_range")
        for r in getattr(descriptor, kind)
    )
    return (*(getattr(descriptor, f) for f in DESCRIPTOR_FIELDS), ranges)


def without_item_rule(descriptor: tuple[Any, ...]) -> tuple[Any, ...]:
    """A key list of per-item parameters states the rule genparams adds (its items must
    name entries) in its additional_constraints, before the node's own text: without it."""
    constraints = DESCRIPTOR_FIELDS.index("additional_constraints")
    text = descriptor[constraints]
    if text.startswith(ITEM_RULE):
        text = text.partition("; no repeats")[2].removeprefix("; ")
        return (*descriptor[:constraints], text, *descriptor[constraints + 1 :])
    return descriptor


def plain(value: Any) -> Any:
    return list(value) if isinstance(value, (list, tuple)) or hasattr(value, "tolist") else value


def schema_key(keys: Iterable[str], name: str) -> str | None:
    """The schema key that holds the parameter ``name``: its own name, a mapped group's
    entry (``gains.*.p`` holds ``gains.shoulder.p``), or a per-item parameter (``offsets``
    holds ``offsets.shoulder``, ``*`` the top level's); None when no key holds it."""
    known = set(keys)
    if name in known:
        return name
    parts = name.split(".")
    for index in range(len(parts) - 1):
        entry = ".".join([*parts[:index], "*", *parts[index + 1 :]])
        if entry in known:
            return entry
    space = name.rpartition(".")[0] or "*"
    return space if space in known else None
