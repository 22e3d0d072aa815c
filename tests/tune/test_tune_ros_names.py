"""The tuning page (real Chromium) and audit on a node whose names hold '-', '/' and `type`
(schema: tests/cases/ros_names; the node runs in another process with a params file)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from playwright.sync_api import Page, expect

from genparams.audit.deployment import read_deployment
from genparams.audit.findings import DRIFT_FILE, VIOLATION
from genparams.audit.walk import audit
from genparams.live.graph import Graph
from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX
from genparams.tune.server import TuneServer
from tests.patience import WAIT_S
from tests.runtime.test_ros_names import PARAMS  # one params file for node and page
from tests.support import RosHarness, ServiceClient
from tests.tune.support import demo_nodes, eventually, open_node, unique

NODE = f"/{unique('tune_names')}"
SCALE = "walk_button.axis_mappings.twist-linear-x.scale"


@pytest.fixture(scope="module")
def params_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("names") / "teleop.yaml"
    path.write_text(PARAMS, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def server(params_file: Path) -> Iterator[TuneServer]:
    with demo_nodes(f"{NODE[1:]}:names", ros_args=("--params-file", str(params_file))):
        tune = TuneServer(nodes=(NODE,))
        tune.start()
        try:
            yield tune
        finally:
            tune.stop()


@pytest.fixture
def page(page: Page, server: TuneServer) -> Page:
    open_node(page, server, NODE)
    return page


@pytest.fixture(scope="module")
def remote(ros_harness: RosHarness) -> ServiceClient:
    return ServiceClient(ros_harness, NODE)


def control(page: Page, name: str):  # type: ignore[no-untyped-def]
    return page.locator(f'form[data-node="{NODE}"] [data-param="{name}"]')


def test_the_page_lists_the_names_as_ros_spells_them(page: Page) -> None:
    expect(control(page, SCALE)).to_have_value("0.8")
    expect(control(page, "walk_button.type")).to_have_value("action")
    expect(control(page, "type.type.mode")).to_have_value("slow")
    expect(page.locator('[data-param-box="input_shape/height"]')).to_have_value("720")
    expect(page.locator('[data-row="max-speed"]')).to_contain_text("m/s")
    expect(page.locator('[data-entry="buttons.deadman-switch"]')).to_have_count(1)
    expect(control(page, "buttons.deadman-switch.type")).to_have_value("hold")


def test_a_set_of_a_dashed_name_reaches_the_node_and_is_checked(
    page: Page, remote: ServiceClient
) -> None:
    box = control(page, SCALE)
    box.fill("0.3")
    box.dispatch_event("change")
    eventually(lambda: remote.get(SCALE) == [0.3])
    height = page.locator('[data-param-box="input_shape/height"]')
    height.fill("0")
    height.dispatch_event("change")
    expect(page.locator('[data-param-error="input_shape/height"]')).to_contain_text(
        "input_shape/height: must be within"
    )
    assert remote.get("input_shape/height") == [720]


def topics_of(graph: Graph) -> set[str]:
    return {topic for topic, _types in graph.node.get_topic_names_and_types()}


def test_audit_reads_the_names_and_compares_them_with_a_deployment(
    server: TuneServer, tmp_path: Path
) -> None:
    deployment = tmp_path / "robot.yaml"
    deployment.write_text(
        f"{NODE}:\n  ros__parameters:\n    max-speed: 3.0\n    type:\n      type:\n"
        "        mode: slow\n",
        encoding="utf-8",
    )
    graph = Graph(unique("audit_names"))
    try:
        eventually(lambda: NODE + SCHEMA_TOPIC_SUFFIX in topics_of(graph))
        result = audit(graph, read_deployment([deployment]), only=(NODE,), timeout=WAIT_S)
    finally:
        graph.close()
    assert result.audited == [NODE]
    assert not [f for f in result.findings if f.kind == VIOLATION]
    drifted = [(f.parameter, f.expected, f.actual) for f in result.findings if f.kind == DRIFT_FILE]
    assert drifted == [("max-speed", 3.0, 2.5)]
