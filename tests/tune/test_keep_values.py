"""Keep tuned values: a node tuned over its services, its values kept with
``genparams audit --params-file F --write``, the node started again from the files holds
the same values; the commented file changes only on the lines of the changed values."""

from __future__ import annotations

import difflib
from pathlib import Path

from rclpy.parameter import Parameter

from tests.support import RosHarness, ServiceClient
from tests.tune.support import demo_nodes, run_audit, unique

NODE = f"/{unique('keep_cam')}"
FILE = f"""\
# Camera of the bench robot.
{NODE}:
  ros__parameters:
    camera:
      fps: 15.0        # Hz: tuned on the bench
      encoding: rgb8
    control:
      pid: {{kp: 1.0, ki: 0.1}}   # from the last tuning
"""
NAMES = ("camera.fps", "control.pid.kp", "camera.width", "camera.encoding")


def test_a_tuned_value_survives_a_restart(ros_harness: RosHarness, tmp_path: Path) -> None:
    params, kept = tmp_path / "camera.yaml", tmp_path / "kept.yaml"
    params.write_text(FILE, encoding="utf-8")
    with demo_nodes(f"{NODE[1:]}:camera", ros_args=("--params-file", str(params))):
        client = ServiceClient(ros_harness, NODE)
        tuned = [Parameter("camera.fps", value=20.0), Parameter("control.pid.kp", value=2.5),
                 Parameter("camera.width", value=800)]  # fmt: skip
        assert all(r.successful for r in client.set(*tuned))
        done = run_audit("--params-file", str(params), "--write", "--new-values", str(kept), NODE)
        client.close()
    assert done.returncode == 0, done.stdout + done.stderr
    assert [line for line in done.stderr.splitlines() if line.startswith("kept:")] == [
        f"kept: {params}:5:12: {NODE}: camera.fps: 15.0 -> 20.0",
        f"kept: {kept} (added): {NODE}: camera.width: 640 -> 800",
        f"kept: {params}:8:17: {NODE}: control.pid.kp: 1.0 -> 2.5",
    ]
    diff = [
        line
        for line in difflib.unified_diff(
            FILE.splitlines(), params.read_text(encoding="utf-8").splitlines(), lineterm="", n=0
        )
        if line[:1] in "+-" and not line.startswith(("+++", "---"))
    ]
    assert diff == [
        "-      fps: 15.0        # Hz: tuned on the bench",
        "+      fps: 20.0        # Hz: tuned on the bench",
        "-      pid: {kp: 1.0, ki: 0.1}   # from the last tuning",
        "+      pid: {kp: 2.5, ki: 0.1}   # from the last tuning",
    ]
    ros_args = ("--params-file", str(params), "--params-file", str(kept))
    with demo_nodes(f"{NODE[1:]}:camera", ros_args=ros_args):
        client = ServiceClient(ros_harness, NODE)
        assert client.get(*NAMES) == [20.0, 2.5, 800, "rgb8"]
        client.close()
