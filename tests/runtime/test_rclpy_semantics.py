"""A node with a genparams class bound is plain rclpy for every parameter the class does not own.

Each scenario below runs twice, the way rclpy's own tests drive a node: on a
plain node and on a node with a class bound that has every part genparams adds
to a set (an old name, a mapped group, an array parameter). Both runs must tell
the same story: results, reasons, exceptions and their text, the order in which
pre-set, on-set and post-set callbacks run and what each is given, the values
left behind, and the parameter events published.
"""

from __future__ import annotations

import time
import types
from collections.abc import Callable, Iterator
from typing import Any

import pytest
from rcl_interfaces.msg import (
    IntegerRange,
    ParameterDescriptor,
    ParameterEvent,
    SetParametersResult,
)
from rclpy.node import Node
from rclpy.parameter import Parameter

from tests.patience import WAIT_S
from tests.runtime.schemas import generate
from tests.support import RosHarness

BOUND = """\
genparams: 1
name: bound
parameters:
  max_speed: {type: double, default: 1.0, range: {min: 0.0, max: 3.0}, aliases: [speed_limit]}
  tags: {type: string_array, default: [a]}
  joints: {type: string_array, default: [left]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0}
"""

EMPTY_LIST_REFUSED = (
    "parameter list cannot be empty, this might be due to pre_set_parameters_callback "
    "modifying the original parameters list."
)

Story = list[Any]


@pytest.fixture(scope="module")
def bound(tmp_path_factory: pytest.TempPathFactory) -> types.ModuleType:
    return generate(tmp_path_factory.mktemp("bound"), BOUND, "bound")


def outcome(call: Callable[[], Any]) -> Any:
    """What a call gives back, in plain data: results, or the exception's type and text."""
    try:
        returned = call()
    except Exception as exc:  # the story records every exception rclpy raises
        return (type(exc).__name__, str(exc))
    return plain_data(returned)


def plain_data(returned: Any) -> Any:
    if isinstance(returned, SetParametersResult):
        return (returned.successful, returned.reason)
    if isinstance(returned, list):
        return [plain_data(item) for item in returned]
    return returned


def value_of(node: Node, name: str) -> Any:
    return node.get_parameter(name).value if node.has_parameter(name) else "<undeclared>"


def user_parameters(node: Node) -> None:
    node.declare_parameter("foo", 1)
    node.declare_parameter("bar", 10)
    node.declare_parameter("ranged", 5, ParameterDescriptor(integer_range=[IntegerRange(
        from_value=0, to_value=10, step=1)]))  # fmt: skip
    node.declare_parameter("fixed", "x", ParameterDescriptor(read_only=True))
    node.declare_parameter("dyn", 1, ParameterDescriptor(dynamic_typing=True))


def refusing_pre_set(node: Node, story: Story) -> None:
    def refuse(parameters: list[Parameter]) -> list[Parameter]:
        story.append(("pre-set", [p.name for p in parameters]))
        return []

    node.add_pre_set_parameters_callback(refuse)
    story.append(outcome(lambda: node.set_parameters([Parameter("foo", value=2)])))
    story.append(outcome(lambda: node.set_parameters_atomically([Parameter("foo", value=3)])))
    story.append(value_of(node, "foo"))
    node.remove_pre_set_parameters_callback(refuse)
    story.append(outcome(lambda: node.set_parameters([Parameter("foo", value=4)])))
    story.append(value_of(node, "foo"))


def modifying_pre_set(node: Node, story: Story) -> None:
    def add_bar(parameters: list[Parameter]) -> list[Parameter]:
        """rclpy's contract: return the whole modified list."""
        extra = [Parameter("bar", value=p.value * 10) for p in parameters if p.name == "foo"]
        return [*parameters, *extra]

    node.add_pre_set_parameters_callback(add_bar)
    node.add_post_set_parameters_callback(lambda ps: story.append([p.name for p in ps]))
    story.append(outcome(lambda: node.set_parameters([Parameter("foo", value=2)])))
    story.append((value_of(node, "foo"), value_of(node, "bar")))
    story.append(outcome(lambda: node.set_parameters_atomically([Parameter("foo", value=3)])))
    story.append((value_of(node, "foo"), value_of(node, "bar")))
    node.remove_pre_set_parameters_callback(add_bar)


def items_that_are_no_parameters(node: Node, story: Story) -> None:
    bad: list[Any] = [42]
    story.append(outcome(lambda: node.set_parameters(bad)))
    story.append(outcome(lambda: node.set_parameters_atomically(bad)))
    mixed: list[Any] = [Parameter("foo", value=2), 42]
    story.append(outcome(lambda: node.set_parameters_atomically(mixed)))
    story.append(value_of(node, "foo"))


