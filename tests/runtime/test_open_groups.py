"""Open groups (``for_each: overrides``) on real nodes, side by side with the hand-written
rclpy code they replace: one group of parameters per key the params file holds under a
namespace, found once when the node starts.

The schema is the golden case tests/cases/open_groups.
"""

from __future__ import annotations

import types
from pathlib import Path
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
from tests.runtime.served_node import audit_served, served
from tests.support import RosHarness, import_file, unique_name

PARAMS = """\
/**:
  ros__parameters:
    sensors:
      front: {topic: /front/scan, rate: 50.0}
      rear: {topic: /rear/scan}
    controllers:
      arm: {gains: {left: {p: 2.0}}}
"""


@pytest.fixture(scope="module")
def module() -> types.ModuleType:
    return import_file(CASES / "open_groups" / "expected_params.py")


def params_file(tmp_path: Path, text: str = PARAMS) -> list[str]:
    path = tmp_path / "params file.yaml"
    path.write_text(text, encoding="utf-8")
    return ["--params-file", str(path)]


def keys_under(node: Node, namespace: str) -> list[str]:
    """What such nodes do by hand: the keys their overrides hold under a namespace."""
    keys: list[str] = []
    for name in node._parameter_overrides:
        parts = name.split(".")
        if len(parts) > 2 and parts[0] == namespace and parts[1] not in keys:
            keys.append(parts[1])
    return keys


def by_hand(ros: RosHarness, args: list[str]) -> Node:
    """The same node written by hand: one group of declarations per key found."""
    node = ros.node(args=args)
    node.declare_parameter("rate", 10.0, ParameterDescriptor(description="[Hz]"))
    node.declare_parameter("joints", ["left", "right"])
    span = FloatingPointRange(from_value=1.0, to_value=200.0, step=0.0)
    for key in keys_under(node, "sensors"):
        node.declare_parameter(
            f"sensors.{key}.topic",
            Parameter.Type.STRING,
            ParameterDescriptor(description="Topic the sensor publishes on."),
        )
        node.declare_parameter(
            f"sensors.{key}.rate",
            30.0,
            ParameterDescriptor(description="[Hz]", floating_point_range=[span]),
        )
        node.declare_parameter(f"sensors.{key}.enabled", True)
    for key in keys_under(node, "controllers"):
        for joint in node.get_parameter("joints").value:
            node.declare_parameter(f"controllers.{key}.gains.{joint}.p", 1.0)
    return node


def test_the_same_parameters_as_the_code_by_hand(
    ros: RosHarness, module: types.ModuleType, tmp_path: Path
) -> None:
    args = params_file(tmp_path)
    node = ros.node(args=args)
    cfg = module.OpenGroupsParams.declare(node)
    hand = by_hand(ros, args)
    names = sorted(node.get_parameters_by_prefix(""))
    assert names == sorted(hand.get_parameters_by_prefix(""))
    assert [n for n in names if n.startswith("sensors.")] == [
        f"sensors.{key}.{field}"
        for key in ("front", "rear")
        for field in ("enabled", "rate", "topic")
    ]
    ours, theirs = ros.client(node), ros.client(hand)
    # joints, a key list of a mapped group, says so in its constraints: the rest is the same.
    compared = [name for name in names if name != "joints"]
    assert ours.describe(*compared) == theirs.describe(*compared)
    assert ours.get(*names) == theirs.get(*names)
    assert list(cfg.sensors) == ["front", "rear"]
    assert (cfg.sensors["front"].rate, cfg.sensors["rear"].rate) == (50.0, 30.0)
    assert cfg.sensors["rear"].topic == "/rear/scan"
    gains = cfg.controllers["arm"].gains
    assert {joint: entry.p for joint, entry in gains.items()} == {"left": 2.0, "right": 1.0}
    assert cfg.to_dict()["sensors"]["front"] == {
        "enabled": True,
        "rate": 50.0,
        "topic": "/front/scan",
    }
    with pytest.raises(TypeError):
        cfg.sensors["side"] = cfg.sensors["front"]


