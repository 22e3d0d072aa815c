"""What reaches ``cfg`` and ``on_change``, and when.

A set to the value a parameter already holds changes nothing and notifies no
one (equal, not identical: every set carries a fresh object). A set another
on-set callback vetoes must leave ``cfg`` as it was: genparams checks after every
other on-set callback and commits only once the node has stored the values.
"""

from __future__ import annotations

import types
from pathlib import Path

import pytest
from rcl_interfaces.msg import SetParametersResult
from rclpy.parameter import Parameter

from genparams.runtime import Changes, DetachedSnapshotError
from tests.support import ROOT, RosHarness, load_generated

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"
SERIAL = ["-p", "serial:=ABCD1234"]


@pytest.fixture
def module(tmp_path: Path) -> types.ModuleType:
    return load_generated(SCHEMA, tmp_path)


def test_setting_the_current_value_notifies_no_one(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=SERIAL)
    cfg = module.CameraDriverParams.declare(node)
    seen: list[Changes[object]] = []
    cfg.on_change(seen.append)
    before = cfg.snapshot()
    client = ros.client(node)
    same = [
        Parameter("camera.fps", value=30.0),
        Parameter("camera.width", value=640),
        Parameter("camera.encoding", value="rgb8"),
        Parameter("topics", value=["/sensor/data", "/robot/status"]),
    ]
    assert all(result.successful for result in client.set(*same))
    assert client.set_atomically(*same).successful
    node.set_parameters(same)
    assert seen == []
    assert cfg.snapshot() is before  # nothing was rebuilt either


def test_a_mixed_set_reports_only_what_changed(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=SERIAL)
    cfg = module.CameraDriverParams.declare(node)
    seen: list[Changes[object]] = []
    cfg.on_change(seen.append)
    result = ros.client(node).set_atomically(
        Parameter("camera.fps", value=30.0), Parameter("camera.width", value=800)
    )
    assert result.successful
    (changes,) = seen
    assert [(c.name, c.old, c.new) for c in changes] == [("camera.width", 640, 800)]
    assert changes.names == {"camera.width"}
    ros.client(node).set(Parameter("camera.width", value=800))
    assert len(seen) == 1


def test_a_veto_after_genparams_accepted_leaves_cfg_unchanged(
    ros: RosHarness, module: types.ModuleType
) -> None:
    """genparams checks last and commits only once the node stored the values: a veto
    by another on-set callback leaves cfg, snapshots and subscribers untouched."""
    node = ros.node(args=SERIAL)
    calls: list[str] = []

    def veto(parameters: list[Parameter]) -> SetParametersResult:
        if not calls:  # armed only after declaring: declarations pass through it too
            return SetParametersResult(successful=True)
        calls.append("veto")
        return SetParametersResult(successful=False, reason="vetoed by safety")

    node.add_on_set_parameters_callback(veto)
    cfg = module.CameraDriverParams.declare(node)
    seen: list[Changes[object]] = []
    cfg.on_change(seen.append)
    calls.append("armed")
    (result,) = ros.client(node).set(Parameter("camera.fps", value=10.0))
    assert (result.successful, result.reason) == (False, "vetoed by safety")
    assert calls == ["armed", "veto"]
    assert cfg.camera.fps == 30.0 and cfg.snapshot().camera.fps == 30.0
    assert node.get_parameter("camera.fps").value == 30.0
    assert seen == []
    # The next accepted set commits its own values, not the vetoed ones.
    node.remove_on_set_parameters_callback(veto)
    (result,) = ros.client(node).set(Parameter("camera.width", value=800))
    assert result.successful
    assert (cfg.camera.fps, cfg.camera.width) == (30.0, 800)
    assert [(c.name, c.new) for c in seen[0]] == [("camera.width", 800)]


def test_genparams_checks_after_every_other_callback(
    ros: RosHarness, module: types.ModuleType
) -> None:
    """A callback added after declare still runs before genparams' check, so the check
    judges the request last, against the node's current state."""
    node = ros.node(args=SERIAL)
    module.CameraDriverParams.declare(node)
    seen: list[str] = []

    def observer(parameters: list[Parameter]) -> SetParametersResult:
        seen.extend(p.name for p in parameters)
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(observer)
    (result,) = ros.client(node).set(Parameter("control.pid.kp", value=-1.0))
    assert result.reason == "control.pid.kp: must be >= 0.0 (ge), got -1.0"
    assert seen == ["control.pid.kp"]
    assert node.get_parameter("control.pid.kp").value == 1.0


def test_a_subscriber_that_raises_is_logged_and_the_others_still_hear(
    ros: RosHarness, module: types.ModuleType, capfd: pytest.CaptureFixture[str]
) -> None:
    node = ros.node(args=SERIAL)
    cfg = module.CameraDriverParams.declare(node)
    seen: list[Changes[object]] = []

    def broken(changes: Changes[object]) -> None:
        raise RuntimeError("subscriber bug")

    cfg.on_change(broken)
    cfg.on_change(seen.append)
    (result,) = ros.client(node).set(Parameter("camera.fps", value=12.0))
    assert result.successful
    assert cfg.camera.fps == 12.0 and [(c.name, c.new) for c in seen[0]] == [("camera.fps", 12.0)]
    logged = capfd.readouterr().err
    assert "on_change callback" in logged and "RuntimeError: subscriber bug" in logged, logged


def test_snapshots_taken_after_a_set_are_still_detached(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=SERIAL)
    cfg = module.CameraDriverParams.declare(node)
    ros.client(node).set_atomically(
        Parameter("camera.fps", value=12.0), Parameter("camera.width", value=800)
    )
    ros.client(node).set(Parameter("camera.height", value=600))
    frozen = cfg.snapshot()
    assert (frozen.camera.fps, frozen.camera.width, frozen.camera.height) == (12.0, 800, 600)
    assert frozen.snapshot() is frozen
    with pytest.raises(DetachedSnapshotError):
        frozen.on_change(print)


def test_every_problem_of_a_request_is_named(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=SERIAL)
    cfg = module.CameraDriverParams.declare(node)
    result = ros.client(node).set_atomically(
        Parameter("camera.fps", value=12.0),
        Parameter("control.pid.kp", value=-1.0),
        Parameter("camera.encoding", value="yuv"),
    )
    assert result.reason == (
        "control.pid.kp: must be >= 0.0 (ge), got -1.0; "
        "camera.encoding: must be one of ['rgb8', 'mono8', 'bgr8'] (one_of), got 'yuv'"
    )
    assert (cfg.camera.fps, cfg.control.pid.kp) == (30.0, 1.0)
