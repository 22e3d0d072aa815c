"""The generated example module on a real node, seen through the parameter services."""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import pytest
from rcl_interfaces.msg import SetParametersResult
from rclpy.parameter import Parameter

from genparams.runtime import Changes, ParameterDeclarationError
from tests.support import ROOT, RosHarness, load_generated

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"
SERIAL = ["-p", "serial:=ABCD1234"]


@pytest.fixture
def module(tmp_path: Path) -> types.ModuleType:
    return load_generated(SCHEMA, tmp_path)


def test_declared_values_match_node_and_service(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=SERIAL)
    cfg = module.CameraDriverParams.declare(node)
    client = ros.client(node)
    names = ["camera.fps", "camera.width", "camera.encoding", "topics", "serial", "robot_name"]
    through_service = client.get(*names)
    through_node = [node.get_parameter(n).value for n in names]
    through_cfg = [
        cfg.camera.fps,
        cfg.camera.width,
        cfg.camera.encoding,
        list(cfg.topics),
        cfg.serial,
        cfg.robot_name,
    ]
    assert (
        through_service
        == through_cfg
        == [v if not isinstance(v, tuple) else list(v) for v in through_node]
    )
    assert through_cfg == [
        30.0,
        640,
        "rgb8",
        ["/sensor/data", "/robot/status"],
        "ABCD1234",
        "my_robot",
    ]


def test_descriptor_carries_range_description_and_constraints(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=SERIAL)
    module.CameraDriverParams.declare(node)
    fps, encoding, robot = ros.client(node).describe("camera.fps", "camera.encoding", "robot_name")
    assert fps.type == Parameter.Type.DOUBLE.value
    assert fps.description == "Frame rate. [Hz]"
    assert (
        fps.floating_point_range[0].from_value,
        fps.floating_point_range[0].to_value,
        fps.floating_point_range[0].step,
    ) == (1.0, 120.0, 0.5)
    assert encoding.additional_constraints == "one of 'rgb8', 'mono8', 'bgr8'"
    assert robot.read_only is True


def _reason(result: SetParametersResult) -> str:
    assert not result.successful
    return str(result.reason)


def test_sets_through_service(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=SERIAL)
    cfg = module.CameraDriverParams.declare(node)
    client = ros.client(node)
    (ok,) = client.set(Parameter("camera.fps", value=60.0))
    assert ok.successful and cfg.camera.fps == 60.0
    assert _reason(client.set(Parameter("camera.fps", value=500.0))[0]) == (
        "camera.fps: must be within [1.0, 120.0] (range), got 500.0"
    )
    assert _reason(client.set(Parameter("camera.fps", value=5))[0]) == (
        "camera.fps: expected double, got integer 5 (ROS does not convert: write 5.0)"
    )
    assert "read-only" in _reason(client.set(Parameter("robot_name", value="x"))[0])
    reason = _reason(client.set(Parameter("camera.encoding", value="yuv"))[0])
    assert reason == "camera.encoding: must be one of ['rgb8', 'mono8', 'bgr8'] (one_of), got 'yuv'"
    reason = _reason(client.set(Parameter("control.pid.kp", value=-1.0))[0])
    assert reason == "control.pid.kp: must be >= 0.0 (ge), got -1.0"
    assert cfg.camera.fps == 60.0 and cfg.camera.encoding == "rgb8" and cfg.control.pid.kp == 1.0
    assert node.get_parameter("camera.encoding").value == "rgb8"


def test_atomic_set_with_one_bad_value_applies_nothing(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=SERIAL)
    cfg = module.CameraDriverParams.declare(node)
    seen: list[Changes[object]] = []
    cfg.on_change(seen.append)
    result = ros.client(node).set_atomically(
        Parameter("camera.width", value=1280), Parameter("control.pid.ki", value=-0.5)
    )
    assert "control.pid.ki: must be >= 0.0" in _reason(result)
    assert cfg.camera.width == 640 and node.get_parameter("camera.width").value == 640
    assert seen == []
    result = ros.client(node).set_atomically(
        Parameter("camera.width", value=1280), Parameter("camera.height", value=720)
    )
    assert result.successful
    assert (cfg.camera.width, cfg.camera.height) == (1280, 720)
    assert len(seen) == 1 and seen[0].names == {"camera.width", "camera.height"}


def test_veto_by_another_callback_leaves_cfg_unchanged(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=SERIAL)
    armed = False
    # Added before declaring, so rclpy (which runs the callback added last first) runs it
    # after genparams' own check accepted the value: a commit made on-set would show.
    node.add_on_set_parameters_callback(
        lambda params: SetParametersResult(successful=not armed, reason="vetoed by safety")
    )
    cfg = module.CameraDriverParams.declare(node)
    armed = True
    (result,) = ros.client(node).set(Parameter("camera.fps", value=10.0))
    assert _reason(result) == "vetoed by safety"
    assert cfg.camera.fps == 30.0 and cfg.snapshot().camera.fps == 30.0


