"""Names that are no Python identifiers on real nodes: `twist-linear-x`, `input_shape/height`
and parameters named `type`, side by side with the rclpy code that declares them by hand.

The ROS names keep their `-` and `/`; the attributes spell them with `_`. The schema is
the golden case tests/cases/ros_names.
"""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import pytest
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter

from tests.golden import CASES
from tests.support import RosHarness, import_file

PARAMS = """\
/**:
  ros__parameters:
    walk_button:
      type: action
      axis_mappings:
        twist-linear-x: {axis: 4, scale: 0.8}
        twist-angular-z.axis: 3
    type.type.mode: slow
    input_shape/height: 720
    max-speed: 2.5
    wheel-names: [left-front, right-rear]
    wheels:
      right-rear: {max-rpm: 250}
    gain-per-axis:
      left-front: 0.5
    buttons:
      deadman-switch: {button-id: 4, type: hold}
      turbo: {button-id: 5}
"""

FIXED = {
    "walk_button.type": "action",
    "walk_button.topic_name": "cmd_vel",
    "walk_button.axis_mappings.twist-linear-x.axis": 4,
    "walk_button.axis_mappings.twist-linear-x.scale": 0.8,
    "walk_button.axis_mappings.twist-linear-x.offset": 0.0,
    "walk_button.axis_mappings.twist-angular-z.axis": 3,
    "walk_button.axis_mappings.twist-angular-z.scale": 1.5,
    "type.type.mode": "slow",
    "input_shape/height": 720,
    "max-speed": 2.5,
    "from-": False,
    "wheel-names": ["left-front", "right-rear"],
    "wheels.left-front.max-rpm": 100,
    "wheels.right-rear.max-rpm": 250,
    "gain-per-axis.left-front": 0.5,
    "gain-per-axis.right-rear": 1.0,
    "buttons.deadman-switch.button-id": 4,
    "buttons.deadman-switch.type": "hold",
    "buttons.turbo.button-id": 5,
    "buttons.turbo.type": "press",
}


@pytest.fixture(scope="module")
def module() -> types.ModuleType:
    return import_file(CASES / "ros_names" / "expected_params.py")


def params_args(tmp_path: Path) -> list[str]:
    path = tmp_path / "names.yaml"
    path.write_text(PARAMS, encoding="utf-8")
    return ["--params-file", str(path)]


def by_hand(ros: RosHarness, args: list[str]) -> Node:
    """The same parameters declared with rclpy: the names are plain strings to it."""
    node = ros.node(args=args)
    for name, default in FIXED.items():
        if name.startswith(("wheels.", "gain-per-axis.", "buttons.")):
            continue
        descriptor = ParameterDescriptor()
        if name == "input_shape/height":
            descriptor = ParameterDescriptor(
                integer_range=[IntegerRange(from_value=1, to_value=4096, step=0)]
            )
        node.declare_parameter(name, default, descriptor)
    for name in ("wheels.left-front.max-rpm", "wheels.right-rear.max-rpm"):
        node.declare_parameter(name, 100)
    for name in ("gain-per-axis.left-front", "gain-per-axis.right-rear"):
        node.declare_parameter(name, 1.0)
    for key in ("deadman-switch", "turbo"):
        node.declare_parameter(f"buttons.{key}.button-id", 0)
        node.declare_parameter(f"buttons.{key}.type", "press")
    return node


def test_the_params_file_reaches_every_name_and_attribute(
    ros: RosHarness, module: types.ModuleType, tmp_path: Path
) -> None:
    args = params_args(tmp_path)
    node = ros.node(args=args)
    cfg = module.RosNamesParams.declare(node)
    hand = by_hand(ros, args)
    names = sorted(node.get_parameters_by_prefix(""))
    assert names == sorted([*FIXED, "use_sim_time", "start_type_description_service"])
    assert names == sorted(hand.get_parameters_by_prefix(""))
    ours, theirs = ros.client(node), ros.client(hand)
    assert ours.get(*FIXED) == theirs.get(*FIXED)
    assert {name: node.get_parameter(name).value for name in FIXED} == FIXED
    mappings = cfg.walk_button.axis_mappings
    assert (mappings.twist_linear_x.axis, mappings.twist_linear_x.scale) == (4, 0.8)
    assert (mappings.twist_angular_z.axis, mappings.twist_angular_z.scale) == (3, 1.5)
    assert (cfg.walk_button.type, cfg.type.type.mode) == ("action", "slow")
    assert (cfg.input_shape_height, cfg.max_speed, cfg.from_) == (720, 2.5, False)
    assert {key: entry.max_rpm for key, entry in cfg.wheels.items()} == {
        "left-front": 100,
        "right-rear": 250,
    }
    assert dict(cfg.gain_per_axis) == {"left-front": 0.5, "right-rear": 1.0}
    assert {key: (e.button_id, e.type) for key, e in cfg.buttons.items()} == {
        "deadman-switch": (4, "hold"),
        "turbo": (5, "press"),
    }
    as_dict = cfg.to_dict()
    assert as_dict["walk_button"]["axis_mappings"]["twist-linear-x"]["axis"] == 4
    assert as_dict["walk_button"]["type"] == "action"
    assert as_dict["type"] == {"type": {"mode": "slow"}}
    assert (as_dict["input_shape/height"], as_dict["max-speed"], as_dict["from-"]) == (
        720,
        2.5,
        False,
    )
    assert as_dict["wheels"]["right-rear"] == {"max-rpm": 250}
    assert as_dict["buttons"]["deadman-switch"] == {"button-id": 4, "type": "hold"}
    rebuilt = module.RosNamesParams.defaults(as_dict)
    assert rebuilt.to_dict() == as_dict and rebuilt == cfg.snapshot()
    dotted = module.RosNamesParams.defaults({"walk_button.axis_mappings.twist-linear-x.axis": 9})
    assert dotted.walk_button.axis_mappings.twist_linear_x.axis == 9


