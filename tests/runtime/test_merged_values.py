"""What a rule reads during a change: the proposed values over the committed ones, as a
mapping of every fixed parameter by relative ROS name."""

from __future__ import annotations

import types
from pathlib import Path

import pytest

from genparams.runtime.core.problems import ParameterProblem
from genparams.runtime.core.rule_check import MergedValues, broken_rules
from genparams.runtime.core.spec import compile_schema
from tests.support import load_generated

SCHEMA = """\
genparams: 1
name: speeds
parameters:
  min_speed: {type: double, default: 0.5}
  max_speed: {type: double, default: 2.0}
  camera:
    fps: {type: double, default: 30.0}
rules:
  - {name: speed_order, check: min_speed <= max_speed}
"""


@pytest.fixture
def module(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "speeds.yaml"
    schema.write_text(SCHEMA)
    return load_generated(schema, tmp_path)


def test_proposed_values_read_over_the_committed_ones(module: types.ModuleType) -> None:
    committed = module.SpeedsParams.defaults({"camera.fps": 15.0})
    parameters = compile_schema(module.SpeedsParams._SPEC).parameters
    merged = MergedValues(committed, {"max_speed": 0.25}, parameters)
    assert dict(merged) == {"min_speed": 0.5, "max_speed": 0.25, "camera.fps": 15.0}
    assert len(merged) == 3 and sorted(merged) == ["camera.fps", "max_speed", "min_speed"]


def test_a_rule_reads_the_proposed_value_and_the_committed_other(
    module: types.ModuleType,
) -> None:
    committed = module.SpeedsParams.defaults({"min_speed": 1.5})
    assert broken_rules(committed, {"camera.fps": 5.0}, str) == []
    assert broken_rules(committed, {"max_speed": 1.5}, str) == []
    assert broken_rules(committed, {"max_speed": 1.0}, lambda name: f"front.{name}") == [
        ParameterProblem(
            "",
            "rule 'speed_order' broken: min_speed <= max_speed is false for "
            "front.min_speed=1.5, front.max_speed=1.0",
        )
    ]
