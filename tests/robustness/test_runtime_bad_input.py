"""Hostile values through the parameter services and in-process sets.

Whatever arrives, the node keeps serving, a rejected set changes nothing
anywhere, and node, cfg and service agree afterwards.
"""

from __future__ import annotations

import math
import time
import types
from pathlib import Path
from typing import Any

import pytest
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime import Params
from tests.readback import mismatches, params_class, read_back, same
from tests.support import RosHarness, ServiceClient, load_generated

SCHEMA = """\
genparams: 1
name: hardened
parameters:
  speed: {type: double, default: 1.0, range: {min: 0.0, max: 10.0}}
  gain: {type: double, default: 1.0, validators: [{gt: 0.0}, {lt: 100.0}]}
  bounded: {type: double, default: 0.5, validators: [{bounds: [0.0, 1.0]}]}
  free: {type: double, default: 0.0}
  count: {type: int, default: 1, validators: [{bounds: [0, 100]}]}
  steps: {type: int, default: 0, range: {min: -5, max: 5}}
  plain_int: {type: int, default: 0}
  label: {type: string, default: a, validators: [{length: {max: 8}}]}
  any_text: {type: string, default: ""}
  names: {type: string_array, default: [a], validators: [{length: {max: 3}}]}
  samples: {type: double_array, default: [], validators: [{element_bounds: [-1.0, 1.0]}]}
  free_samples: {type: double_array, default: []}
  blob: {type: byte_array, default: []}
  word: {type: string, default: aa, validators: [{pattern: '^(a|aa)+$'}]}
"""

DEFAULTS: dict[str, Any] = {
    "speed": 1.0,
    "gain": 1.0,
    "bounded": 0.5,
    "free": 0.0,
    "count": 1,
    "steps": 0,
    "plain_int": 0,
    "label": "a",
    "any_text": "",
    "names": ("a",),
    "samples": (),
    "free_samples": (),
    "blob": b"",
    "word": "aa",
}


@pytest.fixture(scope="module")
def hardened(tmp_path_factory: pytest.TempPathFactory) -> type[Params]:
    folder = Path(tmp_path_factory.mktemp("hardened"))
    (folder / "hardened.yaml").write_text(SCHEMA, encoding="utf-8")
    module: types.ModuleType = load_generated(folder / "hardened.yaml", folder)
    return params_class(module)


class Declared:
    def __init__(self, ros: RosHarness, cls: type[Params]) -> None:
        self.ros = ros
        self.node: Node = ros.node()
        self.cfg = cls.declare(self.node)
        self.client: ServiceClient = ros.client(self.node)

    def assert_state(self, expected: dict[str, Any]) -> None:
        seen = read_back(self.ros, self.node, self.cfg, client=self.client)
        assert mismatches(seen, expected) == {}


@pytest.fixture
def declared(ros: RosHarness, hardened: type[Params]) -> Declared:
    return Declared(ros, hardened)


WRONG_TYPES = [
    Parameter("speed", value=5),
    Parameter("speed", value="5.0"),
    Parameter("count", value=5.0),
    Parameter("count", value=True),
    Parameter("label", value=["a"]),
    Parameter("names", value="a"),
    Parameter("samples", value=[1, 2]),
    Parameter("blob", value=[1, 2]),
    Parameter("free", value=[0.5]),
]


def test_wrong_types_are_refused_and_change_nothing(declared: Declared) -> None:
    results = declared.client.set(*WRONG_TYPES)
    assert [r.successful for r in results] == [False] * len(WRONG_TYPES)
    for parameter, result in zip(WRONG_TYPES, results, strict=True):
        assert result.reason.startswith(f"{parameter.name}: "), result.reason
        assert "Wrong parameter type" not in result.reason, result.reason
    atomic = declared.client.set_atomically(Parameter("speed", value=2.0), *WRONG_TYPES)
    assert not atomic.successful
    declared.assert_state(DEFAULTS)


@pytest.mark.parametrize("name", ["speed", "gain", "bounded", "samples"])
@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf], ids=["nan", "inf", "-inf"])
def test_nan_and_infinities_break_ranges_and_validators(
    declared: Declared, name: str, bad: float
) -> None:
    value = [0.0, bad] if name == "samples" else bad
    (result,) = declared.client.set(Parameter(name, value=value))
    assert not result.successful
    assert result.reason.startswith(f"{name}: "), result.reason
    declared.assert_state(DEFAULTS)


def test_nan_and_infinities_are_values_where_no_rule_forbids_them(declared: Declared) -> None:
    for value in (math.nan, math.inf, -math.inf, -0.0, 5e-324):
        (result,) = declared.client.set(Parameter("free", value=value))
        assert result.successful
        declared.assert_state({**DEFAULTS, "free": value})
    (result,) = declared.client.set(Parameter("free_samples", value=[math.nan, -math.inf]))
    assert result.successful
    declared.assert_state({**DEFAULTS, "free": 5e-324, "free_samples": (math.nan, -math.inf)})


