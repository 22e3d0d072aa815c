"""Values at, just inside and just outside every kind of bound and step.

One schema holds each kind: ``range`` with and without a step on int, double
and their arrays, ``gt``/``ge``/``lt``/``le``, ``bounds``, ``element_bounds`` and
``length``. Each case is a value and whether a node must accept it. The same
table drives the runtime tests (services and overrides) and the check-params
tests, so the two stay in agreement.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

SCHEMA = """\
genparams: 1
name: edges
parameters:
  count: {type: int, default: 10, range: {min: 0, max: 100, step: 5}}
  span: {type: int, default: 0, range: {min: -10, max: 10}}
  ratio: {type: double, default: 0.5, range: {min: 0.0, max: 1.0, step: 0.25}}
  level: {type: double, default: 0.0, range: {min: -2.0, max: 2.0}}
  ticks: {type: int_array, default: [0, 100], range: {min: 0, max: 100, step: 5}}
  weights: {type: double_array, default: [0.5], range: {min: 0.0, max: 1.0, step: 0.25}}
  spans: {type: int_array, default: [0], range: {min: -10, max: 10}}
  gain: {type: double, default: 1.0, validators: [{gt: 0.0}, {le: 10.0}]}
  offset: {type: int, default: 0, validators: [{ge: -5}, {lt: 5}]}
  trim: {type: double, default: 0.0, validators: [{bounds: [-1.0, 1.0]}]}
  steps: {type: int, default: 0, validators: [{bounds: [-3, 3]}]}
  trims: {type: double_array, default: [0.0], validators: [{element_bounds: [-1.0, 1.0]}]}
  ids: {type: int_array, default: [1, 2], validators: [{length: {min: 2, max: 3}}]}
  tag: {type: string, default: ab, validators: [{length: {min: 1, max: 4}}]}
