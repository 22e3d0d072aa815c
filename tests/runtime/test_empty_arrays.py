"""An empty array set through the services keeps the parameter's declared type.

`ros2 param set /node waypoints "[]"` sends a BOOL_ARRAY (an empty YAML list has no
element type); rclpy would refuse it for any other array parameter.
"""

from __future__ import annotations

import types
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

from tests.support import RosHarness, load_generated

ROUTE = """\
genparams: 1
name: route
parameters:
  waypoints: {type: int_array, default: [1, 2]}
  weights: {type: double_array, default: [0.5]}
  labels: {type: string_array, default: [a]}
  flags: {type: bool_array, default: [true]}
  blob: {type: byte_array, default: [1]}
  stops: {type: int_array, default: [3], validators: [not_empty]}
  legacy: {type: int_array, default: [4], aliases: [old_legacy]}
  count: {type: int, default: 1}
"""

OTHER = """\
genparams: 1
name: other
parameters:
  tags: {type: string_array, default: [x], aliases: [old_tags]}
"""


@pytest.fixture
def route(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "route.yaml"
    schema.write_text(ROUTE)
    return load_generated(schema, tmp_path)


@pytest.fixture
def other(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "other.yaml"
    schema.write_text(OTHER)
    return load_generated(schema, tmp_path)


def empty_as(name: str, ros_type: Parameter.Type) -> Parameter:
    """An empty array of ``ros_type``, as a client such as `ros2 param set` sends it."""
    return Parameter(name, ros_type, [])


@pytest.mark.parametrize(
    ("name", "expected_type", "expected"),
    [
        ("waypoints", Parameter.Type.INTEGER_ARRAY, ()),
        ("weights", Parameter.Type.DOUBLE_ARRAY, ()),
        ("labels", Parameter.Type.STRING_ARRAY, ()),
        ("flags", Parameter.Type.BOOL_ARRAY, ()),
        ("blob", Parameter.Type.BYTE_ARRAY, b""),
    ],
)
@pytest.mark.parametrize("sent_type", [Parameter.Type.BOOL_ARRAY, Parameter.Type.BYTE_ARRAY])
def test_empty_array_of_another_type_is_accepted_as_the_declared_type(
    ros: RosHarness,
    route: types.ModuleType,
    name: str,
    expected_type: Parameter.Type,
    expected: object,
    sent_type: Parameter.Type,
) -> None:
    node = ros.node()
    cfg = route.RouteParams.declare(node)
    (result,) = ros.client(node).set(empty_as(name, sent_type))
    assert result.successful, result.reason
    assert getattr(cfg, name) == expected
    assert node.get_parameter(name).type_ == expected_type
    assert list(ros.client(node).get(name)[0]) == []


def test_empty_array_still_meets_the_validators(ros: RosHarness, route: types.ModuleType) -> None:
    node = ros.node()
    cfg = route.RouteParams.declare(node)
    (result,) = ros.client(node).set(empty_as("stops", Parameter.Type.BOOL_ARRAY))
    assert not result.successful
    assert "stops" in result.reason and "empty" in result.reason
    assert cfg.stops == (3,)


def test_non_empty_array_of_another_type_is_still_refused(
    ros: RosHarness, route: types.ModuleType
) -> None:
    node = ros.node()
    cfg = route.RouteParams.declare(node)
    (result,) = ros.client(node).set(Parameter("waypoints", Parameter.Type.BOOL_ARRAY, [True]))
    assert not result.successful
    assert cfg.waypoints == (1, 2)
    assert node.get_parameter("waypoints").type_ == Parameter.Type.INTEGER_ARRAY


def test_empty_array_for_a_scalar_is_still_refused(
    ros: RosHarness, route: types.ModuleType
) -> None:
    node = ros.node()
    cfg = route.RouteParams.declare(node)
    (result,) = ros.client(node).set(empty_as("count", Parameter.Type.BOOL_ARRAY))
    assert not result.successful
    assert cfg.count == 1


def test_empty_array_under_an_old_name_reaches_both_names(
    ros: RosHarness, route: types.ModuleType
) -> None:
    node = ros.node()
    cfg = route.RouteParams.declare(node)
    (result,) = ros.client(node).set(empty_as("old_legacy", Parameter.Type.BOOL_ARRAY))
    assert result.successful, result.reason
    assert cfg.legacy == ()
    assert ros.client(node).get("legacy", "old_legacy") == [[], []]


def test_two_classes_with_rewrites_set_each_parameter_once(
    ros: RosHarness, route: types.ModuleType, other: types.ModuleType
) -> None:
    node = ros.node()
    route.RouteParams.declare(node, prefix="route")
    cfg = other.OtherParams.declare(node, prefix="other")
    seen: list[list[str]] = []
    node.add_post_set_parameters_callback(lambda ps: seen.append([p.name for p in ps]))
    (result,) = ros.client(node).set(Parameter("other.tags", value=["y"]))
    assert result.successful, result.reason
    assert cfg.tags == ("y",)
    assert [sorted(names) for names in seen] == [["other.old_tags", "other.tags"]]
