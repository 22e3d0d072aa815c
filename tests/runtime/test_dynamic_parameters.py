"""Parameters of type ``any`` on real nodes, side by side with rclpy's own
``declare_parameter(name, value, ParameterDescriptor(dynamic_typing=True))``.

The schema is the golden case tests/cases/dynamic.
"""

from __future__ import annotations

import types
from typing import Any

import pytest
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.audit.findings import DRIFT_DEFAULT, VIOLATION
from genparams.live.graph import Graph
from genparams.runtime import ParameterDeclarationError
from tests.golden import CASES
from tests.patience import WAIT_S
from tests.runtime.served_node import audit_served, first_read, served
from tests.support import RosHarness, import_file, unique_name

ARG = ["-p", "plugin.arg:=[a, b]"]


@pytest.fixture(scope="module")
def module() -> types.ModuleType:
    return import_file(CASES / "dynamic" / "expected_params.py")


def by_hand(ros: RosHarness) -> Node:
    node = ros.node()
    dynamic = ParameterDescriptor(dynamic_typing=True)
    node.declare_parameter("threshold", 5, dynamic)
    node.declare_parameter("extra", None, ParameterDescriptor(dynamic_typing=True))
    return node


def test_declared_as_rclpy_declares_a_dynamically_typed_parameter(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=ARG)
    cfg = module.DynamicParams.declare(node)
    hand = by_hand(ros)
    for name in ("threshold", "extra"):
        ours, theirs = node.describe_parameter(name), hand.describe_parameter(name)
        assert (ours.type, ours.dynamic_typing) == (theirs.type, theirs.dynamic_typing)
        assert ours.dynamic_typing
        assert node.get_parameter_types([name]) == hand.get_parameter_types([name])
        # Dynamically typed and not set: get_parameter answers NOT_SET, it does not raise.
        assert node.get_parameter(name).value == hand.get_parameter(name).value
    assert node.describe_parameter("rate").dynamic_typing is False
    assert (cfg.threshold, cfg.label, cfg.weights, cfg.extra) == (5, "none", (1.0, 0.5), None)
    assert cfg.plugin.arg == ("a", "b")
    assert node.get_parameter_types(["plugin.arg", "weights"]) == [
        Parameter.Type.STRING_ARRAY.value,
        Parameter.Type.DOUBLE_ARRAY.value,
    ]


def test_a_set_may_change_the_type(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=ARG)
    cfg = module.DynamicParams.declare(node)
    hand = by_hand(ros)
    seen: list[tuple[str, Any, Any]] = []
    cfg.on_change(lambda changes: seen.extend((c.name, c.old, c.new) for c in changes))
    for target in (node, hand):
        client = ros.client(target)
        assert client.set(Parameter("threshold", Parameter.Type.DOUBLE, 0.5))[0].successful
        assert target.describe_parameter("threshold").type == Parameter.Type.DOUBLE.value
        assert client.set(Parameter("extra", Parameter.Type.STRING_ARRAY, ["x"]))[0].successful
        assert client.get("threshold", "extra") == [0.5, ["x"]]
    assert (cfg.threshold, cfg.extra) == (0.5, ("x",))
    # 1 then 1.0 are equal in Python, but a change of type is a change.
    ros.client(node).set(Parameter("threshold", Parameter.Type.INTEGER, 1))
    ros.client(node).set(Parameter("threshold", Parameter.Type.DOUBLE, 1.0))
    assert type(cfg.threshold) is float
    assert seen == [
        ("threshold", 5, 0.5),
        ("extra", None, ("x",)),
        ("threshold", 0.5, 1),
        ("threshold", 1, 1.0),
    ]
    # rclpy undeclares a dynamically typed parameter set to NOT_SET; a schema keeps it.
    (unset,) = ros.client(node).set(Parameter("threshold", Parameter.Type.NOT_SET))
    assert not unset.successful and node.has_parameter("threshold")
    (read_only,) = ros.client(node).set(Parameter("plugin.setting", Parameter.Type.INTEGER, 1))
    assert not read_only.successful


def test_overrides_bring_their_type(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=[*ARG, "-p", "threshold:=0.75", "-p", "label:=[1, 2]"])
    cfg = module.DynamicParams.declare(node)
    assert (cfg.threshold, cfg.label) == (0.75, (1, 2))
    assert node.get_parameter("label").type_ == Parameter.Type.INTEGER_ARRAY
    with pytest.raises(ParameterDeclarationError, match=r"plugin\.arg: required parameter"):
        module.DynamicParams.declare(ros.node())


def test_defaults_and_remote(ros: RosHarness, module: types.ModuleType) -> None:
    cls = module.DynamicParams
    assert cls.defaults({"plugin.arg": 3, "threshold": "high"}).threshold == "high"
    with pytest.raises(ParameterDeclarationError, match="must share one type"):
        cls.defaults({"plugin.arg": [1, "a"]})
    target = ros.node(args=ARG)
    cfg = cls.declare(target)
    remote = cls.remote(ros.node(), target.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)
    assert ros.wait(remote.get()) == cfg.snapshot()
    assert ros.wait(remote.set({"threshold": "low", "extra": [True]})) is None
    assert (cfg.threshold, cfg.extra) == ("low", (True,))
    assert target.get_parameter("extra").type_ == Parameter.Type.BOOL_ARRAY


def test_tune_and_audit_read_the_live_type(module: types.ModuleType) -> None:
    graph = Graph(unique_name("dynamic_graph"))
    try:
        with served(module.DynamicParams, [*ARG, "-p", "threshold:=0.5"]) as target:
            assert graph.services_ready(target, WAIT_S)
            read = {p["name"]: p for p in first_read(graph, target)}
            result = audit_served(graph, target)
    finally:
        graph.close()
    assert (read["threshold"]["type"], read["threshold"]["value"]) == ("double", 0.5)
    assert (read["plugin.arg"]["type"], read["plugin.arg"]["value"]) == ("string_array", ["a", "b"])
    assert read["extra"]["type"] == "unset"
    assert target in result.audited
    assert [f for f in result.findings if f.kind == VIOLATION] == []
    drifted = {f.parameter for f in result.findings if f.kind == DRIFT_DEFAULT}
    assert drifted == {"threshold"}  # 0.5 for the default 5
