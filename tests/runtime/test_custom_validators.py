"""Custom validators: imported at declare, run on overrides and on every set."""

from __future__ import annotations

import types
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

from genparams.runtime import ParameterDeclarationError
from tests.support import RosHarness, load_generated

SCHEMA = """\
genparams: 1
name: custom_demo
parameters:
  lanes: {type: int, default: 2, validators: [{custom: 'tests.custom_checks:is_even'}]}
  fragile: {type: string, default: x, validators: [{custom: 'tests.custom_checks:always_raises'}]}
"""


@pytest.fixture
def module(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "custom_demo.yaml"
    schema.write_text(SCHEMA)
    return load_generated(schema, tmp_path)


def test_failing_custom_validator_rejects_instead_of_crashing(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=["-p", "fragile:=zzz", "-p", "lanes:=3"])
    with pytest.raises(ParameterDeclarationError) as caught:
        module.CustomDemoParams.declare(node)
    assert tuple(map(str, caught.value.problems)) == (
        "fragile: override rejected: custom validator tests.custom_checks:always_raises "
        "raised RuntimeError: checker is broken",
        "lanes: override rejected: 3 is odd (tests.custom_checks:is_even)",
    )
    assert not node.has_parameter("lanes")


def test_custom_validator_accepts_and_rejects(ros: RosHarness, tmp_path: Path) -> None:
    schema = tmp_path / "even.yaml"
    schema.write_text(
        "genparams: 1\nname: even\nparameters:\n"
        "  lanes: {type: int, default: 2, validators: [{custom: 'tests.custom_checks:is_even'}]}\n"
    )
    module = load_generated(schema, tmp_path)
    node = ros.node()
    cfg = module.EvenParams.declare(node)
    client = ros.client(node)
    (accepted,) = client.set(Parameter("lanes", value=4))
    (rejected,) = client.set(Parameter("lanes", value=5))
    assert accepted.successful and not rejected.successful
    assert rejected.reason == "lanes: 5 is odd (tests.custom_checks:is_even)"
    assert cfg.lanes == 4 and client.get("lanes") == [4]
