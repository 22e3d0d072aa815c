"""The tuning page in a real browser (Debian's Chromium) against real nodes in another process."""

from __future__ import annotations

import json
import os
import urllib.error
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import pytest
from playwright.sync_api import Page, Route, expect
from rclpy.parameter import Parameter

from genparams.cli import main as cli_main
from genparams.tune.server import TuneServer
from tests.support import ROOT, RosHarness
from tests.tune.support import demo_nodes, error, eventually, open_node, service_client, unique

CAM, ARM, MOTION, PLAIN = (
    f"/{unique(s)}" for s in ("tune_cam", "tune_arm", "tune_motion", "tune_plain")
)


@pytest.fixture(scope="module")
def nodes() -> Iterator[None]:
    specs = [f"{CAM[1:]}:camera", f"{ARM[1:]}:arm", f"{MOTION[1:]}:motion", f"{PLAIN[1:]}:plain"]
    with demo_nodes(*specs):
        yield


@pytest.fixture(scope="module")
def server(nodes: None) -> Iterator[TuneServer]:
    tune = TuneServer(nodes=(CAM, ARM, MOTION, PLAIN))
    tune.start()
    try:
        yield tune
    finally:
        tune.stop()


def control(page: Page, node: str, name: str):  # type: ignore[no-untyped-def]
    return page.locator(f'form[data-node="{node}"] [data-param="{name}"]')


def test_slider_sets_the_node_value(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, CAM)
    slider = control(page, CAM, "camera.fps")
    expect(slider).to_have_attribute("step", "0.5")
    slider.fill("60")
    remote = service_client(ros_harness, CAM)
    eventually(lambda: remote.get("camera.fps") == [60.0])
    expect(page.locator('[data-diff="camera.fps"]')).to_be_visible()


def test_out_of_range_is_stopped_in_the_page(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, CAM)
    box = page.locator('[data-param-box="camera.width"]')
    box.fill("9000")
    box.dispatch_event("change")
    expect(error(page, "camera.width")).to_contain_text(
        "camera.width: must be within [64, 4096] (range), got"
    )
    assert service_client(ros_harness, CAM).get("camera.width") == [640]


def test_rule_breaking_value_shows_the_node_reason(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, MOTION)
    control(page, MOTION, "min_speed").fill("4")
    expect(error(page, "min_speed")).to_contain_text("rule 'speed_order' broken")
    assert service_client(ros_harness, MOTION).get("min_speed") == [0.1]


def test_a_set_made_elsewhere_shows_up(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, CAM)
    result = service_client(ros_harness, CAM).set(Parameter("camera.width", value=800))
    assert result[0].successful
    expect(control(page, CAM, "camera.width")).to_have_value("800")
    open_node(page, server, PLAIN)
    service_client(ros_harness, PLAIN).set(Parameter("frame", value="odom"))
    expect(control(page, PLAIN, "frame")).to_have_value("odom")


def test_read_only_parameters_are_disabled(page: Page, server: TuneServer) -> None:
    open_node(page, server, CAM)
    expect(control(page, CAM, "robot_name")).to_be_disabled()
    expect(control(page, CAM, "camera.encoding")).to_be_enabled()
    expect(page.locator('[data-row="serial"] .required')).to_be_visible()
    open_node(page, server, PLAIN)
    expect(control(page, PLAIN, "hardware_id")).to_be_disabled()
    expect(control(page, PLAIN, "gain")).to_have_attribute("step", "0.5")


def test_a_choice_offers_exactly_its_choices(page: Page, server: TuneServer) -> None:
    open_node(page, server, CAM)
    options = control(page, CAM, "camera.encoding").locator("option")
    assert options.all_text_contents() == ["rgb8", "mono8", "bgr8"]


def test_plain_node_slider_sets_the_value(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, PLAIN)
    control(page, PLAIN, "gain").fill("7.5")
    eventually(lambda: service_client(ros_harness, PLAIN).get("gain") == [7.5])


def test_add_and_remove_a_map_key(page: Page, server: TuneServer, ros_harness: RosHarness) -> None:
    open_node(page, server, ARM)
    page.locator('[data-map-add="gains"]').fill("wrist")
    page.locator('[data-map-add-button="gains"]').click()
    expect(control(page, ARM, "gains.wrist.p")).to_be_visible()
    remote = service_client(ros_harness, ARM)
    assert remote.get("joints", "gains.wrist.p") == [["shoulder", "elbow", "wrist"], 1.0]
    page.locator('[data-map-remove="gains.elbow"]').click()
    expect(control(page, ARM, "gains.elbow.p")).to_have_count(0)
    eventually(lambda: remote.get("joints") == [["shoulder", "wrist"]])


