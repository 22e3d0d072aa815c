"""check-params --node fails when no section of the file reaches the node: a check of
nothing must not pass, and it names the sections it saw."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from tests.support import ROOT

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"
FILE = """\
/robot/multi_cam:
  ros__parameters:
    camera:
      fps: 1000.0
      fsp: 30.0
/robot/lidar:
  ros__parameters:
    rate: 10
"""


def _run(tmp_path: Path, capsys: pytest.CaptureFixture[str], node: str) -> tuple[int, str]:
    params = tmp_path / "params.yaml"
    params.write_text(FILE, encoding="utf-8")
    code = main(["check-params", str(SCHEMA), str(params), "--node", node])
    return code, capsys.readouterr().out


def test_a_node_no_section_reaches_fails_and_names_what_it_saw(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out = _run(tmp_path, capsys, "/multi_cam")
    assert code == 1
    assert out.splitlines() == [
        f"{tmp_path / 'params.yaml'}:1:1: /multi_cam: no section of the file names this node, "
        "so nothing checks it; sections seen: /robot/multi_cam, /robot/lidar "
        "(did you mean /robot/multi_cam?)",
        f"{tmp_path / 'params.yaml'}:1:1: serial: required parameter is not set for /multi_cam "
        "(it has no default: add serial: <string>)",
    ]


def test_a_misspelt_node_gets_the_closest_section(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out = _run(tmp_path, capsys, "/robot/multi_cma")
    assert code == 1
    assert "(did you mean /robot/multi_cam?)" in out


def test_a_node_a_section_reaches_is_checked(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out = _run(tmp_path, capsys, "/robot/multi_cam")
    assert code == 1
    assert "no section" not in out
    assert "camera.fsp: unknown parameter" in out


def test_a_pattern_section_reaches_every_node(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    params = tmp_path / "params.yaml"
    params.write_text("/**:\n  ros__parameters:\n    serial: ABCD1234\n", encoding="utf-8")
    assert main(["check-params", str(SCHEMA), str(params), "--node", "/multi_cam"]) == 0
    assert capsys.readouterr().out == ""


def test_a_node_only_the_all_nodes_section_reaches_fails(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    params = tmp_path / "params.yaml"
    params.write_text("/**:\n  ros__parameters:\n    use_sim_time: true\n" + FILE, encoding="utf-8")
    assert main(["check-params", str(SCHEMA), str(params), "--node", "/multi_cam"]) == 1
    out = capsys.readouterr().out
    assert "/multi_cam: no section of the file names this node" in out
    assert (
        "sections seen: /**, /robot/multi_cam, /robot/lidar (did you mean /robot/multi_cam?)" in out
    )
