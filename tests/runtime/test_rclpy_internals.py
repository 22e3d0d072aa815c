"""Every rclpy internal genparams relies on still behaves as rclpy_internals.py says.

If one of these fails after an rclpy upgrade, genparams' commit discipline is
no longer sound on that release: read genparams/runtime/node/rclpy_internals.py.
"""

from __future__ import annotations

import importlib.metadata
import inspect
from collections.abc import Sequence

import pytest
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor, SetParametersResult
from rclpy.exceptions import ParameterNotDeclaredException
from rclpy.lifecycle import Node as LifecycleNode
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime.node import rclpy_internals as internals
from tests.support import RosHarness, unique_name


def test_checked_release_is_the_installed_one() -> None:
    installed = importlib.metadata.version("rclpy")
    assert installed.startswith(internals.RCLPY_CHECKED + "."), (
        f"rclpy {installed} is installed; genparams' use of its internals was checked "
        f"against {internals.RCLPY_CHECKED}: re-read rclpy_internals.py and update it"
    )


def test_the_common_set_path_has_the_signature_the_wrapper_spells_out() -> None:
    names = list(inspect.signature(Node._set_parameters_atomically_common).parameters)
    assert names == ["self", "parameter_list", "descriptors", "allow_not_set_type"]
    assert list(inspect.signature(Node._call_post_set_parameters_callback).parameters) == [
        "self",
        "parameter_list",
    ]


def test_order_of_a_set_on_set_then_store_then_post_set_newest_first(ros: RosHarness) -> None:
    node = ros.node()
    node.declare_parameter("x", 1)
    seen: list[str] = []

    def on_set(name: str):  # type: ignore[no-untyped-def]
        def callback(parameters: list[Parameter]) -> SetParametersResult:
            seen.append(f"on:{name}:{node.get_parameter('x').value}")
            return SetParametersResult(successful=True)

        return callback

    def post_set(name: str):  # type: ignore[no-untyped-def]
        return lambda parameters: seen.append(f"post:{name}:{node.get_parameter('x').value}")

    node.add_on_set_parameters_callback(on_set("old"))
    node.add_on_set_parameters_callback(on_set("new"))
    last = on_set("last")
    internals.add_last_on_set_callback(node, last)
    node.add_on_set_parameters_callback(on_set("newest"))
    node.add_post_set_parameters_callback(post_set("old"))
    node.add_post_set_parameters_callback(post_set("new"))
    node.set_parameters([Parameter("x", Parameter.Type.INTEGER, 2)])
    assert seen == [
        "on:newest:1",
        "on:new:1",
        "on:old:1",
        "on:last:1",
        "post:new:2",
        "post:old:2",
    ]
    assert internals.on_set_callbacks(node)[-1] is last


def test_shadowed_set_path_and_post_set_caller_see_every_set(ros: RosHarness) -> None:
    node = ros.node()
    calls: list[str] = []
    unlocked = internals.set_path(node)
    run_post_set = internals.post_set_caller(node)

    def set_path(parameter_list, descriptors=None, allow_not_set_type=False):  # type: ignore[no-untyped-def]
        calls.append(f"set:{[p.name for p in parameter_list]}:{descriptors is not None}")
        return unlocked(parameter_list, descriptors, allow_not_set_type)

    def post_set(parameters: Sequence[Parameter]) -> None:
        calls.append("post")
        run_post_set(parameters)

    internals.replace_set_path(node, set_path)
    internals.replace_post_set_caller(node, post_set)
    node.declare_parameter("a", 1.0)
    node.set_parameters([Parameter("a", Parameter.Type.DOUBLE, 2.0)])
    node.set_parameters_atomically([Parameter("a", Parameter.Type.DOUBLE, 3.0)])
    internals.declare_with_descriptors(
        node, [Parameter("b", Parameter.Type.INTEGER_ARRAY, [])], {"b": ParameterDescriptor(type=7)}
    )
    assert node.get_parameter("b").type_ == Parameter.Type.INTEGER_ARRAY
    result = internals.set_with_descriptors(
        node, [Parameter("b")], {"b": ParameterDescriptor(dynamic_typing=True)}
    )
    assert result.successful and not node.has_parameter("b")
    assert calls == [
        "set:['a']:True",
        "post",
        "set:['a']:False",
        "post",
        "set:['a']:False",
        "post",
        "set:['b']:True",
        "post",
        "set:['b']:True",
        "post",
    ]


