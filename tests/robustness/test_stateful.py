"""Random sequences of sets through the parameter services, checked against a pure model.

One node carries a fixed schema with every kind of rule. The model below is
written from the schema's meaning and rclpy's documented range semantics, not
from genparams: a set is accepted exactly when the model accepts it, node, cfg
and service always agree with the model's state, and every value ever observed
satisfies every rule.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

import pytest
from hypothesis import settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, invariant, rule, run_state_machine_as_test
from rclpy.parameter import Parameter

from genparams.runtime import Params
from tests.budget import examples
from tests.readback import mismatches, params_class, read_back
from tests.support import RosHarness, load_generated

SCHEMA = """\
genparams: 1
name: stateful
parameters:
  fps: {type: double, default: 30.0, range: {min: 1.0, max: 120.0, step: 0.5}}
  width: {type: int, default: 640, range: {min: 64, max: 4096, step: 64}}
  gain: {type: double, default: 1.0, validators: [{gt: 0.0}, {le: 10.0}]}
  mode: {type: string, default: auto, choices: [auto, manual, "off"]}
  serial: {type: string, default: ABCD1234, validators: [{pattern: '^[A-Z0-9]{8}$'}]}
  name: {type: string, default: robot, validators: [not_empty, {length: {max: 12}}]}
  enabled: {type: bool, default: true}
  robot_id: {type: string, default: r1, read_only: true}
  io:
    topics: {type: string_array, default: [/a], validators: [not_empty, unique, {pattern: '^/'}]}
    weights:
      type: double_array
      default: [0.5, 0.5]
      validators: [{length: {min: 1, max: 4}}, {element_bounds: [0.0, 1.0]}]
    ids: {type: int_array, default: [1, 2], validators: [{subset_of: [1, 2, 3, 4]}, unique]}
    mask: {type: byte_array, default: [1, 2], validators: [{length: {max: 4}}]}
    flags: {type: bool_array, default: [true]}
  offset: {type: int, default: 0, validators: [{bounds: [-100, 100]}]}
rules:
  - name: gain_within_fps
    check: gain * 10 <= fps
  - name: one_weight_per_id
    check: len(io.weights) == len(io.ids)
"""

T = Parameter.Type
REL_TOL = 1e-6  # rclpy's Node.PARAM_REL_TOL


def ros_double_range(value: float, low: float, high: float, step: float) -> bool:
    """rclpy's _apply_floating_point_range, restated."""
    if math.isclose(value, low, rel_tol=REL_TOL) or math.isclose(value, high, rel_tol=REL_TOL):
        return True
    if not low < value < high:
        return False
    steps = round((value - low) / step)
    return math.isclose(low + steps * step, value, rel_tol=REL_TOL)


def ros_int_range(value: int, low: int, high: int, step: int) -> bool:
    """rclpy's _apply_integer_range, restated: the edges are always valid."""
    return value in (low, high) or (low < value < high and (value - low) % step == 0)


def unique(items: Any) -> bool:
    return len(set(items)) == len(items)


@dataclass(frozen=True)
class Rule:
    type: Parameter.Type
    holds: Callable[[Any], bool]
    default: Any
    read_only: bool = False


MODEL: dict[str, Rule] = {
    "fps": Rule(T.DOUBLE, lambda v: ros_double_range(v, 1.0, 120.0, 0.5), 30.0),
    "width": Rule(T.INTEGER, lambda v: ros_int_range(v, 64, 4096, 64), 640),
    "gain": Rule(T.DOUBLE, lambda v: 0.0 < v <= 10.0, 1.0),
    "mode": Rule(T.STRING, lambda v: v in ("auto", "manual", "off"), "auto"),
    "serial": Rule(T.STRING, lambda v: re.search(r"^[A-Z0-9]{8}$", v) is not None, "ABCD1234"),
    "name": Rule(T.STRING, lambda v: 0 < len(v) <= 12, "robot"),
    "enabled": Rule(T.BOOL, lambda v: True, True),
    "robot_id": Rule(T.STRING, lambda v: True, "r1", read_only=True),
    "io.topics": Rule(
        T.STRING_ARRAY, lambda v: len(v) > 0 and unique(v) and all(t[:1] == "/" for t in v), ("/a",)
    ),
    "io.weights": Rule(
        T.DOUBLE_ARRAY, lambda v: 1 <= len(v) <= 4 and all(0.0 <= x <= 1.0 for x in v), (0.5, 0.5)
    ),
    "io.ids": Rule(T.INTEGER_ARRAY, lambda v: set(v) <= {1, 2, 3, 4} and unique(v), (1, 2)),
    "io.mask": Rule(T.BYTE_ARRAY, lambda v: len(v) <= 4, b"\x01\x02"),
    "io.flags": Rule(T.BOOL_ARRAY, lambda v: True, (True,)),
    "offset": Rule(T.INTEGER, lambda v: -100 <= v <= 100, 0),
}