def test_two_edits_apply_atomically_and_one_bad_value_changes_nothing(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, MOTION)
    page.locator("#live").uncheck()
    control(page, MOTION, "max_speed").fill("2")
    control(page, MOTION, "min_speed").fill("3")
    apply = page.locator("[data-apply]")
    expect(apply).to_contain_text("Apply 2 change(s)")
    apply.click()
    expect(error(page, "min_speed")).to_contain_text("rule 'speed_order' broken")
    remote = service_client(ros_harness, MOTION)
    assert remote.get("max_speed", "min_speed") == [1.0, 0.1]
    control(page, MOTION, "min_speed").fill("1.5")
    apply.click()
    eventually(lambda: remote.get("max_speed", "min_speed") == [2.0, 1.5])


def test_downloaded_params_file_passes_check_params(
    page: Page, server: TuneServer, tmp_path: Path
) -> None:
    open_node(page, server, CAM)
    with page.expect_download() as download:
        page.locator("[data-download]").click()
    saved = tmp_path / "cam.yaml"
    download.value.save_as(saved)
    schema = ROOT / "examples/camera_node/camera_driver.yaml"
    assert "serial: CAM12345" in saved.read_text()
    assert cli_main(["check-params", str(schema), str(saved), "--node", CAM]) == 0


def test_screenshot_for_the_docs(page: Page, server: TuneServer, tmp_path: Path) -> None:
    """The picture in the docs; `make screenshots` sets GENPARAMS_SCREENSHOTS=docs/images
    to refresh it there, every other run leaves the repository alone."""
    page.set_viewport_size({"width": 1100, "height": 900})
    open_node(page, server, CAM)
    expect(page.locator("body[data-ready]")).to_be_attached()
    target = Path(os.environ.get("GENPARAMS_SCREENSHOTS", tmp_path)) / "tune.png"
    page.screenshot(path=str(target), full_page=True)
    assert target.stat().st_size > 10_000


def post(url: str, body: dict[str, object], token: str | None = None) -> int:
    request = urllib.request.Request(
        url, data=json.dumps(body).encode(), headers={"content-type": "application/json"}
    )
    if token is not None:
        request.add_header("x-genparams-token", token)
    try:
        with urllib.request.urlopen(request, timeout=10) as response:
            return int(response.status)
    except urllib.error.HTTPError as exc:
        return exc.code


def test_read_only_page_and_token(page: Page, server: TuneServer) -> None:
    viewer = TuneServer(read_only=True, graph=server.graph, nodes=(CAM,))
    guarded = TuneServer(token="s3cret-s3cret-s3cret", graph=server.graph, nodes=(CAM,))
    try:
        viewer.start()
        open_node(page, viewer, CAM)
        expect(control(page, CAM, "camera.encoding")).to_be_disabled()
        expect(page.locator("#mode")).to_be_visible()
        assert "token" not in page.url  # the page keeps it in a cookie, not the address bar
        body: dict[str, object] = {
            "node": CAM,
            "params": [{"name": "camera.fps", "type": "double", "value": 5}],
        }
        assert post(viewer.base + "/api/set", body, token=viewer.token) == 403
        guarded.start()
        assert guarded.url.endswith("/?token=s3cret-s3cret-s3cret")
        assert post(guarded.base + "/api/set", body) == 403
        assert post(guarded.base + "/api/set", body, token="wrong") == 403
        assert post(guarded.base + "/api/set", body, token="s3cret-s3cret-s3cret") == 200
    finally:
        viewer.stop()
        guarded.stop()


def test_reset_to_default_and_the_diff(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, CAM)
    remote = service_client(ros_harness, CAM)
    assert remote.set(Parameter("control.pid.kp", value=2.5))[0].successful
    expect(page.locator('[data-diff="control.pid.kp"]')).to_contain_text("2.5")
    page.locator('[data-reset="control.pid.kp"]').click()
    eventually(lambda: remote.get("control.pid.kp") == [1.0])
    expect(page.locator('[data-diff="control.pid.kp"]')).to_have_count(0)


def test_a_change_before_the_page_listens_is_caught_up(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    """The node is read, then changed before the page's event stream opens: the event
    goes nowhere, and the page reads the node again once the stream opens."""
    open_node(page, server, CAM)  # the server knows the node
    page.goto("about:blank")
    remote = service_client(ros_harness, CAM)
    [old] = remote.get("camera.height")
    new = old + 2 if old < 4000 else old - 2
    held: list[Route] = []

    def hold(route: Route) -> None:  # the stream opens when the test says
        held.append(route)

    page.route("**/api/events", hold)

    def stale_then_changed(route: Route) -> None:
        answer = route.fetch()  # the node as it is now
        assert remote.set(Parameter("camera.height", value=new))[0].successful
        route.fulfill(response=answer)

    page.route("**/api/node?*", stale_then_changed, times=1)
    page.goto(f"{server.url}#{CAM}")
    expect(control(page, CAM, "camera.height")).to_have_value(str(old))

    def stream_asked() -> bool:
        page.wait_for_timeout(50)  # Playwright calls hold() only while in one of its calls
        return bool(held)

    eventually(stream_asked)
    held[0].continue_()
    expect(control(page, CAM, "camera.height")).to_have_value(str(new))
