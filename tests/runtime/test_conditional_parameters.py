"""Conditional declaration (``when:``) on real nodes, side by side with the hand-written
``if`` it replaces: decided once, from the values the node starts with.

The schema is the golden case tests/cases/conditional.
"""

from __future__ import annotations

import pickle
import types
from typing import Any

import pytest
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.audit.findings import VIOLATION
from genparams.live.graph import Graph
from genparams.runtime import NoneOf, ParameterDeclarationError, ParamSpec
from tests.golden import CASES
from tests.patience import WAIT_S
from tests.runtime.served_node import audit_served, first_read, served
from tests.support import RosHarness, import_file, unique_name

NAMES = ("gain", "filter.window", "filter.kind", "lease_rate", "device")


@pytest.fixture(scope="module")
def module() -> types.ModuleType:
    return import_file(CASES / "conditional" / "expected_params.py")


def by_hand(ros: RosHarness, args: list[str]) -> Node:
    """What such nodes do by hand."""
    node = ros.node(args=args)
    mode = node.declare_parameter("mode", "basic").value
    use_filter = node.declare_parameter("use_filter", False).value
    if mode in ("advanced", "expert"):
        node.declare_parameter("gain", 1.0)
    if use_filter:
        node.declare_parameter("filter.window", 5)
        node.declare_parameter("filter.kind", Parameter.Type.STRING)
    if mode != "expert":  # when: {mode: {not: expert}}
        node.declare_parameter("lease_rate", 1.0)
    if mode not in ("advanced", "expert") and not use_filter:
        node.declare_parameter("device", "/dev/ttyUSB0")
    return node


@pytest.mark.parametrize(
    "args",
    [
        [],
        ["-p", "mode:=expert"],
        ["-p", "use_filter:=true", "-p", "filter.kind:=median", "-p", "gain:=3.0"],
        ["-p", "mode:=advanced", "-p", "lease_rate:=4.0", "-p", "device:=/dev/ttyACM0"],
        ["-p", "lease_rate:=4.0", "-p", "device:=/dev/ttyACM0"],
    ],
)
def test_declared_exactly_when_the_hand_written_node_declares(
    ros: RosHarness, module: types.ModuleType, args: list[str]
) -> None:
    node = ros.node(args=args)
    cfg = module.ConditionalParams.declare(node)
    hand = by_hand(ros, args)
    for name in NAMES:
        assert node.has_parameter(name) == hand.has_parameter(name), name
    values = {
        "gain": cfg.gain,
        "filter.window": cfg.filter.window,
        "filter.kind": cfg.filter.kind,
        "lease_rate": cfg.lease_rate,
        "device": cfg.device,
    }
    for name, value in values.items():
        assert (value is None) == (not node.has_parameter(name)), name
        unset: list[Any] = [0]  # rclpy gives a declared parameter's type as its int value
        if value is not None and hand.get_parameter_types([name]) != unset:
            assert value == hand.get_parameter(name).value


def test_decided_at_start_up(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node()
    cfg = module.ConditionalParams.declare(node)
    client = ros.client(node)
    # The controlling parameter changes later: nothing is declared, as by hand.
    assert client.set(Parameter("use_filter", Parameter.Type.BOOL, True))[0].successful
    assert cfg.use_filter and cfg.filter.window is None
    assert not node.has_parameter("filter.window")
    (refused,) = client.set(Parameter("filter.window", Parameter.Type.INTEGER, 3))
    assert not refused.successful  # not declared: ROS refuses the set
    # The rule reading gain holds while gain is not declared.
    assert client.set(Parameter("limit", Parameter.Type.DOUBLE, 0.5))[0].successful


def test_declared_parameters_are_checked(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=["-p", "mode:=advanced"])
    cfg = module.ConditionalParams.declare(node)
    client = ros.client(node)
    (broken,) = client.set(Parameter("gain", Parameter.Type.DOUBLE, 3.0))
    assert not broken.successful and "rule 'gain_below_limit' broken" in broken.reason
    assert client.set(Parameter("gain", Parameter.Type.DOUBLE, 1.5))[0].successful
    assert cfg.gain == 1.5
    with pytest.raises(ParameterDeclarationError, match=r"filter\.kind: required parameter"):
        module.ConditionalParams.declare(ros.node(args=["-p", "use_filter:=true"]))


def test_defaults_and_remote(ros: RosHarness, module: types.ModuleType) -> None:
    cls = module.ConditionalParams
    assert cls.defaults({"mode": "expert"}).gain == 1.0
    with pytest.raises(ParameterDeclarationError, match="declared only when mode is"):
        cls.defaults({"gain": 1.0})
    assert cls.defaults({"mode": "advanced"}).lease_rate == 1.0
    with pytest.raises(ParameterDeclarationError, match="declared only when mode is not 'expert'"):
        cls.defaults({"mode": "expert", "lease_rate": 2.0})
    target = ros.node(args=["-p", "mode:=advanced"])
    cfg = cls.declare(target)
    remote = cls.remote(ros.node(), target.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)
    snapshot = ros.wait(remote.get())
    assert snapshot == cfg.snapshot()
    assert (snapshot.gain, snapshot.filter.window) == (1.0, None)
    assert (snapshot.lease_rate, snapshot.device) == (1.0, None)


def test_tune_and_audit(module: types.ModuleType) -> None:
    graph = Graph(unique_name("conditional_graph"))
    try:
        with served(module.ConditionalParams, ["-p", "mode:=expert"]) as target:
            assert graph.services_ready(target, WAIT_S)
            read = {p["name"]: p["value"] for p in first_read(graph, target)}
            result = audit_served(graph, target)
    finally:
        graph.close()
    assert read["gain"] == 1.0 and "filter.window" not in read
    assert "lease_rate" not in read and "device" not in read  # mode is expert: neither
    assert target in result.audited
    assert [f.text() for f in result.findings if f.kind == VIOLATION] == []


def test_negated_conditions_in_words_and_across_processes() -> None:
    spec = ParamSpec("port", "string", default="a", when=(("link", NoneOf("sim", "udp", "can")),))
    assert spec.condition_text == "declared only when link is none of 'sim', 'udp' or 'can'"
    assert not spec.declared_with({"link": "udp"}) and spec.declared_with({"link": "serial"})
    copy = pickle.loads(pickle.dumps(spec))  # a record pickles by value
    assert copy == spec and copy.when[0][1] == NoneOf("sim", "udp", "can")
    assert not copy.declared_with({"link": "can"})