def callbacks_in_order(node: Node, story: Story) -> None:
    def on_set(label: str, refuse: int | None = None) -> Callable[..., SetParametersResult]:
        def callback(parameters: list[Parameter]) -> SetParametersResult:
            story.append((label, [(p.name, p.value) for p in parameters]))
            if refuse is not None and any(p.value == refuse for p in parameters):
                return SetParametersResult(successful=False, reason=f"{label} refuses {refuse}")
            return SetParametersResult(successful=True)

        return callback

    def post_set(label: str) -> Callable[[list[Parameter]], None]:
        return lambda parameters: story.append((label, [p.name for p in parameters]))

    first, second = on_set("on-set 1", refuse=99), on_set("on-set 2")
    node.add_on_set_parameters_callback(first)
    node.add_on_set_parameters_callback(second)
    node.add_post_set_parameters_callback(post_set("post-set 1"))
    node.add_post_set_parameters_callback(post_set("post-set 2"))
    story.append(outcome(lambda: node.set_parameters([Parameter("foo", value=7)])))
    story.append(outcome(lambda: node.set_parameters([Parameter("foo", value=99)])))
    story.append(outcome(lambda: node.set_parameters_atomically([
        Parameter("foo", value=8), Parameter("bar", value=99)])))  # fmt: skip
    story.append(outcome(lambda: node.set_parameters([
        Parameter("foo", value=9), Parameter("bar", value=99)])))  # fmt: skip
    story.append((value_of(node, "foo"), value_of(node, "bar")))
    node.remove_on_set_parameters_callback(second)
    story.append(outcome(lambda: node.set_parameters([Parameter("bar", value=11)])))


def undeclared_names(node: Node, story: Story) -> None:
    undeclared = Parameter("undeclared", value=1)
    story.append(outcome(lambda: node.set_parameters([Parameter("foo", value=5), undeclared])))
    story.append(value_of(node, "foo"))
    story.append(outcome(lambda: node.set_parameters_atomically([
        Parameter("foo", value=6), undeclared])))  # fmt: skip
    story.append(value_of(node, "foo"))
    story.append(outcome(lambda: node.get_parameter("undeclared")))


def descriptor_refusals(node: Node, story: Story) -> None:
    story.append(outcome(lambda: node.set_parameters([Parameter("foo", value="text")])))
    story.append(outcome(lambda: node.set_parameters([Parameter("ranged", value=11)])))
    story.append(outcome(lambda: node.set_parameters([Parameter("fixed", value="y")])))
    story.append(outcome(lambda: node.set_parameters([Parameter("foo")])))  # NOT_SET
    story.append(outcome(lambda: node.set_parameters_atomically([
        Parameter("ranged", value=3), Parameter("ranged", value=12)])))  # fmt: skip
    story.append((value_of(node, "foo"), value_of(node, "ranged"), value_of(node, "fixed")))


def undeclaring(node: Node, story: Story) -> None:
    story.append(outcome(lambda: node.undeclare_parameter("bar")))
    story.append(outcome(lambda: node.undeclare_parameter("fixed")))
    story.append(outcome(lambda: node.undeclare_parameter("nope")))
    story.append(outcome(lambda: node.set_parameters([Parameter("dyn")])))  # NOT_SET undeclares
    story.append([node.has_parameter(name) for name in ("bar", "fixed", "dyn")])
    story.append(outcome(lambda: node.declare_parameter("bar", 3).value))


SCENARIOS = [
    refusing_pre_set,
    modifying_pre_set,
    items_that_are_no_parameters,
    callbacks_in_order,
    undeclared_names,
    descriptor_refusals,
    undeclaring,
]


def story_of(node: Node, scenario: Callable[[Node, Story], None]) -> Story:
    user_parameters(node)
    story: Story = []
    scenario(node, story)
    return story


@pytest.mark.parametrize("scenario", SCENARIOS, ids=lambda s: s.__name__)
def test_a_bound_node_tells_the_story_of_a_plain_one(
    scenario: Callable[[Node, Story], None], ros: RosHarness, bound: types.ModuleType
) -> None:
    plain = story_of(ros.node(), scenario)
    node = ros.node()
    bound.BoundParams.declare(node, prefix="gp")
    assert story_of(node, scenario) == plain


