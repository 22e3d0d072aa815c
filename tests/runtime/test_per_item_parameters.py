"""Per-item parameters (a leaf with ``for_each``) on real nodes, side by side with the
hand-written rclpy loop they replace: one parameter per item, named by the item itself.

The schema is the golden case tests/cases/per_item.
"""

from __future__ import annotations

import types
from typing import Any

import pytest
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.audit.findings import VIOLATION
from genparams.live.graph import Graph
from genparams.runtime import ParameterDeclarationError
from tests.golden import CASES
from tests.patience import WAIT_S
from tests.runtime.served_node import audit_served, first_read, served
from tests.support import RosHarness, import_file, unique_name


@pytest.fixture(scope="module")
def module() -> types.ModuleType:
    return import_file(CASES / "per_item" / "expected_params.py")


def by_hand(ros: RosHarness, args: list[str]) -> Node:
    """What such nodes do by hand: read the list, then declare one parameter per item."""
    node = ros.node(args=args)
    joints = node.declare_parameter("joints", ["shoulder", "elbow"]).value
    span = FloatingPointRange(from_value=-3.14, to_value=3.14, step=0.0)
    for joint in joints:
        node.declare_parameter(
            f"offsets.{joint}", 0.0, ParameterDescriptor(floating_point_range=[span])
        )
    for sensor in node.declare_parameter("sensors", ["imu"]).value:
        node.declare_parameter(sensor, "")
    return node


def test_the_same_parameters_as_the_loop_by_hand(ros: RosHarness, module: types.ModuleType) -> None:
    args = ["-p", "joints:=[hip, knee]", "-p", "offsets.knee:=0.5", "-p", "sensors:=[imu, gps]"]
    node = ros.node(args=args)
    cfg = module.PerItemParams.declare(node)
    hand = by_hand(ros, args)
    names = ["offsets.hip", "offsets.knee", "imu", "gps"]
    for name in names:
        ours, theirs = node.describe_parameter(name), hand.describe_parameter(name)
        assert (ours.type, list(ours.floating_point_range)) == (
            theirs.type,
            list(theirs.floating_point_range),
        )
        assert node.get_parameter(name).value == hand.get_parameter(name).value
    assert dict(cfg.offsets) == {"hip": 0.0, "knee": 0.5}
    assert (cfg["imu"], cfg["gps"], cfg.limits["hip"]) == ("", "", (-1.0, 1.0))
    assert cfg.to_dict()["offsets"] == {"hip": 0.0, "knee": 0.5}
    assert {"imu": "", "gps": ""}.items() <= cfg.to_dict().items()


def test_items_come_and_go_with_the_list(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node()
    cfg = module.PerItemParams.declare(node)
    seen: list[tuple[str, Any, Any]] = []
    cfg.on_change(lambda changes: seen.extend((c.name, c.old, c.new) for c in changes))
    client = ros.client(node)
    (out_of_range,) = client.set(Parameter("offsets.elbow", Parameter.Type.DOUBLE, 9.0))
    assert not out_of_range.successful
    assert client.set(Parameter("offsets.elbow", Parameter.Type.DOUBLE, 0.25))[0].successful
    assert cfg.offsets["elbow"] == 0.25
    keys = Parameter("joints", Parameter.Type.STRING_ARRAY, ["elbow", "wrist"])
    assert client.set(keys)[0].successful
    assert dict(cfg.offsets) == {"elbow": 0.25, "wrist": 0.0}
    assert node.has_parameter("offsets.wrist") and not node.has_parameter("offsets.shoulder")
    assert ("offsets.wrist", None, 0.0) in seen and ("offsets.shoulder", 0.0, None) in seen
    # An item may not take a name that is already a parameter beside its entries.
    clash = Parameter("sensors", Parameter.Type.STRING_ARRAY, ["joints"])
    (refused,) = client.set(clash)
    assert not refused.successful and "already a name in the top level" in refused.reason


def test_overrides_of_items_are_checked(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=["-p", "offsets.shoulder:=5.0", "-p", "imu:=3"])
    with pytest.raises(ParameterDeclarationError) as caught:
        module.PerItemParams.declare(node)
    text = str(caught.value)
    assert (
        "offsets.shoulder: override rejected: must be within [-3.14, 3.14] (range), got 5.0" in text
    )
    assert "imu: override has the wrong type" in text


def test_defaults_and_remote(ros: RosHarness, module: types.ModuleType) -> None:
    cls = module.PerItemParams
    built = cls.defaults({"joints": ["a"], "offsets": {"a": 1}, "sensors": ["lidar"]})
    assert (dict(built.offsets), built["lidar"]) == ({"a": 1.0}, "")
    target = ros.node(args=["-p", "offsets.elbow:=0.5"])
    cfg = cls.declare(target)
    remote = cls.remote(ros.node(), target.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)
    snapshot = ros.wait(remote.get())
    assert snapshot == cfg.snapshot() and snapshot.offsets["elbow"] == 0.5
    assert ros.wait(remote.set({"offsets.shoulder": 0.125, "imu": "/imu"})) is None
    assert (cfg.offsets["shoulder"], cfg["imu"]) == (0.125, "/imu")


def test_tune_and_audit_name_each_item(module: types.ModuleType) -> None:
    graph = Graph(unique_name("per_item_graph"))
    try:
        with served(module.PerItemParams, ["-p", "offsets.elbow:=0.5"]) as target:
            assert graph.services_ready(target, WAIT_S)
            read = {p["name"]: p["value"] for p in first_read(graph, target)}
            result = audit_served(graph, target)
    finally:
        graph.close()
    assert (read["offsets.elbow"], read["imu"], read["limits.shoulder"]) == (0.5, "", [-1.0, 1.0])
    assert target in result.audited
    assert [f.text() for f in result.findings if f.kind == VIOLATION] == []
    drifted = {f.parameter for f in result.findings if f.parameter.startswith("offsets")}
    assert drifted == {"offsets.elbow"}  # audited against the item's default
