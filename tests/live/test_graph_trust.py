"""What the graph believes: a schema only from the one node of its name, schema topics only of
nodes that exist, hidden nodes only when asked for, and no pattern that costs too much.

- A second node with a camera's name publishes a forged schema on the camera's topic: the
  camera's schema is not believed (the page shows why), and the audit reports the name.
- One node publishes the schema topics of 40 nodes that do not exist: none is followed.
- A node named ``_hidden_...`` is listed by the page and the audit only when asked for.
- A node publishes a schema whose pattern multiplies out (``(?:x{400}){400}``): its schema is a
  problem, for the page and the audit, told before anything compiles the pattern.
"""

from __future__ import annotations

import json
from collections.abc import Iterator

import pytest

from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX
from genparams.tune.server import TuneServer
from tests.live.support import hostile_nodes
from tests.node_process import node_process
from tests.tune.support import api_call, demo_nodes, eventually, run_audit, unique
from tests.tune.test_hostile_schemas import camera_message

CAM, GOOD = f"/{unique('trust_cam')}", f"/{unique('trust_good')}"
GHOSTS = unique("trust_ghosts")
HIDDEN = f"/_{unique('trust_hidden')}"
GHOST_COUNT = 40
COSTLY = f"/{unique('trust_costly')}"
COSTLY_PATTERN = "(?:x{400}){400}"


@pytest.fixture(scope="module")
def graph(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    workdir = tmp_path_factory.mktemp("trust")
    forged = camera_message(CAM, workdir)
    forged["hash"] = "forged"
    costly = camera_message(COSTLY, workdir)
    robot_name = next(p for p in costly["classes"][0]["parameters"] if p["name"] == "robot_name")
    robot_name["validators"] = [["pattern", COSTLY_PATTERN]]
    twin = [
        {"node": CAM[1:], "topic": CAM + SCHEMA_TOPIC_SUFFIX, "text": json.dumps(forged)},
        {"node": COSTLY[1:], "topic": COSTLY + SCHEMA_TOPIC_SUFFIX, "text": json.dumps(costly)},
    ]
    spec_file = workdir / "twin.json"
    spec_file.write_text(json.dumps(twin), encoding="utf-8")
    with (
        demo_nodes(f"{CAM[1:]}:camera", f"{GOOD[1:]}:camera"),
        hostile_nodes(f"{GHOSTS}:ghosts:{GHOST_COUNT}", f"{HIDDEN[1:]}:plain"),
        node_process("tests.tune.hostile_schemas", str(spec_file)),
    ):
        yield


@pytest.fixture(scope="module")
def server(graph: None) -> Iterator[TuneServer]:
    tune = TuneServer()
    tune.start()
    try:
        yield tune
    finally:
        tune.stop()


def listed(server: TuneServer) -> dict[str, dict[str, object]]:
    return {n["name"]: n for n in api_call(server, "/api/nodes").json()["nodes"]}


def test_two_nodes_of_one_name_leave_neither_a_schema(server: TuneServer) -> None:
    eventually(lambda: listed(server).get(GOOD, {}).get("genparams"))

    def twin_seen() -> dict[str, object] | None:
        # CAM can be listed before discovery has found its twin: wait for both.
        node = listed(server).get(CAM)
        return node if node is not None and "2 nodes" in str(node["schema_problem"]) else None

    node = eventually(twin_seen)
    assert node["genparams"] is False
    assert f"2 nodes in the graph have the name {CAM}" in str(node["schema_problem"])
    answer = api_call(server, f"/api/node?name={CAM}")
    if not answer.ok:
        # The twins answer one service call each, in either order: a list from one and a
        # describe from the other cannot be used together. Never a 500, never a schema.
        assert answer.status == 422 and b"cannot be used" in answer.body, answer.body
        return
    assert answer.json()["schema"] is None
    assert "2 nodes" in answer.json()["schema_problem"]


def test_the_audit_reports_two_nodes_of_one_name(graph: None) -> None:
    # The whole graph, once its node list (each name with its count) is settled: naming
    # the nodes ends discovery at the first node of a name.
    done = run_audit("--format", "json", settle=3.0)
    assert "Traceback" not in done.stderr, done.stderr
    findings = json.loads(done.stdout)["findings"]
    kinds = {(f["node"], f["kind"]) for f in findings}
    assert (CAM, "duplicate-name") in kinds, findings
    assert not {kind for node, kind in kinds if node == GOOD} - {"drift-from-default"}
    assert done.returncode == 1


def test_schema_topics_of_nodes_not_in_the_graph_are_not_followed(server: TuneServer) -> None:
    graph = server.graph
    ghost_topics = {f"/{GHOSTS}_ghost_{i}{SCHEMA_TOPIC_SUFFIX}" for i in range(GHOST_COUNT)}

    def discovered() -> bool:
        return ghost_topics <= {t for t, _ in graph.node.get_topic_names_and_types()}

    eventually(discovered)
    eventually(lambda: graph.schema(GOOD))
    graph.watch_schema_topics()
    with graph.lock:
        followed = set(graph.topics.subscriptions)
    assert GOOD + SCHEMA_TOPIC_SUFFIX in followed
    assert not followed & ghost_topics
    assert len(list(graph.node.subscriptions)) < GHOST_COUNT


def test_hidden_nodes_are_listed_only_when_asked(server: TuneServer, graph: None) -> None:
    eventually(lambda: HIDDEN in server.graph.node_names(hidden=True))
    eventually(lambda: GOOD in listed(server))
    assert HIDDEN not in listed(server)
    assert HIDDEN not in server.graph.node_names(hidden=False)
    assert api_call(server, f"/api/node?name={HIDDEN}").ok  # a node named is served
    shown = TuneServer(include_hidden=True, graph=server.graph)
    shown.start()
    try:
        assert HIDDEN in {n["name"] for n in api_call(shown, "/api/nodes").json()["nodes"]}
    finally:
        shown.stop()


def test_the_audit_lists_hidden_nodes_only_when_asked(graph: None) -> None:
    plain = run_audit("--format", "json", settle=3.0)
    assert HIDDEN not in json.loads(plain.stdout)["without_schema"], plain.stderr
    asked = run_audit("--format", "json", "--include-hidden", settle=3.0)
    assert HIDDEN in json.loads(asked.stdout)["without_schema"], asked.stderr


def test_a_pattern_that_multiplies_out_is_a_schema_problem(server: TuneServer) -> None:
    node = eventually(lambda: listed(server).get(COSTLY, {}).get("schema_problem"))
    assert "expands to more than" in str(node) and COSTLY_PATTERN in str(node)
    done = run_audit("--format", "json", COSTLY, settle=3.0)
    assert "Traceback" not in done.stderr, done.stderr
    details = [
        f["detail"] for f in json.loads(done.stdout)["findings"] if f["kind"] == "bad-schema"
    ]
    assert any("expands to more than" in detail for detail in details), details
