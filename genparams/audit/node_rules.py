"""Rules across nodes on a running graph: the manifest's rules over the values read."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from genparams.audit.findings import NOT_CHECKED, RULE_ACROSS_NODES, Finding
from genparams.paramsfile.node_rules import NodeRule, NodeValue, check_rules

LIVE = ""  # a live value's place: the node itself, named beside it


def rule_findings(
    rules: Sequence[NodeRule], values: Mapping[str, Mapping[str, Any]]
) -> list[Finding]:
    """A finding per rule the live values break (failing), or cannot check (not failing).

    A rule belongs to no one node: its finding's node is the rule's place in the manifest.
    """
    live = {
        node: {name: NodeValue(value, LIVE) for name, value in read.items()}
        for node, read in values.items()
    }
    results = check_rules(rules, live)
    return [
        *(Finding(p.place, RULE_ACROSS_NODES, p.key, p.message) for p in results.problems),
        *(Finding(p.place, NOT_CHECKED, p.key, p.message) for p in results.notes),
    ]