def test_sets_over_the_services_are_checked_and_reach_the_attributes(
    ros: RosHarness, module: types.ModuleType, tmp_path: Path
) -> None:
    node = ros.node(args=params_args(tmp_path))
    cfg = module.RosNamesParams.declare(node)
    seen: list[tuple[str, Any, Any]] = []
    cfg.on_change(lambda changes: seen.extend((c.name, c.old, c.new) for c in changes))
    before = cfg.snapshot()
    client = ros.client(node)
    (wrong,) = client.set(Parameter("walk_button.type", Parameter.Type.STRING, "jump"))
    assert not wrong.successful and "walk_button.type" in wrong.reason
    (low,) = client.set(Parameter("input_shape/height", Parameter.Type.INTEGER, 0))
    assert not low.successful
    changes = [
        Parameter("walk_button.axis_mappings.twist-linear-x.scale", Parameter.Type.DOUBLE, 0.25),
        Parameter("walk_button.type", Parameter.Type.STRING, "topic"),
        Parameter("input_shape/height", Parameter.Type.INTEGER, 1080),
        Parameter("wheels.right-rear.max-rpm", Parameter.Type.INTEGER, 300),
        Parameter("buttons.turbo.type", Parameter.Type.STRING, "hold"),
    ]
    assert all(result.successful for result in client.set(*changes))
    assert cfg.walk_button.axis_mappings.twist_linear_x.scale == 0.25
    assert (cfg.walk_button.type, cfg.input_shape_height) == ("topic", 1080)
    assert (cfg.wheels["right-rear"].max_rpm, cfg.buttons["turbo"].type) == (300, "hold")
    assert before.walk_button.axis_mappings.twist_linear_x.scale == 0.8
    assert sorted(name for name, _old, _new in seen) == sorted(p.name for p in changes)
    assert ("input_shape/height", 720, 1080) in seen
    (described,) = client.describe("input_shape/height")
    assert described.name == "input_shape/height"
    assert (described.integer_range[0].from_value, described.integer_range[0].to_value) == (
        1,
        4096,
    )
    (typed,) = client.describe("walk_button.type")
    assert typed.name == "walk_button.type" and "topic" in typed.additional_constraints


def test_without_overrides_the_defaults_hold(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node()
    cfg = module.RosNamesParams.declare(node)
    assert node.get_parameter("walk_button.axis_mappings.twist-linear-x.axis").value == 1
    assert cfg.walk_button.type == "topic" and cfg.type.type.mode == "fast"
    assert list(cfg.wheels) == ["left-front", "right-front"] and list(cfg.buttons) == []
    assert cfg.to_dict() == module.RosNamesParams.defaults().to_dict()


def test_remote_reads_and_sets_the_names_under_a_dashed_prefix(
    ros: RosHarness, module: types.ModuleType
) -> None:
    target = ros.node()
    cfg = module.RosNamesParams.declare(target, prefix="pad-1")
    assert target.get_parameter("pad-1.walk_button.axis_mappings.twist-linear-x.axis").value == 1
    remote = module.RosNamesParams.remote(ros.node(), target.get_fully_qualified_name(), "pad-1")
    assert remote.wait_for_services(timeout_sec=10.0)
    snapshot = ros.wait(remote.get())
    assert snapshot == cfg.snapshot()
    assert (snapshot.walk_button.type, snapshot.input_shape_height) == ("topic", 480)
    values = {"walk_button.axis_mappings.twist-angular-z.axis": 5, "input_shape/height": 600}
    assert ros.wait(remote.set(values)) is None
    assert (cfg.walk_button.axis_mappings.twist_angular_z.axis, cfg.input_shape_height) == (5, 600)
    assert list(ros.wait(remote.get()).wheels) == ["left-front", "right-front"]
