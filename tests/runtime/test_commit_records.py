"""Change records reach subscribers, including ones that subscribe after earlier sets."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from rclpy.parameter import Parameter

from genparams.runtime import Changes
from tests.support import ROOT, RosHarness, load_generated

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"


def test_late_subscriber_sees_old_and_new_values(ros: RosHarness, tmp_path: Path) -> None:
    module = load_generated(SCHEMA, tmp_path)
    node = ros.node(args=["-p", "serial:=ABCD1234"])
    cfg = module.CameraDriverParams.declare(node)
    node.set_parameters([Parameter("camera.fps", value=10.0)])  # nobody listening yet
    seen: list[Changes[Any]] = []
    unsubscribe = cfg.on_change(seen.append)
    node.set_parameters([Parameter("camera.fps", value=20.0)])
    assert len(seen) == 1
    (change,) = seen[0]
    assert (change.name, change.old, change.new) == ("camera.fps", 10.0, 20.0)
    assert seen[0].before.camera.fps == 10.0 and seen[0].after.camera.fps == 20.0
    unsubscribe()
    node.set_parameters([Parameter("camera.fps", value=30.0)])
    assert len(seen) == 1 and cfg.camera.fps == 30.0 and cfg.snapshot().camera.fps == 30.0