"""

# rclpy accepts a double within this relative distance of a bound or a step.
TOLERANCE = 1e-6


@dataclass(frozen=True)
class Edge:
    name: str
    value: Any
    accepted: bool
    problem: str = ""  # a phrase the rejection names

    @property
    def id(self) -> str:
        verdict = "ok" if self.accepted else "refused"
        return f"{self.name}={self.value!r}-{verdict}"


def _below(x: float) -> float:
    return math.nextafter(x, -math.inf)


def _above(x: float) -> float:
    return math.nextafter(x, math.inf)


RANGE = "must be within"
STEP = "plus a whole number of steps of"

EDGES: tuple[Edge, ...] = (
    # int range with a step: the edges, one step inside, one past, between steps
    Edge("count", 0, True),
    Edge("count", 100, True),
    Edge("count", 5, True),
    Edge("count", 95, True),
    Edge("count", -1, False, RANGE),
    Edge("count", 101, False, RANGE),
    Edge("count", 105, False, RANGE),
    Edge("count", 7, False, STEP),
    Edge("count", 99, False, STEP),
    # int range without a step
    Edge("span", -10, True),
    Edge("span", 10, True),
    Edge("span", 9, True),
    Edge("span", -11, False, RANGE),
    Edge("span", 11, False, RANGE),
    # double range with a step; within the tolerance counts as on the edge or step
    Edge("ratio", 0.0, True),
    Edge("ratio", 1.0, True),
    Edge("ratio", 0.75, True),
    Edge("ratio", 1.0 + TOLERANCE / 10, True),
    Edge("ratio", 0.25 + TOLERANCE / 10, True),
    Edge("ratio", 1.001, False, RANGE),
    Edge("ratio", -0.001, False, RANGE),
    Edge("ratio", 0.3, False, STEP),
    Edge("ratio", 0.999, False, STEP),
    # double range without a step
    Edge("level", -2.0, True),
    Edge("level", 2.0, True),
    Edge("level", 1.999, True),
    Edge("level", 2.001, False, RANGE),
    Edge("level", -2.001, False, RANGE),
    # array items: rclpy checks no ranges on arrays, genparams checks each item
    Edge("ticks", [0, 100], True),
    Edge("ticks", [5, 95], True),
    Edge("ticks", [0, 101], False, "item 1 must be within [0, 100] (range), got 101"),
    Edge("ticks", [-1], False, "item 0 must be within [0, 100] (range), got -1"),
    Edge(
        "ticks", [0, 7], False, "item 1 must be 0 plus a whole number of steps of 5 (range), got 7"
    ),
    Edge("weights", [0.0, 1.0, 0.25], True),
    Edge("weights", [1.0 + TOLERANCE / 10], True),
    Edge("weights", [0.5, 1.001], False, "item 1 must be within [0.0, 1.0] (range), got 1.001"),
    Edge(
        "weights",
        [0.3],
        False,
        "item 0 must be 0.0 plus a whole number of steps of 0.25 (range), got 0.3",
    ),
    Edge("spans", [-10, 10, 9], True),
    Edge("spans", [11], False, "item 0 must be within [-10, 10] (range), got 11"),
    Edge("spans", [0, -11], False, "item 1 must be within [-10, 10] (range), got -11"),
    # gt / le on a double: the open edge is refused, the closed one accepted
    Edge("gain", 0.0, False, "must be > 0.0 (gt)"),
    Edge("gain", sys.float_info.min, True),  # the smallest normal double: rcl reads no subnormal
    Edge("gain", 10.0, True),
    Edge("gain", _below(10.0), True),
    Edge("gain", _above(10.0), False, "must be <= 10.0 (le)"),
    # ge / lt on an int
    Edge("offset", -5, True),
    Edge("offset", -6, False, "must be >= -5 (ge)"),
    Edge("offset", 4, True),
    Edge("offset", 5, False, "must be < 5 (lt)"),
    # bounds: inclusive at both ends, exact (no tolerance)
    Edge("trim", -1.0, True),
    Edge("trim", 1.0, True),
    Edge("trim", _below(1.0), True),
    Edge("trim", _above(1.0), False, "must be within [-1.0, 1.0] (bounds)"),
    Edge("trim", _below(-1.0), False, "must be within [-1.0, 1.0] (bounds)"),
    Edge("steps", 3, True),
    Edge("steps", -3, True),
    Edge("steps", 4, False, "must be within [-3, 3] (bounds)"),
    Edge("steps", -4, False, "must be within [-3, 3] (bounds)"),
    Edge("trims", [-1.0, 1.0], True),
    Edge("trims", [0.0, _above(1.0)], False, "item 1 must be within [-1.0, 1.0] (element_bounds)"),
    # length: min and max inclusive
    Edge("ids", [1, 2], True),
    Edge("ids", [1, 2, 3], True),
    Edge("ids", [1], False, "length must be between 2 and 3 (length), got 1"),
    Edge("ids", [1, 2, 3, 4], False, "length must be between 2 and 3 (length), got 4"),
    Edge("tag", "a", True),
    Edge("tag", "abcd", True),
    Edge("tag", "", False, "length must be between 1 and 4 (length), got 0"),
    Edge("tag", "abcde", False, "length must be between 1 and 4 (length), got 5"),
)

SCALAR_EDGES = tuple(e for e in EDGES if not isinstance(e.value, list))
ARRAY_EDGES = tuple(e for e in EDGES if isinstance(e.value, list))


def write_schema(folder: Path) -> Path:
    path = folder / "edges.yaml"
    path.write_text(SCHEMA, encoding="utf-8")
    return path


def yaml_value(value: Any) -> str:
    """The value as ROS YAML: repr keeps every digit of a double; strings are quoted."""
    if isinstance(value, list):
        return "[" + ", ".join(yaml_value(item) for item in value) + "]"
    if isinstance(value, str):
        return f"'{value}'"
    text = repr(value)
    if isinstance(value, float) and "e" in text and "." not in text:
        # YAML 1.1 reads 5e-324 as a string: its floats need a dot and a signed exponent.
        mantissa, _, exponent = text.partition("e")
        sign = "" if exponent.startswith(("-", "+")) else "+"
        text = f"{mantissa}.0e{sign}{exponent}"
    return text
