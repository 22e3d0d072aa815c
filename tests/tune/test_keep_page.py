"""The page's "Keep these values": a node tuned on the page, the diff shown, the values
written into the params file it was started with, the node started again from the file
holds them. The write needs the page's token, and a read-only page refuses it."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from playwright.sync_api import Page, expect
from rclpy.parameter import Parameter

from genparams.tune.server import TuneServer
from tests.support import RosHarness, ServiceClient
from tests.tune.support import api_call, demo_nodes, eventually, http_call, open_node, unique

NODE = f"/{unique('keep_page')}"
FILE = f"""\
# bench camera
{NODE}:
  ros__parameters:
    camera:
      fps: 15.0   # tuned last week
"""


@pytest.fixture
def files(tmp_path: Path) -> tuple[Path, Path]:
    params = tmp_path / "camera.yaml"
    params.write_text(FILE, encoding="utf-8")
    return params, tmp_path / "new.yaml"


def test_keep_these_values_survives_a_restart(
    ros_harness: RosHarness, page: Page, files: tuple[Path, Path]
) -> None:
    params, new = files
    with demo_nodes(f"{NODE[1:]}:camera", ros_args=("--params-file", str(params))):
        tune = TuneServer(nodes=(NODE,), keep=((params,), new))
        tune.start()
        try:
            eventually(lambda: tune.graph.schema(NODE))
            client = ServiceClient(ros_harness, NODE)
            tuned = client.set(
                Parameter("camera.fps", value=24.5), Parameter("camera.width", value=800)
            )
            assert all(r.successful for r in tuned)
            client.close()
            assert (
                http_call(
                    tune.port, "POST", "/api/keep", body=b'{"node": "%s"}' % NODE.encode()
                ).status
                == 403
            )
            open_node(page, tune, NODE)
            page.locator("[data-keep]").click()
            diff = page.locator("[data-keep-diff]")
            expect(diff).to_contain_text("-      fps: 15.0   # tuned last week")
            expect(diff).to_contain_text("+      fps: 24.5   # tuned last week")
            expect(diff).to_contain_text("+    camera.width: 800")
            assert params.read_text(encoding="utf-8") == FILE  # shown, not written yet
            page.locator("[data-keep-write]").click()
            expect(page.locator("[data-keep-status]")).to_have_text("kept: 2 value(s) written")
        finally:
            tune.stop()
    assert params.read_text(encoding="utf-8") == FILE.replace("fps: 15.0", "fps: 24.5")
    assert (
        new.read_text(encoding="utf-8") == f"{NODE}:\n  ros__parameters:\n    camera.width: 800\n"
    )
    ros_args = ("--params-file", str(params), "--params-file", str(new))
    with demo_nodes(f"{NODE[1:]}:camera", ros_args=ros_args):
        client = ServiceClient(ros_harness, NODE)
        assert client.get("camera.fps", "camera.width") == [24.5, 800]
        client.close()


@pytest.fixture
def read_only(files: tuple[Path, Path]) -> Iterator[TuneServer]:
    params, new = files
    with demo_nodes(f"{NODE[1:]}_ro:camera"):
        tune = TuneServer(nodes=(NODE + "_ro",), keep=((params,), new), read_only=True)
        tune.start()
        try:
            eventually(lambda: tune.graph.schema(NODE + "_ro"))
            yield tune
        finally:
            tune.stop()


def test_a_read_only_page_shows_but_does_not_write(
    read_only: TuneServer, files: tuple[Path, Path]
) -> None:
    preview = api_call(read_only, f"/api/keep?node={NODE}_ro")
    assert preview.ok, preview.body
    assert api_call(read_only, "/api/keep", {"node": NODE + "_ro"}).status == 403
    assert files[0].read_text(encoding="utf-8") == FILE and not files[1].exists()
