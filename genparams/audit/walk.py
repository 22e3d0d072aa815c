"""Walk the live graph: every node, its published schema, its values through the services.

Cost per node: one subscription to its latched schema topic (one message) and
three service calls (list, get, describe parameters), all made from one node.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from genparams.audit.deployment import expected_values, file_drift
from genparams.audit.findings import (
    BAD_ANSWER,
    BAD_SCHEMA,
    DUPLICATE_NAME,
    NO_SCHEMA,
    UNREACHABLE,
    Finding,
)
from genparams.audit.schema_checks import check_node
from genparams.live.answers import NodeAnswerError
from genparams.live.graph import Graph, is_hidden
from genparams.paramsfile.params_reader import ParamsDocument
from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX


@dataclass
class AuditResult:
    findings: list[Finding] = field(default_factory=list)
    audited: list[str] = field(default_factory=list)  # nodes that publish a schema
    plain: list[str] = field(default_factory=list)  # nodes that do not
    values: dict[str, dict[str, Any]] = field(default_factory=dict)  # by node, what was read
    seconds: float = 0.0

    @property
    def failing(self) -> bool:
        return any(finding.failing for finding in self.findings)


def settled_nodes(
    graph: Graph,
    settle: float,
    timeout: float,
    wanted: Sequence[str] = (),
    hidden: bool = False,
) -> list[str]:
    """The node list once discovery is done, or ``timeout`` passed.

    Named nodes: done when all of them appeared. Otherwise (discovery is gradual
    and nothing says it is over): when the list stopped changing for ``settle`` s.
    Hidden nodes (names starting with ``_``) are listed with ``hidden`` or when named.
    """
    deadline = time.monotonic() + timeout

    def listing() -> list[tuple[str, int]]:  # each name with how many nodes have it
        counted = graph.counted_names()
        return sorted((n, c) for n, c in counted.items() if hidden or wanted or not is_hidden(n))

    names = listing()
    stable_since = time.monotonic()
    while time.monotonic() < deadline:
        if wanted and set(wanted) <= {name for name, _ in names}:
            break
        time.sleep(0.05)
        current = listing()
        if current != names:
            names, stable_since = current, time.monotonic()
        elif not wanted and names and time.monotonic() - stable_since >= settle:
            break
    return [name for name, _ in names]


def schema_publishers(graph: Graph, names: Sequence[str], settle: float) -> list[str]:
    """The nodes with a schema topic; a node's topics may be discovered after the node."""
    deadline = time.monotonic() + settle

    def found() -> list[str]:
        topics = {topic for topic, _ in graph.node.get_topic_names_and_types()}
        return [name for name in names if name + SCHEMA_TOPIC_SUFFIX in topics]

    publishers = found()
    while len(publishers) < len(names) and time.monotonic() < deadline:
        time.sleep(0.05)
        publishers = found()
    return publishers


BATCH = 16  # nodes read at once: their calls overlap, their clients stay few


def read_batch(
    graph: Graph, names: Sequence[str], timeout: float, result: AuditResult
) -> list[tuple[str, dict[str, Any]]]:
    """Values by node; a node that does not answer, or answers what cannot be used, is a
    finding (the batch is read again one node at a time to tell which)."""
    try:
        read = graph.read_nodes(names, timeout)
    except Exception:  # whichever node it was, the others are read on
        read = {}
        for name in names:
            try:
                read[name] = graph.read_node(name, timeout)
            except TimeoutError as exc:
                result.findings.append(Finding(name, UNREACHABLE, "", str(exc)))
            except NodeAnswerError as exc:
                result.findings.append(Finding(name, BAD_ANSWER, "", str(exc)))
            except Exception as exc:  # an answer rclpy itself could not take
                detail = f"its answers cannot be read: {type(exc).__name__}: {exc}"
                result.findings.append(Finding(name, BAD_ANSWER, "", detail))
    finally:
        for name in names:
            graph.forget(name)
    return [
        (name, {p["name"]: p["value"] for p in parameters if p["type"] != "unset"})
        for name, parameters in read.items()
    ]


def audit(
    graph: Graph,
    documents: Sequence[ParamsDocument] = (),
    *,
    only: Sequence[str] = (),
    settle: float = 1.0,
    timeout: float = 5.0,
    trusted_packages: Sequence[str] = (),
    read_every: bool = False,
    hidden: bool = False,
) -> AuditResult:
    """Every node's findings; one node's failure (no answer, a malformed answer, a schema
    that cannot be used) is a finding of that node, and the others are audited on.
    ``read_every``: read the values of nodes without a schema too (rules across nodes)."""
    started = time.monotonic()
    result = AuditResult()
    names = settled_nodes(graph, settle, timeout, only, hidden)
    if only:
        names = [name for name in names if name in only]
    publishers = schema_publishers(graph, names, settle)
    graph.watch_schema_topics()
    graph.wait_for_schemas(publishers, timeout)
    to_read = []
    schemas: dict[str, dict[str, Any]] = {}
    for name in names:
        claimants = graph.claimants(name)
        if claimants > 1:
            detail = f"{claimants} nodes have this name: their answers cannot be told apart"
            result.audited.append(name)
            result.findings.append(Finding(name, DUPLICATE_NAME, "", detail))
            continue
        schema, problem = graph.schema_state(name) if name in publishers else (None, None)
        if problem is not None:
            result.audited.append(name)
            result.findings.append(Finding(name, BAD_SCHEMA, "", problem))
        elif schema is None:
            result.plain.append(name)
            result.findings.append(Finding(name, NO_SCHEMA, "", "publishes no genparams schema"))
        else:
            result.audited.append(name)
            schemas[name] = schema
        if schema is not None or documents or read_every:
            to_read.append(name)
    for start in range(0, len(to_read), BATCH):
        for name, values in read_batch(graph, to_read[start : start + BATCH], timeout, result):
            schema = schemas.get(name)
            if schema is not None:
                from_file = set(expected_values(documents, name))
                try:
                    found = check_node(name, schema, values, trusted_packages)
                except Exception as exc:  # whatever a message makes the checks raise
                    detail = f"its schema cannot be checked: {type(exc).__name__}: {exc}"
                    found = [Finding(name, BAD_SCHEMA, "", detail)]
                result.findings.extend(f for f in found if not f.set_by_file(from_file))
            result.findings.extend(file_drift(name, documents, values))
            result.values[name] = values
    result.seconds = time.monotonic() - started
    return result
