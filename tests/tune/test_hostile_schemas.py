"""Schema messages a tool must not trust, published by other nodes while a good node is tuned
and audited: each is a problem for the node it concerns; the good node stays fine.

The hostile publishers run in a process of their own: one publishes `{"node": ["x"]}`, one
arrays nested 100,000 deep, one format 99, one an unknown type, one a schema for the
camera on its own topic, and one publishes on the plain node's topic.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from playwright.sync_api import expect, sync_playwright

from genparams.runtime.core.json_codec import loads
from genparams.runtime.core.spec import compile_schema
from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX, class_text, node_message_text
from genparams.tune.server import TuneServer
from tests.node_process import node_process
from tests.support import ROOT, load_generated
from tests.tune.support import (
    CHROMIUM,
    CHROMIUM_ARGS,
    api_call,
    demo_nodes,
    eventually,
    run_audit,
    unique,
)

CAM, PLAIN = f"/{unique('hostile_cam')}", f"/{unique('hostile_plain')}"
LISTED, DEEP, FUTURE, FLOAT32, SPOOFER, THIEF = (
    f"/{unique(f'hostile_{s}')}" for s in ("listed", "deep", "future", "float32", "spoof", "thief")
)
# The problem each node gets, in part.
EXPECTED = {
    LISTED: "schema message: no 'format'",
    DEEP: "schema message: nested 100000 deep",
    FUTURE: "schema message: format 99: this genparams reads format 1",
    FLOAT32: "unknown type 'float32'",
    SPOOFER: f"names node '{CAM}', but was published on the topic of {SPOOFER}",
    PLAIN: f"{THIEF}, not {PLAIN}, published on {PLAIN}'s schema topic",
}


def camera_message(node: str, tmp_path: Path) -> dict[str, Any]:
    module = load_generated(ROOT / "examples/camera_node/camera_driver.yaml", tmp_path)
    compiled = compile_schema(module.CameraDriverParams._SPEC)
    return dict(json.loads(node_message_text(node, [class_text(compiled, "")])))


def hostile_entries(tmp_path: Path) -> list[dict[str, str]]:
    future = camera_message(FUTURE, tmp_path) | {"format": 99}
    float32 = camera_message(FLOAT32, tmp_path)
    float32["classes"][0]["parameters"][0]["type"] = "float32"
    texts = {
        LISTED: '{"node": ["x"]}',
        DEEP: "[" * 100_000 + "]" * 100_000,
        FUTURE: json.dumps(future),
        FLOAT32: json.dumps(float32),
        SPOOFER: json.dumps(camera_message(CAM, tmp_path)),
    }
    entries = [
        {"node": n[1:], "topic": n + SCHEMA_TOPIC_SUFFIX, "text": t} for n, t in texts.items()
    ]
    thief = json.dumps(camera_message(PLAIN, tmp_path))
    entries.append({"node": THIEF[1:], "topic": PLAIN + SCHEMA_TOPIC_SUFFIX, "text": thief})
    return entries


@pytest.fixture(scope="module")
def graph_with_hostiles(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    workdir = tmp_path_factory.mktemp("hostile")
    spec_file = workdir / "hostile.json"
    spec_file.write_text(json.dumps(hostile_entries(workdir)), encoding="utf-8")
    with (
        demo_nodes(f"{CAM[1:]}:camera", f"{PLAIN[1:]}:plain"),
        node_process("tests.tune.hostile_schemas", str(spec_file)),
    ):
        yield


@pytest.fixture(scope="module")
def server(graph_with_hostiles: None) -> Iterator[TuneServer]:
    tune = TuneServer()
    tune.start()
    try:
        yield tune
    finally:
        tune.stop()


def call(server: TuneServer, path: str, body: Any = None) -> Any:
    """An API call over HTTP; the answer must be strict JSON."""
    answer = api_call(server, path, body)
    assert answer.ok, answer.body
    text = answer.body.decode("ascii")
    json.loads(text, parse_constant=lambda token: pytest.fail(f"{token} in {path}"))
    return loads(text)


def listed_problems(server: TuneServer) -> dict[str, Any]:
    return {n["name"]: n["schema_problem"] for n in call(server, "/api/nodes")["nodes"]}


def test_tuning_shows_each_bad_schema_as_a_problem_and_tunes_the_good_node(
    server: TuneServer,
) -> None:
    def all_arrived() -> dict[str, Any] | None:
        listed = {n["name"]: n for n in call(server, "/api/nodes")["nodes"]}
        if not listed.get(CAM, {}).get("genparams"):
            return None
        problems = {name: node["schema_problem"] for name, node in listed.items()}
        arrived = all(part in (problems.get(node) or "") for node, part in EXPECTED.items())
        return problems if arrived else None

    problems = eventually(all_arrived)
    assert problems[CAM] is None

    # The executor survived every message: the good node reads and sets as before.
    cam = call(server, f"/api/node?name={CAM}")
    assert cam["schema_problem"] is None
    assert cam["schema"]["node"] == CAM
    result = call(
        server,
        "/api/set",
        {"node": CAM, "params": [{"name": "camera.fps", "type": "double", "value": 15.0}]},
    )
    assert result["results"][0]["successful"], result
    values = {p["name"]: p["value"] for p in call(server, f"/api/node?name={CAM}")["parameters"]}
    assert values["camera.fps"] == 15.0

    # A bad node is shown with its problem and its plain parameters, never its claimed schema.
    for node, part in EXPECTED.items():
        answer = call(server, f"/api/node?name={node}")
        assert answer["schema"] is None
        assert part in answer["schema_problem"]
    plain = call(server, f"/api/node?name={PLAIN}")
    assert "gain" in {p["name"] for p in plain["parameters"]}


def test_the_page_shows_the_problem(server: TuneServer) -> None:
    eventually(lambda: listed_problems(server).get(SPOOFER))
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        try:
            page = browser.new_page()
            page.goto(server.url + f"#{SPOOFER}")
            problem = page.locator("[data-schema-problem]")
            expect(problem).to_be_visible()
            expect(problem).to_contain_text(EXPECTED[SPOOFER])
            badge = page.locator(f'[data-node-link="{SPOOFER}"] .badge')
            expect(badge).to_have_text("bad schema")
            cam_badge = page.locator(f'[data-node-link="{CAM}"] .badge')
            expect(cam_badge).to_have_text("schema")
        finally:
            browser.close()


def test_the_audit_reports_each_bad_schema_and_the_good_node_fine(
    graph_with_hostiles: None,
) -> None:
    done = run_audit("--format", "json", CAM, *EXPECTED)  # each publishes on its schema topic
    assert "Traceback" not in done.stderr, done.stderr
    assert done.returncode == 1, done.stdout + done.stderr
    report = json.loads(done.stdout, parse_constant=lambda token: pytest.fail(token))
    by_node: dict[str, list[dict[str, Any]]] = {}
    for finding in report["findings"]:
        by_node.setdefault(finding["node"], []).append(finding)
    assert {f["kind"] for f in by_node.get(CAM, [])} <= {"drift-from-default"}, by_node.get(CAM)
    assert CAM in report["audited"]
    for node, part in EXPECTED.items():
        kinds = [(f["kind"], f["detail"]) for f in by_node[node]]
        assert ("bad-schema", next(d for k, d in kinds if k == "bad-schema")) in kinds
        assert any(part in detail for kind, detail in kinds if kind == "bad-schema"), kinds
        assert "unreachable" not in {kind for kind, _ in kinds}


def test_non_finite_numbers_of_a_json_report_stay_strict() -> None:
    from genparams.audit.findings import DRIFT_DEFAULT, Finding
    from genparams.audit.report import json_report
    from genparams.audit.walk import AuditResult

    result = AuditResult([Finding("/n", DRIFT_DEFAULT, "x", "differs", math.nan, math.inf)])
    text = json_report(result)
    json.loads(text, parse_constant=lambda token: pytest.fail(token))
    finding = loads(text)["findings"][0]
    assert math.isnan(finding["expected"]) and finding["actual"] == math.inf
