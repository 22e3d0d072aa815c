"""What rclpy nodes do that the schema format cannot state yet.

``awaiting_feature`` is the one place that decides it. Each branch names the
construct and the schema feature it needs; the import warns and leaves the
parameter out. When a feature lands, its branch becomes a translation in
convert.py and the warning goes.
"""

from __future__ import annotations

from genparams.rclpy_import.scan import Found, NodeOption, descriptor_of
from genparams.rclpy_import.values import TypeMarker


def awaiting_feature(found: Found | NodeOption) -> str | None:
    """The schema feature this declaration (or node option) needs, worded for a warning;
    None when today's format can state it."""
    if isinstance(found, NodeOption):
        return (
            f"{found.construct}: parameters named by the params file: "
            "needs open groups keyed by the overrides"
        )
    descriptor = descriptor_of(found)
    if descriptor is not None and descriptor.fields.get("dynamic_typing"):
        return "dynamic_typing=True: needs dynamic typing"
    if not found.value.given and descriptor is None and found.value.problem is None:
        return "declared by name only (rclpy types it dynamically): needs dynamic typing"
    if isinstance(found.value.value, TypeMarker) and found.value.problem is None:
        return "type-only declaration without a value: needs an optional parameter"
    typed = descriptor is not None and isinstance(descriptor.fields.get("type"), TypeMarker)
    if typed and found.value.value is None and found.value.problem is None:
        return "a type in the descriptor without a value: needs an optional parameter"
    if found.runtime_loop is not None and (found.name_is_item or found.name.problem):
        named = "named by the item" if found.name_is_item else "its name computed from the item"
        return f"one parameter per item of {found.runtime_loop}, {named}: needs per-item parameters"
    if found.condition is not None:
        return f"declared only under a condition ({found.condition}): needs conditional declaration"
    return None
