"""Sets nested in callbacks are committed once each, in the node's order."""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import pytest
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime import Changes
from tests.runtime.schemas import MOTION, SAFETY, generate
from tests.support import RosHarness

DOUBLE = Parameter.Type.DOUBLE
STRING = Parameter.Type.STRING


@pytest.fixture
def classes(tmp_path: Path) -> tuple[types.ModuleType, types.ModuleType]:
    return generate(tmp_path, MOTION, "motion"), generate(tmp_path, SAFETY, "safety")


def node_value(node: Node, name: str) -> Any:
    return node.get_parameter(name).value


@pytest.mark.parametrize("motion_first", [True, False])
def test_subscriber_of_one_class_sets_a_parameter_of_another_during_an_atomic_set(
    ros: RosHarness, classes: tuple[types.ModuleType, types.ModuleType], motion_first: bool
) -> None:
    node = ros.node()
    motion_mod, safety_mod = classes
    if motion_first:
        motion = motion_mod.MotionParams.declare(node, prefix="base")
        safety = safety_mod.SafetyParams.declare(node, prefix="safety")
    else:
        safety = safety_mod.SafetyParams.declare(node, prefix="safety")
        motion = motion_mod.MotionParams.declare(node, prefix="base")
    seen: list[float] = []
    safety.on_change(lambda ch: node.set_parameters([Parameter("base.max_speed", DOUBLE, 0.5)]))
    motion.on_change(lambda ch: seen.append(ch.after.max_speed))
    result = node.set_parameters_atomically(
        [Parameter("safety.mode", STRING, "slow"), Parameter("base.max_speed", DOUBLE, 2.5)]
    )
    assert result.successful
    assert node_value(node, "base.max_speed") == 0.5
    assert motion.max_speed == 0.5 and motion.snapshot().max_speed == 0.5
    assert safety.mode == "slow"
    assert seen == [2.5, 0.5]  # the node's order: the atomic set, then the nested one


def test_post_set_callback_that_clamps_by_setting_again(
    ros: RosHarness, classes: tuple[types.ModuleType, types.ModuleType]
) -> None:
    node = ros.node()
    cfg = classes[0].MotionParams.declare(node)

    def clamp(parameters: list[Parameter]) -> None:
        for parameter in parameters:
            if parameter.name == "max_speed" and parameter.value > 5.0:
                node.set_parameters([Parameter("max_speed", DOUBLE, 5.0)])

    node.add_post_set_parameters_callback(clamp)
    assert node.set_parameters([Parameter("max_speed", DOUBLE, 8.0)])[0].successful
    assert node_value(node, "max_speed") == 5.0
    assert cfg.max_speed == 5.0 and cfg.snapshot().max_speed == 5.0


def test_rules_of_another_class_see_committed_values_during_a_nested_set(
    ros: RosHarness, classes: tuple[types.ModuleType, types.ModuleType]
) -> None:
    node = ros.node()
    safety = classes[1].SafetyParams.declare(node, prefix="safety")
    motion = classes[0].MotionParams.declare(node, prefix="base")
    outcomes: list[bool] = []
    # min_speed 4.0 is fine only once the atomic set raised max_speed to 6.0.
    safety.on_change(
        lambda ch: outcomes.append(
            node.set_parameters([Parameter("base.min_speed", DOUBLE, 4.0)])[0].successful
        )
    )
    result = node.set_parameters_atomically(
        [Parameter("safety.mode", STRING, "slow"), Parameter("base.max_speed", DOUBLE, 6.0)]
    )
    assert result.successful and outcomes == [True]
    assert (motion.min_speed, motion.max_speed) == (4.0, 6.0)
    assert node_value(node, "base.min_speed") == 4.0


def test_set_from_an_on_set_callback_is_validated_before_the_outer_one(
    ros: RosHarness, classes: tuple[types.ModuleType, types.ModuleType]
) -> None:
    node = ros.node()
    cfg = classes[0].MotionParams.declare(node)
    nested: list[bool] = []

    def raise_max_first(parameters: list[Parameter]) -> SetParametersResult:
        if any(p.name == "min_speed" for p in parameters) and not nested:
            nested.append(node.set_parameters([Parameter("max_speed", DOUBLE, 9.0)])[0].successful)
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(raise_max_first)
    # 7.0 > max_speed 2.0 at the start; the nested set raises max_speed first.
    assert node.set_parameters([Parameter("min_speed", DOUBLE, 7.0)])[0].successful
    assert nested == [True]
    assert (cfg.min_speed, cfg.max_speed) == (7.0, 9.0)
    assert (node_value(node, "min_speed"), node_value(node, "max_speed")) == (7.0, 9.0)


def test_on_change_setting_its_own_class_is_delivered_in_order(
    ros: RosHarness, classes: tuple[types.ModuleType, types.ModuleType]
) -> None:
    node = ros.node()
    cfg = classes[0].MotionParams.declare(node)
    log: list[tuple[str, float, float]] = []

    def follow(changes: Changes[Any]) -> None:
        for change in changes:
            log.append((change.name, change.old, change.new))
        if "max_speed" in changes and changes.after.max_speed > 3.0:
            node.set_parameters([Parameter("max_speed", DOUBLE, 3.0)])

    cfg.on_change(follow)
    node.set_parameters([Parameter("max_speed", DOUBLE, 4.0)])
    assert log == [("max_speed", 2.0, 4.0), ("max_speed", 4.0, 3.0)]
    assert cfg.max_speed == 3.0 == node_value(node, "max_speed")


def test_nested_set_through_the_parameter_service(
    ros: RosHarness, classes: tuple[types.ModuleType, types.ModuleType]
) -> None:
    node = ros.node()
    motion = classes[0].MotionParams.declare(node, prefix="base")
    safety = classes[1].SafetyParams.declare(node, prefix="safety")
    safety.on_change(lambda ch: node.set_parameters([Parameter("base.max_speed", DOUBLE, 0.5)]))
    client = ros.client(node)
    assert client.set_atomically(
        Parameter("safety.mode", STRING, "stop"), Parameter("base.max_speed", DOUBLE, 2.5)
    ).successful
    assert client.get("base.max_speed") == [0.5]
    assert motion.max_speed == 0.5