def test_entries_are_checked_and_keys_stay_as_declared(
    ros: RosHarness, module: types.ModuleType, tmp_path: Path
) -> None:
    node = ros.node(args=params_file(tmp_path))
    cfg = module.OpenGroupsParams.declare(node)
    seen: list[tuple[str, Any, Any]] = []
    cfg.on_change(lambda changes: seen.extend((c.name, c.old, c.new) for c in changes))
    client = ros.client(node)
    (out_of_range,) = client.set(Parameter("sensors.rear.rate", Parameter.Type.DOUBLE, 500.0))
    assert not out_of_range.successful
    assert client.set(Parameter("sensors.rear.rate", Parameter.Type.DOUBLE, 20.0))[0].successful
    assert cfg.sensors["rear"].rate == 20.0 and ("sensors.rear.rate", 30.0, 20.0) in seen
    # A key given later is no entry: ROS refuses the set of an undeclared parameter.
    (later,) = client.set(Parameter("sensors.side.topic", Parameter.Type.STRING, "/side"))
    assert not later.successful and not node.has_parameter("sensors.side.topic")
    assert list(cfg.sensors) == ["front", "rear"]
    # A change of another map's key list leaves the open group's entries as they are.
    joints = Parameter("joints", Parameter.Type.STRING_ARRAY, ["left"])
    assert client.set(joints)[0].successful
    assert list(cfg.controllers["arm"].gains) == ["left"]
    assert list(cfg.sensors) == ["front", "rear"] and node.has_parameter("sensors.rear.topic")


def test_bad_keys_and_entries_refuse_to_start_together(
    ros: RosHarness, module: types.ModuleType, tmp_path: Path
) -> None:
    text = """\
/**:
  ros__parameters:
    sensors:
      "front left": {topic: /x}
      rear: {rate: 5.0}
      side: {topic: /s, rate: 0.5}
"""
    node = ros.node(args=params_file(tmp_path, text))
    with pytest.raises(ParameterDeclarationError) as caught:
        module.OpenGroupsParams.declare(node)
    text = str(caught.value)
    assert "sensors: key 'front left' given in the overrides cannot name an entry" in text
    assert "sensors.rear.topic: required parameter is not set" in text
    assert (
        "sensors.side.rate: override rejected: must be within [1.0, 200.0] (range), got 0.5" in text
    )
    assert not node.has_parameter("sensors.rear.rate")


def test_no_overrides_no_entries(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node()
    cfg = module.OpenGroupsParams.declare(node)
    assert (dict(cfg.sensors), dict(cfg.controllers)) == ({}, {})
    assert not node.get_parameters_by_prefix("sensors")


def test_defaults_take_the_keys_given(module: types.ModuleType) -> None:
    built = module.OpenGroupsParams.defaults({"sensors": {"imu": {"topic": "/imu"}}})
    assert list(built.sensors) == ["imu"] and built.sensors["imu"].rate == 30.0
    with pytest.raises(ParameterDeclarationError, match=r"sensors\.gps\.topic"):
        module.OpenGroupsParams.defaults({"sensors": {"gps": {"rate": 5.0}}})


def test_remote_reads_the_entries_declared(
    ros: RosHarness, module: types.ModuleType, tmp_path: Path
) -> None:
    target = ros.node(args=params_file(tmp_path))
    cfg = module.OpenGroupsParams.declare(target)
    remote = module.OpenGroupsParams.remote(ros.node(), target.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)
    snapshot = ros.wait(remote.get())
    assert snapshot == cfg.snapshot() and list(snapshot.sensors) == ["front", "rear"]
    assert ros.wait(remote.set({"sensors.front.rate": 60.0})) is None
    assert cfg.sensors["front"].rate == 60.0


def test_audit_checks_each_entry(module: types.ModuleType, tmp_path: Path) -> None:
    graph = Graph(unique_name("open_groups_graph"))
    try:
        with served(module.OpenGroupsParams, params_file(tmp_path)) as target:
            assert graph.services_ready(target, WAIT_S)
            result = audit_served(graph, target)
    finally:
        graph.close()
    assert target in result.audited
    assert [f.text() for f in result.findings if f.kind == VIOLATION] == []
    drifted = {f.parameter for f in result.findings}
    # each audited against its entry's default (30.0, and 1.0 in the map inside the group)
    assert drifted == {"sensors.front.rate", "controllers.arm.gains.left.p"}
