"""Custom validators with fixed arguments: ``{function: 'pkg.mod:f', args: [...]}`` in a
schema, passed after the value on every check, and named in the reasons."""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import pytest
from rclpy.parameter import Parameter

from genparams.runtime.core.validator_kinds import ValidatorArgumentError, build_validator
from genparams.runtime.core.validators import Custom
from tests.support import RosHarness, load_generated

HERE = __name__


def at_least(value: float, low: float, unit: str = "") -> str | None:
    return None if value >= low else f"{value} is below {low}{unit}"


@pytest.mark.parametrize(
    ("argument", "built"),
    [
        ({"function": "pkg.mod:check", "args": [0.5, "m"]}, Custom("pkg.mod:check", (0.5, "m"))),
        ({"function": "pkg.mod:check", "args": (1,)}, Custom("pkg.mod:check", (1,))),
        ({"function": "pkg.mod:check", "args": []}, Custom("pkg.mod:check")),
        ({"function": "pkg.mod:check"}, Custom("pkg.mod:check")),
        ("pkg.mod:check", Custom("pkg.mod:check")),
    ],
)
def test_both_spellings_build_the_check_with_its_arguments(argument: Any, built: Custom) -> None:
    assert build_validator("custom", argument, "double") == built


@pytest.mark.parametrize(
    ("argument", "message"),
    [
        ({"function": "pkg.mod:check", "args": 3}, "custom args must be a list, got 3"),
        ({"function": "pkg.mod:check", "args": "ab"}, "custom args must be a list, got 'ab'"),
        (
            {"function": "pkg.mod:check", "limit": 3},
            "custom takes 'package.module:function' or {function: "
            "'package.module:function', args: [...]}, got {'function': 'pkg.mod:check', "
            "'limit': 3}",
        ),
        (
            {"args": [1]},
            "custom takes 'package.module:function' or {function: "
            "'package.module:function', args: [...]}, got {'args': [1]}",
        ),
    ],
)
def test_malformed_arguments_say_why(argument: Any, message: str) -> None:
    with pytest.raises(ValidatorArgumentError) as caught:
        build_validator("custom", argument, "double")
    assert str(caught.value) == message


def test_arguments_follow_the_value_and_appear_in_the_reason() -> None:
    check = Custom(f"{HERE}:at_least", (2.0, " m"))
    assert check(2.5) is None
    assert check(1.5) == f"1.5 is below 2.0 m ({HERE}:at_least(2.0, ' m'))"
    assert check.describe() == f"passes {HERE}:at_least(2.0, ' m')"


SCHEMA = f"""\
genparams: 1
name: custom_args
parameters:
  gap:
    type: double
    default: 1.0
    validators: [{{custom: {{function: '{HERE}:at_least', args: [0.5]}}}}]
"""


@pytest.fixture
def module(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "custom_args.yaml"
    schema.write_text(SCHEMA)
    return load_generated(schema, tmp_path)


def test_a_node_checks_sets_with_the_schema_arguments(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    cfg = module.CustomArgsParams.declare(node)
    client = ros.client(node)
    (accepted,) = client.set(Parameter("gap", value=0.75))
    (rejected,) = client.set(Parameter("gap", value=0.25))
    assert accepted.successful and not rejected.successful
    assert rejected.reason == f"gap: 0.25 is below 0.5 ({HERE}:at_least(0.5))"
    assert cfg.gap == 0.75 and client.get("gap") == [0.75]