@pytest.mark.parametrize("name", ["count", "steps", "plain_int"])
@pytest.mark.parametrize("big", [2**63, -(2**63) - 1, 10**30])
def test_integers_beyond_int64(declared: Declared, name: str, big: int) -> None:
    # A service request cannot even carry them: rclpy fails client-side, nothing is sent.
    with pytest.raises((AssertionError, ValueError, OverflowError, SystemError)):
        declared.client.set(Parameter(name, value=big))
    # In-process, the node refuses them before storing anything.
    (result,) = declared.node.set_parameters([Parameter(name, value=big)])
    assert not result.successful
    declared.assert_state(DEFAULTS)
    edge = -(2**63) if name == "plain_int" else 5
    (result,) = declared.client.set(Parameter(name, value=edge))
    assert result.successful
    declared.assert_state({**DEFAULTS, name: edge})


@pytest.mark.parametrize(
    "text, reason",
    [("a\x00b", "cannot contain NUL"), ("a\ud800b", "valid UTF-8")],
    ids=["nul", "lone surrogate"],
)
def test_strings_ros_cannot_carry_are_refused_in_process(
    declared: Declared, text: str, reason: str
) -> None:
    """A NUL would be cut by the services; a surrogate made rclpy fail after storing it."""
    (result,) = declared.node.set_parameters([Parameter("any_text", value=text)])
    assert not result.successful and reason in result.reason
    (result,) = declared.node.set_parameters([Parameter("names", value=["ok", text])])
    assert not result.successful and reason in result.reason
    declared.assert_state(DEFAULTS)


def test_enormous_values_are_checked_and_served(declared: Declared) -> None:
    started = time.monotonic()
    big_array = [math.sin(i) for i in range(200_000)]
    (result,) = declared.client.set(Parameter("samples", value=big_array))
    assert result.successful
    big_text = "ü" * 1_000_000
    (result,) = declared.client.set(Parameter("any_text", value=big_text))
    assert result.successful
    (result,) = declared.client.set(Parameter("label", value=big_text))
    assert not result.successful and "length must be at most 8" in result.reason
    (result,) = declared.client.set(Parameter("names", value=["x"] * 100_000))
    assert not result.successful and "length must be at most 3" in result.reason
    (result,) = declared.client.set(Parameter("samples", value=[*big_array, 2.0]))
    assert not result.successful and "item 200000" in result.reason
    declared.assert_state({**DEFAULTS, "samples": tuple(big_array), "any_text": big_text})
    assert time.monotonic() - started < 30


def test_a_pattern_that_backtracks_cannot_stall_the_node(declared: Declared) -> None:
    """'^(a|aa)+$' takes hours on this value with a backtracking matcher: refused in 50 ms."""
    (result,) = declared.client.set(Parameter("word", value="a" * 64 + "!"))
    assert not result.successful
    assert result.reason.startswith(
        "word: could not be matched against '^(a|aa)+$' (pattern) within 50 ms: "
        "the pattern backtracks too much on 'aaaa"
    )
    declared.assert_state(DEFAULTS)
    (result,) = declared.client.set(Parameter("word", value="a" * 64))
    assert result.successful
    declared.assert_state({**DEFAULTS, "word": "a" * 64})


def test_a_flood_of_sets_leaves_one_consistent_state(declared: Declared) -> None:
    futures = []
    for i in range(100):
        value = float(i % 12)  # 11.0 is out of range
        futures.append(
            (
                value,
                declared.client.client.set_parameters(
                    [
                        Parameter("speed", value=value),
                        Parameter("count", value=i if i % 3 else -i),
                    ]
                ),
            )
        )
    accepted_speed = []
    for value, future in futures:
        response = declared.ros.wait(future, timeout=30)
        speed_result, _count_result = response.results
        assert speed_result.successful == (value <= 10.0)
        if speed_result.successful:
            accepted_speed.append(value)
    final = read_back(declared.ros, declared.node, declared.cfg, client=declared.client)
    assert same(final["speed"][0], accepted_speed[-1])
    assert len({repr(v) for v in final["speed"]}) == 1 and len({v for v in final["count"]}) == 1
    assert 0 <= final["count"][0] <= 100


def test_atomic_set_of_many_with_one_bad_value_changes_nothing(declared: Declared) -> None:
    good = [
        Parameter("speed", value=3.0),
        Parameter("count", value=7),
        Parameter("label", value="ok"),
        Parameter("names", value=["x", "y"]),
        Parameter("blob", value=[b"\x01"]),
    ]
    for bad in (Parameter("gain", value=0.0), Parameter("free", value=1), *WRONG_TYPES[:2]):
        assert not declared.client.set_atomically(*good, bad).successful
        declared.assert_state(DEFAULTS)
    assert declared.client.set_atomically(*good).successful
    declared.assert_state(
        {**DEFAULTS, "speed": 3.0, "count": 7, "label": "ok", "names": ("x", "y"), "blob": b"\x01"}
    )


def test_length_validator_with_a_mapping_accepts_sets(declared: Declared) -> None:
    """Regression: a {length: {max: 8}} argument made every accepted set raise in the
    post-set callback, after the node had stored the value."""
    (result,) = declared.node.set_parameters([Parameter("label", value="eight ch")])
    assert result.successful
    declared.assert_state({**DEFAULTS, "label": "eight ch"})