# The schema's rules, restated over the model's state (ROS name -> value).
CROSS_RULES: dict[str, Callable[[dict[str, Any]], bool]] = {
    "gain_within_fps": lambda s: s["gain"] * 10 <= s["fps"],
    "one_weight_per_id": lambda s: len(s["io.weights"]) == len(s["io.ids"]),
}


def rules_hold(state: dict[str, Any]) -> bool:
    return all(holds(state) for holds in CROSS_RULES.values())


text = st.text(st.characters(exclude_categories=["Cs"], exclude_characters="\x00"), max_size=14)
doubles = st.one_of(
    st.floats(-20.0, 140.0),
    st.integers(-4, 260).map(lambda k: k * 0.5),
    st.sampled_from(
        [
            1.0,
            120.0,
            1.0000001,
            119.9999999,
            0.9999,
            120.001,
            0.0,
            -0.0,
            5e-324,
            10.0,
            10.0000001,
            math.nan,
            math.inf,
            -math.inf,
        ]
    ),
)
VALUES: dict[str, st.SearchStrategy[Any]] = {
    "fps": doubles,
    "width": st.one_of(st.integers(0, 5000), st.integers(0, 70).map(lambda k: k * 64)),
    "gain": doubles,
    "mode": st.one_of(st.sampled_from(["auto", "manual", "off", "Auto", "", "off "]), text),
    "serial": st.one_of(st.from_regex(r"[A-Z0-9]{7,9}\n?", fullmatch=True), text),
    "name": text,
    "enabled": st.booleans(),
    "robot_id": text,
    "io.topics": st.lists(st.sampled_from(["/a", "/b", "/c", "d", ""]), max_size=4).map(tuple),
    "io.weights": st.lists(st.one_of(st.floats(-0.5, 1.5), st.just(math.nan)), max_size=5).map(
        tuple
    ),
    "io.ids": st.lists(st.integers(0, 5), max_size=5).map(tuple),
    "io.mask": st.binary(max_size=6),
    "io.flags": st.lists(st.booleans(), max_size=3).map(tuple),
    "offset": st.one_of(st.integers(-200, 200), st.sampled_from([-(2**63), 2**63 - 1])),
}
# A value of another type for each type: ROS must refuse it before any validator runs.
WRONG_TYPE = {
    T.DOUBLE: (T.INTEGER, 5),
    T.INTEGER: (T.DOUBLE, 64.0),
    T.STRING: (T.STRING_ARRAY, ["auto"]),
    T.BOOL: (T.STRING, "true"),
    T.STRING_ARRAY: (T.STRING, "/a"),
    T.DOUBLE_ARRAY: (T.INTEGER_ARRAY, [0]),
    T.INTEGER_ARRAY: (T.DOUBLE_ARRAY, [1.0]),
    T.BYTE_ARRAY: (T.INTEGER_ARRAY, [1]),
    T.BOOL_ARRAY: (T.BOOL, True),
}


@dataclass(frozen=True)
class Assignment:
    name: str
    type: Parameter.Type
    value: Any  # model form: tuples for arrays, bytes for byte arrays

    def parameter(self) -> Parameter:
        if self.type == T.BYTE_ARRAY:
            return Parameter(self.name, self.type, [bytes((b,)) for b in self.value])
        value = list(self.value) if isinstance(self.value, tuple) else self.value
        return Parameter(self.name, self.type, value)

    def accepted_by_model(self) -> bool:
        rule = MODEL[self.name]
        return self.type == rule.type and not rule.read_only and rule.holds(self.value)


def _assignment(name: str) -> st.SearchStrategy[Assignment]:
    rule = MODEL[name]
    wrong_type, wrong_value = WRONG_TYPE[rule.type]
    return st.one_of(
        VALUES[name].map(lambda value: Assignment(name, rule.type, value)),
        st.just(Assignment(name, wrong_type, wrong_value)),
    )


assignments = st.sampled_from(sorted(MODEL)).flatmap(_assignment)


