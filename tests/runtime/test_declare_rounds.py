"""A class is declared in a bounded number of atomic rounds of rclpy's set path, all or
nothing: a refused or raising round leaves nothing of the class declared."""

from __future__ import annotations

import itertools
import time
import types
from collections.abc import Callable
from pathlib import Path

import pytest
from rcl_interfaces.msg import ParameterEvent, SetParametersResult
from rclpy.exceptions import InvalidParameterValueException
from rclpy.parameter import Parameter
from rclpy.qos import qos_profile_parameter_events

from genparams.runtime import ParameterDeclarationError
from genparams.runtime.node.declaring import DECLARE_ROUND
from tests.patience import WAIT_S
from tests.runtime.schemas import generate
from tests.support import RosHarness

COUNT = DECLARE_ROUND + 44  # two rounds


def many_schema() -> str:
    lines = ["genparams: 1", "name: many", "parameters:"]
    lines.append("  locked: {type: string, default: fixed, read_only: true}")
    lines.extend(f"  p{index}: {{type: int, default: {index}}}" for index in range(COUNT - 1))
    return "\n".join(lines) + "\n"


NAMES = sorted(["locked", *(f"p{index}" for index in range(COUNT - 1))])  # as generated

OPEN_ONLY = """\
genparams: 1
name: open_only
parameters:
  sensors:
    for_each: overrides
    rate: {type: double, default: 30.0}
"""


@pytest.fixture(scope="module")
def many(tmp_path_factory: pytest.TempPathFactory) -> types.ModuleType:
    return generate(tmp_path_factory.mktemp("many"), many_schema(), "many")


def test_each_round_is_one_on_set_and_post_set_call_in_order(
    ros: RosHarness, many: types.ModuleType
) -> None:
    node = ros.node()
    on_set: list[list[str]] = []
    post_set: list[list[str]] = []

    def record(parameters: list[Parameter]) -> SetParametersResult:
        on_set.append([p.name for p in parameters])
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(record)
    node.add_post_set_parameters_callback(lambda ps: post_set.append([p.name for p in ps]))
    cfg = many.ManyParams.declare(node, publish_schema=False)
    assert on_set == post_set == [NAMES[:DECLARE_ROUND], NAMES[DECLARE_ROUND:]]
    assert cfg.p298 == 298 and node.get_parameter("p298").value == 298
    assert node.describe_parameter("locked").read_only


def spin_until(ros: RosHarness, condition: Callable[[], bool], step: Callable[[], object]) -> None:
    deadline = time.monotonic() + WAIT_S
    while not condition():
        if time.monotonic() > deadline:
            raise TimeoutError("condition not reached")
        step()
        ros.executor.spin_once(timeout_sec=0.05)


def test_parameter_events_carry_one_round_each(ros: RosHarness, many: types.ModuleType) -> None:
    node = ros.node()
    listener = ros.node()
    target = node.get_fully_qualified_name()
    events: list[ParameterEvent] = []
    listener.create_subscription(
        ParameterEvent, "/parameter_events", events.append, qos_profile_parameter_events
    )
    # Sets of a probe until one is heard: the listener is matched from then on (reliable).
    node.declare_parameter("probe", 0)
    probes = itertools.count(1)
    spin_until(
        ros,
        lambda: any(e.node == target for e in events),
        lambda: node.set_parameters([Parameter("probe", value=next(probes))]),
    )
    events.clear()
    many.ManyParams.declare(node, publish_schema=False)
    spin_until(ros, lambda: len([e for e in events if e.new_parameters]) >= 2, lambda: None)
    declared = [[p.name for p in e.new_parameters] for e in events if e.new_parameters]
    assert declared == [NAMES[:DECLARE_ROUND], NAMES[DECLARE_ROUND:]]


def test_a_refused_later_round_leaves_nothing_declared(
    ros: RosHarness, many: types.ModuleType
) -> None:
    node = ros.node()
    node.declare_parameter("mine", 1)

    def refuse_the_last(parameters: list[Parameter]) -> SetParametersResult:
        refused = any(p.name == NAMES[-1] for p in parameters)
        return SetParametersResult(successful=not refused, reason="not on this robot")

    node.add_on_set_parameters_callback(refuse_the_last)
    with pytest.raises(ParameterDeclarationError) as caught:
        many.ManyParams.declare(node, publish_schema=False)
    assert isinstance(caught.value, InvalidParameterValueException)
    (problem,) = caught.value.problems
    assert problem.message == (
        f"an on-set callback refused the round declaring {COUNT - DECLARE_ROUND} parameters "
        f"({NAMES[DECLARE_ROUND]} to {NAMES[-1]}): not on this robot"
    )
    assert [name for name in NAMES if node.has_parameter(name)] == []
    assert node.get_parameter("mine").value == 1  # what was not the class's stays
    # Nothing of the class is left behind, so it declares once the refusal is gone.
    node.remove_on_set_parameters_callback(refuse_the_last)
    cfg = many.ManyParams.declare(node, publish_schema=False)
    assert cfg.locked == "fixed" and node.get_parameter("p0").value == 0


def test_a_raising_later_round_leaves_nothing_declared(
    ros: RosHarness, many: types.ModuleType
) -> None:
    node = ros.node()

    def raise_in_the_last(parameters: list[Parameter]) -> None:
        if any(p.name == NAMES[-1] for p in parameters):
            raise RuntimeError("post-set broke")

    node.add_post_set_parameters_callback(raise_in_the_last)
    with pytest.raises(RuntimeError, match="post-set broke"):
        many.ManyParams.declare(node, publish_schema=False)
    assert [name for name in NAMES if node.has_parameter(name)] == []


def test_a_refused_single_parameter_round_names_it(
    ros: RosHarness, tmp_path: Path, many: types.ModuleType
) -> None:
    del many
    module = generate(tmp_path, "genparams: 1\nname: one\nparameters:\n  x: {type: int}\n", "one")
    node = ros.node(args=["-p", "x:=3"])
    node.add_on_set_parameters_callback(
        lambda ps: SetParametersResult(successful=False, reason="no")
    )
    with pytest.raises(InvalidParameterValueException) as caught:
        module.OneParams.declare(node, publish_schema=False)
    assert str(caught.value).endswith("x: refused by an on-set callback: no")
    assert not node.has_parameter("x")


def test_a_class_that_declares_no_parameter(ros: RosHarness, tmp_path: Path) -> None:
    module = generate(tmp_path, OPEN_ONLY, "open_only")
    node = ros.node()
    calls: list[list[Parameter]] = []

    def record(parameters: list[Parameter]) -> SetParametersResult:
        calls.append(parameters)
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(record)
    cfg = module.OpenOnlyParams.declare(node)
    assert list(cfg.sensors) == [] and calls == []
