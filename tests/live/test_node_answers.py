"""Nodes whose parameter services answer what cannot be used: fewer descriptors than names,
a value of type 42, 100,001 names, a name 100 segments deep. Each becomes a finding of that
node in the audit (the others are audited as usual), a 422 on the page's API, and an error
line from import-node: never a traceback, a 500 or a stall."""

from __future__ import annotations

import json
from collections.abc import Iterator
from typing import Any

import pytest

from genparams.tune.server import TuneServer
from tests.live.support import hostile_nodes
from tests.tune.support import api_call, demo_nodes, eventually, run_audit, run_genparams, unique

SHORT, TYPE42, HUGE, DEEP = (f"/{unique(f'answers_{k}')}" for k in ("short", "t42", "huge", "deep"))
CAM = f"/{unique('answers_cam')}"
# What each node's problem says, in part.
EXPECTED = {
    SHORT: "1 descriptors for 2 names",
    TYPE42: "has type 42",
    HUGE: "100001 names",
    DEEP: "segments",
}


@pytest.fixture(scope="module")
def graph() -> Iterator[None]:
    specs = (f"{SHORT[1:]}:short_describe", f"{TYPE42[1:]}:type42")
    with (
        hostile_nodes(*specs, f"{HUGE[1:]}:huge", f"{DEEP[1:]}:deep"),
        demo_nodes(f"{CAM[1:]}:camera"),
    ):
        yield


@pytest.fixture(scope="module")
def server(graph: None) -> Iterator[TuneServer]:
    tune = TuneServer()
    tune.start()
    try:
        eventually(lambda: set(EXPECTED) | {CAM} <= set(tune.graph.node_names()))
        yield tune
    finally:
        tune.stop()


def test_the_audit_reports_each_bad_answer_and_audits_the_good_node(graph: None) -> None:
    done = run_audit("--format", "json", CAM, *EXPECTED, settle=3.0)
    assert "Traceback" not in done.stderr, done.stderr
    assert done.returncode == 1, done.stdout + done.stderr
    report = json.loads(done.stdout)
    by_node: dict[str, list[dict[str, Any]]] = {}
    for finding in report["findings"]:
        by_node.setdefault(finding["node"], []).append(finding)
    for node, part in EXPECTED.items():
        kinds = {f["kind"]: f["detail"] for f in by_node[node]}
        assert "bad-answer" in kinds, by_node[node]
        assert part in kinds["bad-answer"], kinds
    assert CAM in report["audited"]
    assert {f["kind"] for f in by_node.get(CAM, [])} <= {"drift-from-default"}, by_node.get(CAM)


@pytest.mark.parametrize("node", list(EXPECTED))
def test_the_page_api_answers_422_naming_the_problem(server: TuneServer, node: str) -> None:
    for path in (f"/api/node?name={node}", f"/api/params-file?node={node}"):
        answer = api_call(server, path)
        assert answer.status == 422, (path, answer.status, answer.body)
        assert EXPECTED[node] in answer.json()["error"]
    # The server still serves the good node.
    assert api_call(server, f"/api/node?name={CAM}").ok


@pytest.mark.parametrize("node", [SHORT, TYPE42])
def test_import_node_names_the_problem(graph: None, node: str) -> None:
    done = run_genparams("import-node", node, "--timeout", "60")
    assert "Traceback" not in done.stderr, done.stderr
    assert done.returncode == 2, done.stdout + done.stderr
    assert done.stderr.startswith(f"genparams import-node: {node}: its ")
    assert EXPECTED[node] in done.stderr
