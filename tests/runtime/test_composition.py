"""Several generated classes on one node, each under its own prefix, each told only its changes."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from rclpy.parameter import Parameter

from genparams.runtime import Changes, ParameterDeclarationError
from tests.support import ROOT, RosHarness, load_generated

CAMERA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"
MOTION = """\
genparams: 1
name: motion
parameters:
  min_speed: {type: double, default: 0.5}
  max_speed: {type: double, default: 2.0}
rules:
  - {name: speed_order, check: min_speed <= max_speed}
"""


class Recorder:
    def __init__(self) -> None:
        self.calls: list[list[tuple[str, Any, Any]]] = []

    def __call__(self, changes: Changes[Any]) -> None:
        self.calls.append([(c.name, c.old, c.new) for c in changes])


def test_each_class_owns_its_prefix_and_hears_only_its_changes(
    ros: RosHarness, tmp_path: Path
) -> None:
    camera_module = load_generated(CAMERA, tmp_path)
    schema = tmp_path / "motion.yaml"
    schema.write_text(MOTION)
    motion_module = load_generated(schema, tmp_path)
    node = ros.node(args=["-p", "front.serial:=FRONT001", "-p", "rear.serial:=REAR0002"])
    node.declare_parameter("unrelated", 1)
    front = camera_module.CameraDriverParams.declare(node, prefix="front")
    rear = camera_module.CameraDriverParams.declare(node, prefix="rear")
    motion = motion_module.MotionParams.declare(node, prefix="drive.motion")
    heard = {"front": Recorder(), "rear": Recorder(), "motion": Recorder()}
    front.on_change(heard["front"])
    rear.on_change(heard["rear"])
    motion.on_change(heard["motion"])
    client = ros.client(node)

    def calls() -> dict[str, list[list[tuple[str, Any, Any]]]]:
        out = {name: recorder.calls for name, recorder in heard.items()}
        for recorder in heard.values():
            recorder.calls = []
        return out

    assert (front.serial, rear.serial) == ("FRONT001", "REAR0002")

    assert client.set(Parameter("front.camera.fps", value=15.0))[0].successful
    assert calls() == {"front": [[("camera.fps", 30.0, 15.0)]], "rear": [], "motion": []}

    assert client.set(Parameter("rear.camera.width", value=800))[0].successful
    assert calls() == {"front": [], "rear": [[("camera.width", 640, 800)]], "motion": []}

    # Parameters nobody owns wake nobody.
    node.set_parameters([Parameter("use_sim_time", value=True)])
    assert client.set(Parameter("unrelated", value=2))[0].successful
    assert calls() == {"front": [], "rear": [], "motion": []}

    # One atomic set across classes: each hears its own part, once.
    result = client.set_atomically(
        Parameter("front.camera.fps", value=20.0),
        Parameter("drive.motion.min_speed", value=1.0),
        Parameter("unrelated", value=3),
    )
    assert result.successful
    assert calls() == {
        "front": [[("camera.fps", 15.0, 20.0)]],
        "rear": [],
        "motion": [[("min_speed", 0.5, 1.0)]],
    }

    # A rule of one class vetoes the whole atomic set: the other class commits nothing.
    result = client.set_atomically(
        Parameter("front.camera.fps", value=25.0),
        Parameter("drive.motion.min_speed", value=9.0),
    )
    assert not result.successful
    assert result.reason == (
        "rule 'speed_order' broken: min_speed <= max_speed is false for "
        "drive.motion.min_speed=9.0, drive.motion.max_speed=2.0"
    )
    # And a validator of one class vetoes a valid change of another.
    result = client.set_atomically(
        Parameter("drive.motion.max_speed", value=5.0),
        Parameter("rear.camera.encoding", value="yuv"),
    )
    assert not result.successful and "rear.camera.encoding: must be one of" in result.reason
    assert calls() == {"front": [], "rear": [], "motion": []}
    assert (front.camera.fps, motion.min_speed, motion.max_speed) == (20.0, 1.0, 2.0)
    assert node.get_parameter("front.camera.fps").value == 20.0

    # Each view holds its own values; snapshots are of their own class.
    assert (front.camera.width, rear.camera.width) == (640, 800)
    assert type(motion.snapshot()) is motion_module.MotionParams
    assert rear.snapshot().camera.fps == 30.0


def test_a_prefix_can_be_declared_once(ros: RosHarness, tmp_path: Path) -> None:
    schema = tmp_path / "motion.yaml"
    schema.write_text(MOTION)
    module = load_generated(schema, tmp_path)
    node = ros.node()
    module.MotionParams.declare(node, prefix="left")
    with pytest.raises(ParameterDeclarationError) as caught:
        module.MotionParams.declare(node, prefix="left")
    assert tuple(map(str, caught.value.problems)) == (
        "MotionParams is already declared at prefix 'left': declare a class once per prefix "
        "and share the view it returns",
    )
    right = module.MotionParams.declare(node, prefix="right")
    assert right.max_speed == 2.0
