"""The committed example stays in sync with its schema, and the demo runs."""

from __future__ import annotations

import os
import signal
import subprocess
import sys

from genparams.cli import main
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
    # Its own session, so a timeout also stops the camera node the demo started.
    demo = subprocess.Popen(
        [sys.executable, str(EXAMPLE / "demo.py")],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=dict(os.environ),
        start_new_session=True,
    )
    try:
        stdout, stderr = demo.communicate(timeout=120)
    finally:
        if demo.poll() is None:
            os.killpg(demo.pid, signal.SIGKILL)
            demo.wait()
    assert demo.returncode == 0, stderr
    result = subprocess.CompletedProcess(demo.args, demo.returncode, stdout, stderr)
    out = result.stdout
    assert "get serial -> 'CAM00042'" in out
    assert "set camera.fps = 15.0 -> accepted" in out
    assert "set camera.encoding = 'yuv422' -> rejected: camera.encoding: must be one of" in out
    assert "set robot_name = 'renamed' -> rejected: Trying to set a read-only parameter" in out
    assert "final: {'camera.fps': 15.0, 'camera.encoding': 'rgb8', 'serial': 'CAM00042'}" in out
    assert "cannot declare camera_driver parameters (3 problems)" in out
    assert "(exit code 1)" in out
