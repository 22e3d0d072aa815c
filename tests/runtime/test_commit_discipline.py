"""Random callbacks that nest sets, veto, clamp or raise, against random sets: node == cfg.

Two classes share one node (prefixes ``a`` and ``b``), each with a rule. Steps
install user callbacks of every kind rclpy and genparams offer (pre-set,
on-set, post-set, ``on_change`` of either class), each reacting to one
parameter by setting another (nested), refusing, clamping or raising, and make
single and atomic sets through the node and through the parameter services.
After every step:

- every parameter on the node equals the typed view of its class;
- no snapshot any subscriber was given, nor the current one, breaks a rule;
- replaying every ``on_change`` delivery, in order, from the defaults gives
  the node's values: each accepted set was committed once, in the node's order.

The run is bounded for CI (``tests/budget.py``); for a longer one:

    GENPARAMS_TEST_PROFILE=dev .venv/bin/python -m pytest tests/runtime/test_commit_discipline.py
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, ClassVar

import pytest
from hypothesis import settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, invariant, rule, run_state_machine_as_test
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime import Changes, Params
from tests.budget import examples
from tests.support import RosHarness, ServiceClient, load_generated

LIMITS = """\
genparams: 1
name: {name}
parameters:
  {low}: {{type: int, default: 10, range: {{min: 0, max: 100}}}}
  {high}: {{type: int, default: 50, range: {{min: 0, max: 100}}}}
rules:
  - {{name: ordered, check: {low} <= {high}}}
