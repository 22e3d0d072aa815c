"""Per-item parameters and mapped-group parameters declared by type only (``optional:
true`` on a ``for_each`` parameter or in a mapped group), on real nodes, next to rclpy's
own ``for name in names: node.declare_parameter(name, Parameter.Type.X)``."""

from __future__ import annotations

import types
from pathlib import Path

import pytest
from rcl_interfaces.msg import SetParametersResult
from rclpy.exceptions import ParameterUninitializedException
from rclpy.node import Node
from rclpy.parameter import Parameter

from tests.rclpy_import.declared import declared, without_item_rule
from tests.support import RosHarness, load_generated

SCHEMA = """\
genparams: 1
name: waypoints
parameters:
  goals: {type: string_array, default: [home, dock]}
  "*": {for_each: goals, type: double_array, optional: true, description: Joint positions.}
  arms: {type: string_array, default: [left]}
  gains:
    for_each: arms
    p: {type: double, optional: true, range: {min: 0.0, max: 10.0}}
    i: {type: double, default: 0.5}
"""


@pytest.fixture
def module(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "waypoints.yaml"
    schema.write_text(SCHEMA, encoding="utf-8")
    return load_generated(schema, tmp_path)


def by_hand(ros: RosHarness, args: list[str] | None = None) -> Node:
    node = ros.node(args=args)
    goals = node.declare_parameter("goals", ["home", "dock"]).value
    for goal in goals:
        node.declare_parameter(goal, Parameter.Type.DOUBLE_ARRAY)
    return node


def test_each_item_is_declared_by_type_only_as_rclpy_declares_it(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    cfg = module.WaypointsParams.declare(node)
    hand = by_hand(ros)
    ours = declared(node)
    theirs = declared(hand)
    for name in ("home", "dock"):
        (descriptor, value), (hand_descriptor, hand_value) = ours[name], theirs[name]
        assert value is None and hand_value is None
        assert descriptor[:2] == hand_descriptor[:2]  # name, type: DOUBLE_ARRAY
        assert without_item_rule(descriptor)[4:6] == hand_descriptor[4:6]  # not dynamic
        with pytest.raises(ParameterUninitializedException):
            node.get_parameter(name)
    assert cfg["home"] is None and cfg.gains["left"].p is None
    assert cfg.gains["left"].i == 0.5


def test_an_override_gives_an_item_its_value(ros: RosHarness, module: types.ModuleType) -> None:
    args = ["-p", "dock:=[1.0, 2.0]", "-p", "gains.left.p:=3.0"]
    node = ros.node(args=args)
    cfg = module.WaypointsParams.declare(node)
    assert cfg["dock"] == (1.0, 2.0) and cfg["home"] is None
    assert cfg.gains["left"].p == 3.0
    assert declared(node)["dock"][1] == declared(by_hand(ros, args))["dock"][1]


def test_a_set_gives_a_value_of_the_declared_type(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    params = module.WaypointsParams.declare(node)
    assert node.set_parameters([Parameter("home", value=[0.5])])[0].successful
    refused = node.set_parameters([Parameter("gains.left.p", value=11.0)])[0]
    assert not refused.successful and "gains.left.p" in refused.reason
    assert params["home"] == (0.5,)
    assert params.gains["left"].p is None


def test_a_new_key_declares_its_entries_by_type_only(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    params = module.WaypointsParams.declare(node)
    result = node.set_parameters(
        [Parameter("goals", value=["home", "pick"]), Parameter("arms", value=["left", "right"])]
    )
    assert all(r.successful for r in result)
    names = set(node.list_parameters([], 0).names)
    assert {"pick", "gains.right.p", "gains.right.i"} <= names and "dock" not in names
    assert node.describe_parameter("pick").type == Parameter.Type.DOUBLE_ARRAY.value
    assert node.get_parameter_or("pick").type_ == Parameter.Type.NOT_SET
    assert params["pick"] is None
    assert params.gains["right"].p is None
    assert node.set_parameters([Parameter("pick", value=[1.0])])[0].successful
    assert params["pick"] == (1.0,)


def test_a_refused_change_of_keys_declares_nothing(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    params = module.WaypointsParams.declare(node)

    def refuse_new_entries(parameters: list[Parameter]) -> SetParametersResult:
        new = any(p.name == "pick" for p in parameters)
        return SetParametersResult(successful=not new, reason="no new goals")

    node.add_on_set_parameters_callback(refuse_new_entries)
    result = node.set_parameters([Parameter("goals", value=["home", "pick"])])[0]
    assert not result.successful
    names = set(node.list_parameters([], 0).names)
    assert "pick" not in names and {"home", "dock"} <= names
    assert params.goals == ("home", "dock")


def test_entries_declared_by_type_are_undeclared_again_when_the_removal_is_refused(
    ros: RosHarness, module: types.ModuleType
) -> None:
    """The entries declared by type only go in a round before the change that removes the
    old keys; a callback refusing that change alone leaves none of them behind."""
    node = ros.node()
    params = module.WaypointsParams.declare(node)

    def refuse_a_removal_alone(parameters: list[Parameter]) -> SetParametersResult:
        names = {p.name for p in parameters}
        alone = "dock" in names and "pick" not in names
        return SetParametersResult(successful=not alone, reason="dock stays")

    node.add_on_set_parameters_callback(refuse_a_removal_alone)
    node.set_parameters([Parameter("goals", value=["home", "pick"])])
    names = set(node.list_parameters([], 0).names)
    assert "pick" not in names and {"home", "dock"} <= names
    assert params["dock"] is None
