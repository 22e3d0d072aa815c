"""Check a whole bringup params file: every node section against its node's schemas.

The manifest names the nodes that run (exactly, or by a pattern such as
``/*/controller_manager``). A pattern stands for every node a section of the
file names that it matches, so one entry covers the namespaced copies of a
robot. Each node is then checked as check-params checks one node, with the
sections rcl applies to it. A section that reaches none of these nodes is
reported: no schema claims it, so nothing checks it, and if its name is a
typo, ROS ignores it without a word.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from genparams.paramsfile.check_params import Bound, Report, check_files
from genparams.paramsfile.explain import explain
from genparams.paramsfile.manifest import NodeEntry
from genparams.paramsfile.node_rules import NodeRule, NodeValue, check_rules
from genparams.paramsfile.node_sections import near_miss
from genparams.paramsfile.params_reader import ParamsDocument
from genparams.paramsfile.ros_yaml import node_matches
from genparams.runtime.core.naming import WILDCARD_ANY, WILDCARD_ONE
from genparams.schema.errors import SchemaProblem

ALL_NODES = "/**"


@dataclass(frozen=True)
class Deployed:
    """One manifest entry with its schemas loaded."""

    entry: NodeEntry
    bounds: tuple[Bound, ...]


# What rclpy gives every node that nothing sets: a rule across nodes compares these too.
BUILTIN_DEFAULTS = {"use_sim_time": False, "start_type_description_service": True}


def check_deployment(
    deployed: Sequence[Deployed],
    document: ParamsDocument,
    known: Sequence[str] = (),
    rules: Sequence[NodeRule] = (),
) -> tuple[Report, list[str]]:
    """Every node of ``document`` checked against its schemas, and the rules across nodes
    against their effective values; and which node got which check."""
    problems: set[SchemaProblem] = set(document.problems)
    warnings: set[SchemaProblem] = set()
    checked: list[str] = []
    nodes = configured_nodes(deployed, document)
    for node, item in nodes:
        report = check_files(
            item.bounds,
            [document],
            [node],
            (*known, *item.entry.known),
            near_misses=False,
            sections_needed=False,
        )
        problems.update(report.problems)
        warnings.update(report.warnings)
        schemas = (
            ", ".join(
                f"{b.schema.source_name}{'@' + b.prefix if b.prefix else ''}" for b in item.bounds
            )
            or "no schema"
        )
        checked.append(f"{node}: checked against {schemas} (manifest entry {item.entry.node})")
    names = [node for node, _ in nodes]
    if rules:
        values = {
            node: effective_values(item.bounds if item else (), [document], node, known)
            for node, item in rule_nodes(nodes, document)
        }
        results = check_rules(rules, values)
        problems.update(results.problems)
        checked.extend(str(note) for note in results.notes)
    for section in document.sections:
        if any(node_matches(section.node, node) for node in names):
            continue
        problems.add(
            SchemaProblem(
                section.node_location,
                section.node,
                f"no node of the manifest gets this section"
                f"{_hint(section.node, [*names, *(d.entry.node for d in deployed)])}: "
                "nothing checks it, and ROS applies it to no node listed",
            )
        )
    return Report(tuple(sorted(problems)), tuple(sorted(warnings))), checked


def configured_nodes(
    deployed: Sequence[Deployed], document: ParamsDocument
) -> list[tuple[str, Deployed]]:
    """The nodes this file configures: those a section names, beyond ``/**`` (every node).

    A manifest serves many files: a node none of this file's sections names is
    not configured here, so its required parameters are not this file's to give.
    An exact entry is such a node when a section matches it; a pattern entry
    stands for each section name it matches (or for itself, when sections are
    patterns too, as in ``/**/controller_manager``).
    """
    named = [s.node for s in document.sections if s.node != ALL_NODES]
    found: dict[str, Deployed] = {}
    for item in deployed:
        pattern = item.entry.node
        if not _is_pattern(pattern):
            if any(node_matches(section, pattern) for section in named):
                found.setdefault(pattern, item)
            continue
        concrete = [n for n in named if not _is_pattern(n) and node_matches(pattern, n)]
        reached = any(node_matches(section, pattern) for section in named)
        for node in concrete or ([pattern] if reached else []):
            found.setdefault(node, item)
    return list(found.items())


def rule_nodes(
    nodes: Sequence[tuple[str, Deployed]], document: ParamsDocument
) -> list[tuple[str, Deployed | None]]:
    """The nodes rules across nodes compare: the manifest's nodes of this file, and every
    other node a section names in full (its values untyped)."""
    found: dict[str, Deployed | None] = dict(nodes)
    for section in document.sections:
        if not _is_pattern(section.node):
            found.setdefault(section.node, None)
    return list(found.items())


def effective_values(
    bounds: Sequence[Bound], documents: Sequence[ParamsDocument], node: str, known: Sequence[str]
) -> dict[str, NodeValue]:
    """What ``node`` starts with, as explain traces it, and rclpy's own defaults."""
    explanation = explain(bounds, documents, node, known)
    values = {
        row.name: NodeValue(row.value, row.source.text)
        for row in explanation.rows
        if row.source is not None and row.value is not None
    }
    for name, value in BUILTIN_DEFAULTS.items():
        values.setdefault(name, NodeValue(value, "rclpy's default"))
    return values


def _is_pattern(name: str) -> bool:
    return any(t in (WILDCARD_ONE, WILDCARD_ANY) for t in name.split("/"))


def _hint(section: str, nodes: list[str]) -> str:
    for node in nodes:
        reason = near_miss(section, node)
        if reason is not None:
            return f" (did you mean {node}? {reason})"
    return ""