def test_on_change_reports_old_and_new_and_ignores_foreign_parameters(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=SERIAL)
    node.declare_parameter("unrelated", 1)
    cfg = module.CameraDriverParams.declare(node)
    seen: list[Changes[Any]] = []
    cfg.on_change(seen.append)
    node.set_parameters([Parameter("unrelated", value=2)])
    node.set_parameters([Parameter("use_sim_time", value=True)])
    assert seen == []
    before = cfg.snapshot()
    node.set_parameters([Parameter("camera.fps", value=15.0)])
    (changes,) = seen
    assert [(c.name, c.old, c.new) for c in changes] == [("camera.fps", 30.0, 15.0)]
    assert changes.before is before and changes.after.camera.fps == 15.0
    assert before.camera.fps == 30.0  # snapshots never move


def test_bad_overrides_are_all_reported_and_nothing_declared(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(
        args=["-p", "camera.fps:=500.0", "-p", "camera.width:=12.5", "-p", "topics:=[a, a]"]
    )
    with pytest.raises(ParameterDeclarationError) as caught:
        module.CameraDriverParams.declare(node)
    problems = caught.value.problems
    assert [problem.key for problem in problems] == [
        "camera.fps",
        "camera.width",
        "serial",
        "topics",
    ]
    assert tuple(map(str, problems)) == (
        "camera.fps: override rejected: must be within [1.0, 120.0] (range), got 500.0",
        "camera.width: override has the wrong type: expected integer, got double 12.5",
        "serial: required parameter is not set "
        "(pass -p serial:=<string> or set it in a params file)",
        "topics: override rejected: must not repeat items (unique), 'a' appears twice",
    )
    assert not node.has_parameter("camera.encoding")


def test_int_override_for_double_is_named_like_ros_would(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=[*SERIAL, "-p", "camera.fps:=30"])
    with pytest.raises(ParameterDeclarationError, match=r"write 30\.0"):
        module.CameraDriverParams.declare(node)


def test_automatically_declared_overrides_keep_descriptor(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(
        args=[*SERIAL, "-p", "robot_name:=rover", "-p", "camera.fps:=60.0"],
        automatically_declare_parameters_from_overrides=True,
    )
    cfg = module.CameraDriverParams.declare(node)
    assert (cfg.robot_name, cfg.camera.fps) == ("rover", 60.0)
    client = ros.client(node)
    robot, fps = client.describe("robot_name", "camera.fps")
    assert robot.read_only and fps.floating_point_range[0].to_value == 120.0
    assert _reason(client.set(Parameter("robot_name", value="x"))[0]) == (
        "robot_name: read-only: set it when the node starts (-p, a params file or launch)"
    )
    assert _reason(client.set(Parameter("camera.fps", value=999.0))[0]) == (
        "camera.fps: must be within [1.0, 120.0] (range), got 999.0"
    )


def test_empty_array_default_keeps_declared_type(ros: RosHarness, tmp_path: Path) -> None:
    schema = tmp_path / "empty.yaml"
    schema.write_text(
        "genparams: 1\nname: empty_lists\nparameters:\n"
        "  names: {type: string_array, default: []}\n"
        "  gains: {type: double_array, default: []}\n"
    )
    module = load_generated(schema, tmp_path)
    node = ros.node()
    cfg = module.EmptyListsParams.declare(node)
    assert node.get_parameter("names").type_ == Parameter.Type.STRING_ARRAY
    assert node.get_parameter("gains").type_ == Parameter.Type.DOUBLE_ARRAY
    (result,) = ros.client(node).set(Parameter("names", value=["a", "b"]))
    assert result.successful and cfg.names == ("a", "b")


def test_prefix_joins_with_one_dot(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=["-p", "front.serial:=ABCD1234"])
    cfg = module.CameraDriverParams.declare(node, prefix="front")
    assert node.get_parameter("front.camera.fps").value == 30.0
    node.set_parameters([Parameter("front.camera.fps", value=12.0)])
    assert cfg.camera.fps == 12.0
    with pytest.raises(ValueError, match="invalid parameter prefix"):
        module.CameraDriverParams.declare(node, prefix="bad..prefix")


def test_defaults_without_ros(module: types.ModuleType) -> None:
    with pytest.raises(ParameterDeclarationError, match="serial: required"):
        module.CameraDriverParams.defaults()
    snap = module.CameraDriverParams.defaults({"serial": "ABCD1234"})
    assert snap.camera.fps == 30.0 and snap.topics == ("/sensor/data", "/robot/status")
    with pytest.raises(AttributeError, match="read-only"):
        snap.camera.fps = 1.0


def test_empty_list_in_params_file_is_an_empty_array(
    ros: RosHarness, module: types.ModuleType, tmp_path: Path
) -> None:
    params = tmp_path / "params.yaml"
    params.write_text("/**:\n  ros__parameters:\n    serial: ABCD1234\n    topics: []\n")
    node = ros.node(args=["--params-file", str(params)])
    with pytest.raises(ParameterDeclarationError) as caught:
        module.CameraDriverParams.declare(node)
    assert tuple(map(str, caught.value.problems)) == (
        "topics: override rejected: must not be empty (not_empty)",
    )
