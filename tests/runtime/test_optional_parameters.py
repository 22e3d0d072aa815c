"""Optional parameters (``optional: true``) on real nodes, side by side with rclpy's own
``declare_parameter(name, Parameter.Type.X)``: descriptor, services, sets, typed view.

The schema is the golden case tests/cases/optional.
"""

from __future__ import annotations

import types
from collections.abc import Iterator
from typing import Any

import pytest
from rclpy.exceptions import ParameterUninitializedException
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.audit.findings import VIOLATION
from genparams.live.graph import Graph
from genparams.runtime import ParameterDeclarationError
from tests.golden import CASES
from tests.patience import WAIT_S
from tests.runtime.served_node import audit_served, first_read, served
from tests.support import RosHarness, import_file, unique_name

OPTIONAL = ("frame_id", "timeout", "retries", "verbose", "topics", "mask", "limits.speed")
TYPES = {
    "frame_id": Parameter.Type.STRING,
    "timeout": Parameter.Type.DOUBLE,
    "retries": Parameter.Type.INTEGER,
    "verbose": Parameter.Type.BOOL,
    "topics": Parameter.Type.STRING_ARRAY,
    "mask": Parameter.Type.BYTE_ARRAY,
    "limits.speed": Parameter.Type.DOUBLE,
}


@pytest.fixture(scope="module")
def module() -> types.ModuleType:
    return import_file(CASES / "optional" / "expected_params.py")


def by_hand(ros: RosHarness) -> Node:
    """The same parameters declared the way hand-written rclpy nodes declare them."""
    node = ros.node()
    for name in OPTIONAL:
        node.declare_parameter(name, TYPES[name])
    return node


def test_declared_as_rclpy_declares_a_type_only_parameter(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    cfg = module.OptionalParams.declare(node)
    hand = by_hand(ros)
    for name in OPTIONAL:
        ours, theirs = node.describe_parameter(name), hand.describe_parameter(name)
        assert (ours.type, ours.dynamic_typing) == (theirs.type, theirs.dynamic_typing)
        assert ours.type == TYPES[name].value and not ours.dynamic_typing
        # rclpy gives a declared parameter's type as its int value, whatever its annotation
        unset: list[Any] = [0]
        assert node.get_parameter_types([name]) == hand.get_parameter_types([name]) == unset
        for either in (node, hand):
            with pytest.raises(ParameterUninitializedException):
                either.get_parameter(name)
            assert either.get_parameter_or(name).type_ == Parameter.Type.NOT_SET
    assert cfg.frame_id is None and cfg.limits.speed is None and cfg.topics is None
    assert cfg.to_dict()["limits"] == {"max_speed": 2.0, "speed": None}
    # What `ros2 param get` sees: the get service answers nothing for a parameter not set.
    for target in (node, hand):
        assert ros.client(target).get("frame_id") == []


def test_a_set_of_the_declared_type_gives_a_value_once_and_for_good(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    cfg = module.OptionalParams.declare(node)
    hand = by_hand(ros)
    seen: list[tuple[str, Any, Any]] = []
    cfg.on_change(lambda changes: seen.extend((c.name, c.old, c.new) for c in changes))
    for target in (node, hand):
        client = ros.client(target)
        wrong = client.set(Parameter("frame_id", Parameter.Type.INTEGER, 3))[0]
        unset = client.set(Parameter("frame_id", Parameter.Type.NOT_SET))[0]
        right = client.set(Parameter("frame_id", Parameter.Type.STRING, "map"))[0]
        again = client.set(Parameter("frame_id", Parameter.Type.NOT_SET))[0]
        assert (wrong.successful, unset.successful, right.successful) == (False, False, True)
        if target is node:  # the class words rclpy's refusal of the type
            assert wrong.reason == "frame_id: expected string, got integer 3"
        else:
            assert wrong.reason.startswith("Wrong parameter type")
        assert not again.successful  # set once, it cannot go back to "not set"
        if target is node:
            assert again.reason == "frame_id: cannot be undeclared"
        assert client.get("frame_id") == ["map"]
    assert cfg.frame_id == "map"
    assert seen == [("frame_id", None, "map")]


def test_checks_apply_once_a_value_is_given(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node()
    cfg = module.OptionalParams.declare(node)
    client = ros.client(node)
    (too_long,) = client.set(Parameter("timeout", Parameter.Type.DOUBLE, 90.0))
    (negative,) = client.set(Parameter("retries", Parameter.Type.INTEGER, -1))
    assert not too_long.successful and not negative.successful
    assert "must be >= 0" in negative.reason
    # The rule reads limits.speed: not checked while it is not set, checked once it is.
    (fast,) = client.set(Parameter("limits.speed", Parameter.Type.DOUBLE, 3.0))
    assert not fast.successful and "rule 'speed_below_max' broken" in fast.reason
    (slow,) = client.set(Parameter("limits.speed", Parameter.Type.DOUBLE, 1.0))
    assert slow.successful and cfg.limits.speed == 1.0
    assert (cfg.timeout, cfg.retries) == (None, None)


def test_overrides_give_values_and_are_checked(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=["-p", "retries:=3", "-p", "frame_id:=odom", "-p", "verbose:=true"])
    cfg = module.OptionalParams.declare(node)
    assert (cfg.retries, cfg.frame_id, cfg.verbose, cfg.timeout) == (3, "odom", True, None)
    assert node.get_parameter("retries").value == 3
    bad = ros.node(args=["-p", "retries:=-2", "-p", "timeout:=5"])
    with pytest.raises(ParameterDeclarationError) as caught:
        module.OptionalParams.declare(bad)
    text = str(caught.value)
    assert "retries: override rejected: must be >= 0" in text
    assert "timeout: override has the wrong type" in text


def test_defaults_without_ros(module: types.ModuleType) -> None:
    cls = module.OptionalParams
    assert cls.defaults().frame_id is None
    given = cls.defaults({"frame_id": "map", "limits": {"speed": 1}})
    assert (given.frame_id, given.limits.speed, given.timeout) == ("map", 1.0, None)
    with pytest.raises(ParameterDeclarationError, match="rule 'speed_below_max' broken"):
        cls.defaults({"limits.speed": 5.0})


def test_remote_reads_not_set_as_none(ros: RosHarness, module: types.ModuleType) -> None:
    target = ros.node(args=["-p", "retries:=3"])
    cfg = module.OptionalParams.declare(target)
    remote = module.OptionalParams.remote(ros.node(), target.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)
    snapshot = ros.wait(remote.get())
    assert snapshot == cfg.snapshot()
    assert (snapshot.retries, snapshot.frame_id, snapshot.limits.speed) == (3, None, None)
    assert ros.wait(remote.set({"frame_id": "map", "limits.speed": 1})) is None
    assert ros.wait(remote.get()).frame_id == "map" == cfg.frame_id


@pytest.fixture
def target(module: types.ModuleType) -> Iterator[str]:
    with served(module.OptionalParams, ["-p", "retries:=3"]) as name:
        yield name


def test_tune_and_audit_read_not_set(target: str) -> None:
    graph = Graph(unique_name("optional_graph"))
    try:
        assert graph.services_ready(target, WAIT_S)
        read = {p["name"]: p for p in first_read(graph, target)}
        assert (read["frame_id"]["type"], read["frame_id"]["value"]) == ("unset", None)
        assert (read["retries"]["type"], read["retries"]["value"]) == ("int", 3)
        result = audit_served(graph, target)
    finally:
        graph.close()
    assert target in result.audited
    assert [f for f in result.findings if f.kind == VIOLATION] == []