class ParameterServiceMachine(RuleBasedStateMachine):
    harness: ClassVar[RosHarness]
    params_cls: ClassVar[type[Params]]
    refused_by_rules: ClassVar[set[str]] = set()  # rule names seen in rejections

    def __init__(self) -> None:
        super().__init__()
        self.node = self.harness.node()
        self.cfg = self.params_cls.declare(self.node)
        self.client = self.harness.client(self.node)
        self.state = {name: rule.default for name, rule in MODEL.items()}

    @rule(sets=st.lists(assignments, min_size=1, max_size=4))
    def set_one_by_one(self, sets: list[Assignment]) -> None:
        """Each is its own change, checked against the state the ones before it left."""
        results = self.client.set(*(a.parameter() for a in sets))
        for assignment, result in zip(sets, results, strict=True):
            proposed = self.state | {assignment.name: assignment.value}
            expected = assignment.accepted_by_model() and rules_hold(proposed)
            assert result.successful == expected, (assignment, result)
            self.note_rules(result.reason)
            if result.successful:
                self.state = proposed

    @rule(sets=st.lists(assignments, min_size=1, max_size=4))
    def set_atomically(self, sets: list[Assignment]) -> None:
        """All or nothing: the rules are checked on the state with every value applied."""
        result = self.client.set_atomically(*(a.parameter() for a in sets))
        proposed = self.state | {a.name: a.value for a in sets}
        expected = all(a.accepted_by_model() for a in sets) and rules_hold(proposed)
        assert result.successful == expected, (sets, result)
        self.note_rules(result.reason)
        if result.successful:
            self.state = proposed

    def note_rules(self, reason: str) -> None:
        self.refused_by_rules.update(name for name in CROSS_RULES if f"rule '{name}'" in reason)

    @rule(broken=st.sampled_from(sorted(CROSS_RULES)))
    def break_a_rule(self, broken: str) -> None:
        """Values that each pass their own validators but together break one rule.

        Random sets reach a rule only by chance; this step makes sure every rule
        is seen refusing in every run.
        """
        if broken == "gain_within_fps":
            sets = [Assignment("gain", T.DOUBLE, 5.0), Assignment("fps", T.DOUBLE, 30.0)]
        else:
            count = len(self.state["io.ids"]) % 4 + 1  # any length but the ids' own
            sets = [Assignment("io.weights", T.DOUBLE_ARRAY, (0.5,) * count)]
        assert all(a.accepted_by_model() for a in sets)
        proposed = self.state | {a.name: a.value for a in sets}
        assert not CROSS_RULES[broken](proposed)
        result = self.client.set_atomically(*(a.parameter() for a in sets))
        assert not result.successful
        assert f"rule '{broken}'" in result.reason, result.reason
        self.note_rules(result.reason)

    @rule(count=st.integers(1, 4), fps=st.sampled_from([30.0, 60.0, 120.0]))
    def fix_two_values_together(self, count: int, fps: float) -> None:
        """The way out of a rule: change the values it links in one atomic set."""
        weights = Assignment("io.weights", T.DOUBLE_ARRAY, (0.25,) * count)
        ids = Assignment("io.ids", T.INTEGER_ARRAY, tuple(range(1, count + 1)))
        gain = Assignment("gain", T.DOUBLE, fps / 20)
        fps_set = Assignment("fps", T.DOUBLE, fps)
        result = self.client.set_atomically(*(a.parameter() for a in (weights, ids, gain, fps_set)))
        assert result.successful, result.reason
        self.state |= {a.name: a.value for a in (weights, ids, gain, fps_set)}

    @invariant()
    def node_cfg_and_service_agree_with_the_model(self) -> None:
        seen = read_back(self.harness, self.node, self.cfg, client=self.client)
        assert mismatches(seen, self.state) == {}
        for name, values in seen.items():
            assert all(MODEL[name].holds(value) for value in values), (name, values)
        assert rules_hold({name: values[0] for name, values in seen.items()})
        assert rules_hold({name: values[1] for name, values in seen.items()})

    def teardown(self) -> None:
        self.harness.destroy_test_nodes()


@pytest.fixture(scope="module")
def stateful_class(tmp_path_factory: pytest.TempPathFactory) -> type[Params]:
    folder = tmp_path_factory.mktemp("stateful")
    schema = Path(folder) / "stateful.yaml"
    schema.write_text(SCHEMA, encoding="utf-8")
    return params_class(load_generated(schema, folder))


def test_model_defaults_match_the_schema(stateful_class: type[Params]) -> None:
    snapshot = stateful_class.defaults()
    assert snapshot.to_dict()["io"]["mask"] == MODEL["io.mask"].default
    assert all(rule.holds(rule.default) for rule in MODEL.values())
    assert rules_hold({name: rule.default for name, rule in MODEL.items()})


def test_sets_through_services_follow_the_model(
    ros_harness: RosHarness, stateful_class: type[Params]
) -> None:
    ParameterServiceMachine.harness = ros_harness
    ParameterServiceMachine.params_cls = stateful_class
    run_state_machine_as_test(
        ParameterServiceMachine,
        settings=settings(max_examples=examples(15), stateful_step_count=10),
    )
    assert ParameterServiceMachine.refused_by_rules == set(CROSS_RULES)  # rules were exercised