"""
CLASSES = {"a": ("limits_a", "lo", "hi"), "b": ("limits_b", "level", "cap")}
NAMES = [f"{prefix}.{n}" for prefix, (_, low, high) in CLASSES.items() for n in (low, high)]
POISON = 13  # a value that makes "raise" callbacks raise, on direct sets only
INT = Parameter.Type.INTEGER
NESTED_PER_STEP = 8

names = st.sampled_from(NAMES)
values = st.integers(0, 100).filter(lambda v: v != POISON)


class PoisonedError(Exception):
    """Raised on purpose by a callback."""


class CommitMachine(RuleBasedStateMachine):
    harness: ClassVar[RosHarness]
    classes: ClassVar[dict[str, type[Params]]]

    def __init__(self) -> None:
        super().__init__()
        self.node: Node = self.harness.node()
        self.views: dict[str, Any] = {
            p: cls.declare(self.node, prefix=p) for p, cls in self.classes.items()
        }
        self.replayed = {name: self.node.get_parameter(name).value for name in NAMES}
        self.observed: list[dict[str, int]] = []
        for prefix, view in self.views.items():
            view.on_change(self.recorder(prefix))
        self.client: ServiceClient | None = None
        # Sets callbacks may start per step: two subscribers that set one parameter to
        # different values would otherwise ping-pong for ever (as they would without genparams).
        self.budget = 0

    def recorder(self, prefix: str) -> Any:
        def record(changes: Changes[Any]) -> None:
            for change in changes:
                self.replayed[f"{prefix}.{change.name}"] = change.new
            self.observed.append({f"{prefix}.{k}": v for k, v in changes.after.to_dict().items()})

        return record

    def service(self) -> ServiceClient:
        if self.client is None:
            self.client = self.harness.client(self.node)
        return self.client

    def nested(self, name: str, value: int, atomic_with: str | None = None) -> None:
        if self.budget <= 0:
            return
        self.budget -= 1
        request = [Parameter(name, INT, value)]
        if atomic_with is not None and atomic_with != name:
            request.append(Parameter(atomic_with, INT, 100 - value))
            self.node.set_parameters_atomically(request)
        else:
            self.node.set_parameters(request)

    # -- callbacks -------------------------------------------------------------------

    @rule(trigger=names, goal=names, value=values, partner=st.none() | names)
    def on_change_sets_another(
        self, trigger: str, goal: str, value: int, partner: str | None
    ) -> None:
        prefix, _, relative = trigger.partition(".")

        def react(changes: Changes[Any]) -> None:
            if relative in changes:
                self.nested(goal, value, partner)

        self.views[prefix].on_change(react)

    @rule(trigger=names, goal=names, value=values)
    def post_set_sets_another(self, trigger: str, goal: str, value: int) -> None:
        def react(parameters: list[Parameter]) -> None:
            if any(p.name == trigger for p in parameters):
                self.nested(goal, value)

        self.node.add_post_set_parameters_callback(react)

    @rule(trigger=names, ceiling=values)
    def post_set_clamps(self, trigger: str, ceiling: int) -> None:
        def clamp(parameters: list[Parameter]) -> None:
            for parameter in parameters:
                if parameter.name == trigger and parameter.value > ceiling:
                    self.nested(trigger, ceiling)

        self.node.add_post_set_parameters_callback(clamp)

    @rule(trigger=names, goal=names, value=values)
    def on_set_sets_another(self, trigger: str, goal: str, value: int) -> None:
        def react(parameters: list[Parameter]) -> SetParametersResult:
            if any(p.name == trigger for p in parameters):
                self.nested(goal, value)
            return SetParametersResult(successful=True)

        self.node.add_on_set_parameters_callback(react)

    @rule(trigger=names, refused=values)
    def on_set_vetoes(self, trigger: str, refused: int) -> None:
        def veto(parameters: list[Parameter]) -> SetParametersResult:
            bad = any(p.name == trigger and p.value == refused for p in parameters)
            return SetParametersResult(successful=not bad, reason="vetoed")

        self.node.add_on_set_parameters_callback(veto)

    @rule(trigger=names, goal=names, value=values)
    def pre_set_sets_another(self, trigger: str, goal: str, value: int) -> None:
        def react(parameters: list[Parameter]) -> list[Parameter]:
            if any(p.name == trigger for p in parameters):
                self.nested(goal, value)
            return list(parameters)

        if not self.node._pre_set_parameters_callbacks:  # rclpy concatenates their lists
            self.node.add_pre_set_parameters_callback(react)

    @rule(kind=st.sampled_from(["on_set", "post_set", "on_change"]), prefix=st.sampled_from("ab"))
    def add_a_raising_callback(self, kind: str, prefix: str) -> None:
        def poisoned(parameters: Any) -> SetParametersResult:
            items = parameters.changed if isinstance(parameters, Changes) else parameters
            if any(getattr(p, "value", getattr(p, "new", None)) == POISON for p in items):
                raise PoisonedError("poisoned value")
            return SetParametersResult(successful=True)

        if kind == "on_set":
            self.node.add_on_set_parameters_callback(poisoned)
        elif kind == "post_set":
            self.node.add_post_set_parameters_callback(poisoned)
        else:
            self.views[prefix].on_change(poisoned)

    # -- sets ------------------------------------------------------------------------

    @rule(name=names, value=st.integers(0, 100))
    def set_one_on_the_node(self, name: str, value: int) -> None:
        self.budget = NESTED_PER_STEP
        try:
            self.node.set_parameters([Parameter(name, INT, value)])
        except PoisonedError:
            assert value == POISON

    @rule(pairs=st.lists(st.tuples(names, st.integers(0, 100)), min_size=1, max_size=4))
    def set_atomically_on_the_node(self, pairs: list[tuple[str, int]]) -> None:
        self.budget = NESTED_PER_STEP
        request = [Parameter(n, INT, v) for n, v in dict(pairs).items()]
        try:
            self.node.set_parameters_atomically(request)
        except PoisonedError:
            assert any(p.value == POISON for p in request)

    @rule(pairs=st.lists(st.tuples(names, values), min_size=1, max_size=4), atomic=st.booleans())
    def set_through_the_services(self, pairs: list[tuple[str, int]], atomic: bool) -> None:
        self.budget = NESTED_PER_STEP
        request = [Parameter(n, INT, v) for n, v in dict(pairs).items()]
        if atomic:
            self.service().set_atomically(*request)
        else:
            self.service().set(*request)

    # -- what must hold --------------------------------------------------------------

    @invariant()
    def node_and_views_agree(self) -> None:
        on_node = {name: self.node.get_parameter(name).value for name in NAMES}
        in_views = {
            f"{prefix}.{name}": value
            for prefix, view in self.views.items()
            for name, value in view.to_dict().items()
        }
        assert in_views == on_node
        assert self.replayed == on_node  # every delivery, in order, rebuilds the node's state
        for values_seen in [*self.observed, on_node]:
            for prefix, (_, low, high) in CLASSES.items():
                if f"{prefix}.{low}" in values_seen:
                    assert values_seen[f"{prefix}.{low}"] <= values_seen[f"{prefix}.{high}"]
        self.observed.clear()

    def teardown(self) -> None:
        self.harness.destroy_test_nodes()


@pytest.fixture(scope="module")
def limit_classes(tmp_path_factory: pytest.TempPathFactory) -> dict[str, type[Params]]:
    folder = Path(tmp_path_factory.mktemp("commit_discipline"))
    out = {}
    for prefix, (name, low, high) in CLASSES.items():
        schema = folder / f"{name}.yaml"
        schema.write_text(LIMITS.format(name=name, low=low, high=high), encoding="utf-8")
        module = load_generated(schema, folder)
        out[prefix] = getattr(module, "".join(w.title() for w in name.split("_")) + "Params")
    return out


def test_node_and_views_agree_whatever_the_callbacks_do(
    ros_harness: RosHarness, limit_classes: dict[str, type[Params]]
) -> None:
    CommitMachine.harness = ros_harness
    CommitMachine.classes = limit_classes
    run_state_machine_as_test(
        CommitMachine,
        settings=settings(max_examples=examples(300), stateful_step_count=20),
    )


def test_the_machine_reaches_nested_sets(
    ros_harness: RosHarness, limit_classes: dict[str, type[Params]]
) -> None:
    """A fixed run: the nesting the random one explores is really there."""
    CommitMachine.harness = ros_harness
    CommitMachine.classes = limit_classes
    machine = CommitMachine()
    machine.budget = NESTED_PER_STEP
    try:
        machine.on_change_sets_another("a.hi", "b.cap", 90, None)
        machine.post_set_clamps("b.cap", 70)
        machine.set_atomically_on_the_node([("a.hi", 60), ("b.cap", 20)])
        assert machine.node.get_parameter("b.cap").value == 70
        assert machine.views["b"].cap == 70
        machine.node_and_views_agree()
    finally:
        machine.teardown()
