"""genparams audit against real nodes in two processes: a violation, a drift, a plain node."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import pytest

from genparams.audit.deployment import read_deployment
from genparams.audit.findings import DRIFT_DEFAULT, DRIFT_FILE, NO_SCHEMA, VIOLATION
from genparams.audit.report import json_report
from genparams.audit.walk import AuditResult, audit
from genparams.live.graph import Graph
from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX
from tests.patience import WAIT_S
from tests.support import RosHarness
from tests.tune.support import (
    demo_nodes,
    eventually,
    run_audit,
    set_values_its_schema_forbids,
    unique,
)

LOOSE, PLAIN, CAM, ARM = (f"/{unique(f'audit_{s}')}" for s in ("loose", "plain", "cam", "arm"))
NODES = (LOOSE, PLAIN, CAM, ARM)


@pytest.fixture(scope="module")
def running(ros_harness: RosHarness) -> Iterator[None]:
    with (
        demo_nodes(f"{LOOSE[1:]}:loose", f"{PLAIN[1:]}:plain"),
        demo_nodes(f"{CAM[1:]}:camera", f"{ARM[1:]}:arm"),
    ):
        set_values_its_schema_forbids(ros_harness, LOOSE)
        yield


@pytest.fixture(scope="module")
def deployment(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("deploy") / "robot.yaml"
    path.write_text(
        f"{CAM}:\n  ros__parameters:\n    camera:\n      fps: 15.0\n      width: 640\n"
        f"{ARM}:\n  ros__parameters:\n    max_speed: 1.0\n",
        encoding="utf-8",
    )
    return path


def schema_topics_seen(graph: Graph, *nodes: str) -> bool:
    topics = {topic for topic, _ in graph.node.get_topic_names_and_types()}
    return all(node + SCHEMA_TOPIC_SUFFIX in topics for node in nodes)


@pytest.fixture(scope="module")
def result(running: None, deployment: Path) -> Iterator[AuditResult]:
    graph = Graph(unique("audit_test"))
    try:
        # The plain node has no schema topic to wait for: the audit waits `settle` for it.
        # Its topics may be discovered after the node: the others' are waited for here.
        eventually(lambda: schema_topics_seen(graph, LOOSE, CAM, ARM))
        documents = read_deployment([deployment])
        yield audit(graph, documents, only=NODES, settle=0.3, timeout=WAIT_S)
    finally:
        graph.close()


def kinds(result: AuditResult, node: str) -> dict[str, set[str]]:
    found: dict[str, set[str]] = {}
    for finding in result.findings:
        if finding.node == node:
            found.setdefault(finding.kind, set()).add(finding.parameter)
    return found


def test_a_forbidden_value_and_a_broken_rule_are_violations(result: AuditResult) -> None:
    assert result.failing
    found = kinds(result, LOOSE)
    assert found[VIOLATION] == {"max_speed", ""}  # the range, then the rule (no parameter)
    texts = [f.text() for f in result.findings if f.node == LOOSE and f.kind == VIOLATION]
    assert any("max_speed: must be within [0.0, 5.0] (range), got 7.0" in t for t in texts), texts
    assert any("rule 'one_weight_per_topic' broken" in t for t in texts), texts
    assert found[DRIFT_DEFAULT] == {"max_speed", "weights"}


def test_drift_from_the_deployment_file(result: AuditResult, deployment: Path) -> None:
    drifted = [f for f in result.findings if f.node == CAM and f.kind == DRIFT_FILE]
    assert [(f.parameter, f.expected, f.actual) for f in drifted] == [("camera.fps", 15.0, 30.0)]
    assert drifted[0].detail.startswith(f"differs from {deployment}:4:")
    assert VIOLATION not in kinds(result, CAM)
    assert kinds(result, ARM) == {}  # defaults, and what the file says


def test_nodes_without_schema_are_listed(result: AuditResult) -> None:
    assert result.plain == [PLAIN]
    assert sorted(result.audited) == sorted([LOOSE, CAM, ARM])
    assert kinds(result, PLAIN) == {NO_SCHEMA: {""}}


def test_the_json_report_lists_the_nodes_without_schema(result: AuditResult) -> None:
    report = json.loads(json_report(result))
    assert report["ok"] is False
    assert report["without_schema"] == [PLAIN]


def test_the_command_exits_1_with_a_json_report(running: None, deployment: Path) -> None:
    done = run_audit("--format", "json", "--params-file", str(deployment), LOOSE, CAM, ARM)
    assert done.returncode == 1, done.stderr
    report = json.loads(done.stdout)
    assert report["ok"] is False
    assert report["without_schema"] == []
    violations = {(f["node"], f["parameter"]) for f in report["findings"] if f["kind"] == VIOLATION}
    assert violations == {(LOOSE, "max_speed"), (LOOSE, "")}


def test_a_clean_graph_exits_0(running: None) -> None:
    done = run_audit(ARM)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "audited 1 node(s) with a schema, 0 without; 0 violation(s)" in done.stdout


def test_an_unreadable_params_file_is_bad_input(tmp_path: Path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("node: [unclosed\n", encoding="utf-8")
    done = run_audit("--params-file", str(bad))
    assert done.returncode == 2
    assert "bad.yaml:" in done.stderr