def wait_until(ros: RosHarness, condition: Callable[[], bool]) -> None:
    deadline = time.monotonic() + WAIT_S
    while not condition():
        if time.monotonic() > deadline:
            raise TimeoutError("the parameter events did not arrive")
        ros.executor.spin_once(timeout_sec=0.1)


class EventLog:
    """The parameter events one node publishes, as the names each event carries."""

    def __init__(self, ros: RosHarness, node: Node) -> None:
        self.ros = ros
        self.node_name = node.get_fully_qualified_name()
        self.events: list[tuple[list[str], list[str], list[str]]] = []
        self.subscription = ros.client_node.create_subscription(
            ParameterEvent, "/parameter_events", self.heard, 1000
        )

    def heard(self, event: ParameterEvent) -> None:
        if event.node == self.node_name:
            self.events.append(
                (
                    [p.name for p in event.new_parameters],
                    [p.name for p in event.changed_parameters],
                    [p.name for p in event.deleted_parameters],
                )
            )

    def wait_for(self, count: int) -> Iterator[tuple[list[str], list[str], list[str]]]:
        """The first ``count`` events heard (waiting for them); each name list sorted."""
        wait_until(self.ros, lambda: len(self.events) >= count)
        return ((sorted(n), sorted(c), sorted(d)) for n, c, d in self.events[:count])


def events_of_user_parameters(ros: RosHarness, node: Node) -> list[Any]:
    log = EventLog(ros, node)
    marker = "marker"
    node.declare_parameter(marker, 0)  # the first event heard once the subscription matched
    wait_until(ros, lambda: any(marker in new for new, _, _ in log.events))
    log.events.clear()
    user_parameters(node)
    node.set_parameters([Parameter("foo", value=2), Parameter("bar", value=3)])
    node.set_parameters_atomically([Parameter("foo", value=4), Parameter("bar", value=5)])
    node.set_parameters([Parameter("ranged", value=50)])  # refused: no event
    node.set_parameters([Parameter("dyn")])  # undeclared
    node.undeclare_parameter("bar")  # rclpy publishes nothing for this
    node.set_parameters([Parameter("foo", value=6)])
    events = list(log.wait_for(10))  # 5 declared, 2 + 1 set, 1 undeclared, 1 set
    ros.client_node.destroy_subscription(log.subscription)
    return events


def test_parameter_events_are_those_of_a_plain_node(
    ros: RosHarness, bound: types.ModuleType
) -> None:
    plain = events_of_user_parameters(ros, ros.node())
    node = ros.node()
    bound.BoundParams.declare(node, prefix="gp")
    assert events_of_user_parameters(ros, node) == plain
    assert plain[-3:] == [([], ["bar", "foo"], []), ([], [], ["dyn"]), ([], ["foo"], [])]


# Old names (aliases) ------------------------------------------------------------------


@pytest.mark.parametrize("name", ["speed_limit", "max_speed"])
def test_a_pre_set_refusal_holds_for_a_renamed_parameter(
    name: str, ros: RosHarness, bound: types.ModuleType
) -> None:
    node = ros.node()
    cfg = bound.BoundParams.declare(node)
    node.add_pre_set_parameters_callback(lambda parameters: [])
    (result,) = node.set_parameters([Parameter(name, value=2.0)])
    assert (result.successful, result.reason) == (False, EMPTY_LIST_REFUSED)
    (served,) = ros.client(node).set(Parameter(name, value=2.0))  # as `ros2 param set` does
    assert (served.successful, served.reason) == (False, EMPTY_LIST_REFUSED)
    assert [value_of(node, n) for n in ("max_speed", "speed_limit")] == [1.0, 1.0]
    assert cfg.max_speed == 1.0


def test_a_pre_set_rewrite_of_an_old_name_reaches_both_names(
    ros: RosHarness, bound: types.ModuleType
) -> None:
    node = ros.node()
    cfg = bound.BoundParams.declare(node)

    def clamp(parameters: list[Parameter]) -> list[Parameter]:
        return [
            Parameter(p.name, value=min(p.value, 2.5)) if p.name == "speed_limit" else p
            for p in parameters
        ]

    node.add_pre_set_parameters_callback(clamp)
    seen: list[list[str]] = []
    node.add_post_set_parameters_callback(lambda ps: seen.append(sorted(p.name for p in ps)))
    (result,) = ros.client(node).set(Parameter("speed_limit", value=2.9))
    assert result.successful, result.reason
    assert [value_of(node, n) for n in ("max_speed", "speed_limit")] == [2.5, 2.5]
    assert cfg.max_speed == 2.5 and seen == [["max_speed", "speed_limit"]]