def test_undeclare_runs_no_callback_and_can_be_shadowed(ros: RosHarness) -> None:
    node = ros.node()
    node.declare_parameter("gone", 1)
    called: list[object] = []

    def record(parameters: list[Parameter]) -> SetParametersResult:
        called.append(parameters)
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(record)
    refused: list[str] = []
    original = internals.replace_undeclare(node, refused.append)
    node.undeclare_parameter("gone")
    assert refused == ["gone"] and node.has_parameter("gone")
    original("gone")
    assert not node.has_parameter("gone") and called == []


def test_overrides_and_lifecycle_state(ros: RosHarness) -> None:
    node = ros.node(args=["-p", "speed:=2.5"])
    assert internals.parameter_overrides(node)["speed"].value == 2.5
    assert internals.lifecycle_state(node) is None
    managed = LifecycleNode(unique_name("managed"), context=ros.context)
    ros.add_node(managed)
    assert internals.lifecycle_state(managed) == "unconfigured"
    managed.trigger_configure()
    assert internals.lifecycle_state(managed) == "inactive"
    managed.trigger_activate()
    assert internals.lifecycle_state(managed) == "active"


def test_descriptor_check_is_the_verdict_of_a_set_and_stores_nothing(ros: RosHarness) -> None:
    node = ros.node()
    other = ros.node()  # any node runs the check: it reads nothing of its own
    descriptor = ParameterDescriptor(
        integer_range=[IntegerRange(from_value=0, to_value=10, step=2)]
    )
    node.declare_parameter("n", 4, descriptor)
    for value in (3, 12, 6):
        declared = node.describe_parameter("n")
        verdict = internals.descriptor_check(other, Parameter("n", value=value), declared)
        assert not other.has_parameter("n")
        (result,) = node.set_parameters([Parameter("n", value=value)])
        assert (verdict.successful, verdict.reason) == (result.successful, result.reason)
    wrong = internals.descriptor_check(other, Parameter("n", value=1.5), declared)
    assert not wrong.successful
    assert wrong.reason.startswith("Wrong parameter type")
    frozen = ParameterDescriptor(read_only=True, type=Parameter.Type.INTEGER.value)
    assert not internals.descriptor_check(other, Parameter("n", value=1), frozen).successful


def test_undeclared_check_is_the_refusal_of_a_set(ros: RosHarness) -> None:
    node = ros.node()
    node.declare_parameter("a", 1)
    for names in (["y"], ["a", "y", "z"], ["a"]):
        parameters = [Parameter(name, value=1) for name in names]
        verdict = internals.undeclared_check(parameters, ["a"])
        try:
            node.set_parameters_atomically(parameters)
        except ParameterNotDeclaredException as exc:
            assert verdict == str(exc)
        else:
            assert verdict is None


def test_first_descriptor_refusal_is_the_value_a_set_is_refused_for(ros: RosHarness) -> None:
    node = ros.node()
    ranged = ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=10, step=1)])
    node.declare_parameter("a", 1, ranged)
    node.declare_parameter("b", 1, ranged)
    node.declare_parameter("c", "x", ParameterDescriptor(read_only=True))
    cases = [
        (["a", 11, "b", 12], "a"),
        (["a", 5, "b", 12], "b"),
        (["c", "y", "a", 11], "c"),
        (["a", 5, "b", 6], None),
    ]
    for (first, one, second, two), refused in cases:
        parameters = [Parameter(first, value=one), Parameter(second, value=two)]
        assert internals.first_descriptor_refusal(node, parameters) == refused
        result = node.set_parameters_atomically(parameters)
        assert result.successful == (refused is None)
        if refused is not None:
            assert refused in result.reason  # rclpy names the value it refused


def test_declared_check_runs_after_pre_set_callbacks_and_can_be_shadowed(
    ros: RosHarness,
) -> None:
    node = ros.node()
    node.declare_parameter("a", 1)
    rclpy_check = internals.declared_check(node)
    seen: list[str] = []

    def check(parameter_list: list[Parameter]) -> None:
        seen.append(f"check:{[p.name for p in parameter_list]}")
        rclpy_check(parameter_list)

    def pre_set(parameters: list[Parameter]) -> list[Parameter]:
        seen.append("pre-set")
        return [*parameters, Parameter("y", value=1)]

    internals.replace_declared_check(node, check)
    node.add_pre_set_parameters_callback(pre_set)
    with pytest.raises(ParameterNotDeclaredException):
        node.set_parameters([Parameter("a", value=2)])
    assert seen == ["pre-set", "check:['a', 'y']"]
    with pytest.raises(TypeError):
        rclpy_check([42])  # type: ignore[list-item]
    assert node.get_parameter("a").value == 1
