"""genparams explain's output: a table of the effective configuration, or one params file."""

from __future__ import annotations

from typing import Any

from genparams.outputs.yaml_text import key_text, node_key_text, scalar_text
from genparams.paramsfile.explain import Explanation, Row
from genparams.paramsfile.ros_yaml import PARAMS_KEY, ros_type_name
from genparams.runtime.core.visible import visible
from genparams.schema.errors import SchemaProblem


def shown(value: Any) -> str:
    """A value as a params file spells it: what ROS reads back is what is shown."""
    if value is None:
        return "(not set)"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(shown(item) for item in value) + "]"
    if isinstance(value, bytes):
        return "[" + ", ".join(str(b) for b in value) + "]"
    kind = ros_type_name(value)
    return scalar_text(value, {"integer": "int"}.get(kind, kind))


def text_report(explanation: Explanation) -> str:
    lines = [f"{explanation.node}: {explanation.sections} section(s) apply, in rcl's order"]
    table = [("parameter", "value", "source", "shadowed")]
    for row in sorted(explanation.rows, key=lambda r: r.name):
        cells = (row.name, shown(row.value), _source(row), _shadowed(row))
        table.append((visible(cells[0]), visible(cells[1]), visible(cells[2]), visible(cells[3])))
    widths = [max(len(r[i]) for r in table) for i in range(3)]
    for cells in table:
        text = "  ".join(c.ljust(w) for c, w in zip(cells, widths, strict=False))
        lines.append(f"{text}  {cells[3]}".rstrip())
    ignored = [str(p) for p in explanation.report.problems]
    ignored += [
        str(
            SchemaProblem(
                s.section.node_location, s.section.node, f"section for another node: {s.reason}"
            )
        )
        for s in explanation.near_misses
    ]
    if ignored:
        lines += ["", "What ROS would ignore or refuse:"]
        lines += [f"  {line}" for line in ignored]
    if explanation.report.warnings:
        lines += ["", "Warnings:", *(f"  {w}" for w in explanation.report.warnings)]
    return "\n".join(lines) + "\n"


def _source(row: Row) -> str:
    if row.source is None:
        return "optional, not set" if row.optional else "required, not set"
    owner = {"rclpy": " [rclpy]", "known": " [other code]", "nobody": " [unknown: ignored]"}
    return row.source.text + owner.get(row.owner, "")


def _shadowed(row: Row) -> str:
    return "; ".join(f"{shown(s.value)} from {s.text}" for s in reversed(row.shadowed))


def yaml_report(explanation: Explanation) -> str:
    """The effective configuration as one params file for the node (unset ones left out)."""
    lines = [
        f"# Effective parameters of {explanation.node}, written by genparams explain.",
        f"{node_key_text(explanation.node)}:",
        f"  {PARAMS_KEY}:",
    ]
    rows = [r for r in sorted(explanation.rows, key=lambda r: r.name) if r.value is not None]
    for row in rows:
        if isinstance(row.value, (list, tuple, bytes)) and not row.value:
            lines.append(f"    # {key_text(row.name)}: []  (ROS reads [] as not set)")
            continue
        lines.append(f"    {key_text(row.name)}: {shown(row.value)}")
    if not rows:
        lines[-1] += " {}"
    return "\n".join(lines) + "\n"
