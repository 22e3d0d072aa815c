"""The committed example stays in sync with its schema, and the demo runs."""

from __future__ import annotations

import os
import sys

from genparams.cli import main
from tests.patience import run_patiently
from tests.support import ROOT

EXAMPLE = ROOT / "examples" / "camera_node"


def test_committed_module_is_up_to_date() -> None:
    code = main(
        [
            "generate",
            str(EXAMPLE / "camera_driver.yaml"),
            "-o",
            str(EXAMPLE / "camera_node" / "camera_driver_params.py"),
            "--check",
        ]
    )
    assert code == 0, "run `make demo` (or genparams generate) and commit the result"


def test_demo_tunes_a_node_in_another_process() -> None:
    # Alone it takes about 4 s; the budget is in idle-machine seconds (tests/patience.py),
    # so a loaded machine gets longer and a hang still fails.
    result = run_patiently(
        [sys.executable, str(EXAMPLE / "demo.py")], budget_s=120, env=dict(os.environ)
    )
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "get serial -> 'CAM00042'" in out
    assert "set camera.fps = 15.0 -> accepted" in out
    assert "set camera.encoding = 'yuv422' -> rejected: camera.encoding: must be one of" in out
    assert "set robot_name = 'renamed' -> rejected: robot_name: read-only: set it when" in out
    assert "final: {'camera.fps': 15.0, 'camera.encoding': 'rgb8', 'serial': 'CAM00042'}" in out
    assert "cannot declare camera_driver parameters (3 problems)" in out
    assert "(exit code 1)" in out
