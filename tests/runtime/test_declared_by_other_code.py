"""A parameter other code declared first is reported once, not also as "not set"."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.api import load_schema
from genparams.runtime import ParameterDeclarationError
from tests.support import RosHarness, load_generated

SCHEMA = """\
genparams: 1
name: taken
parameters:
  serial: {type: string}
  fps: {type: double, default: 30.0}
"""


def test_one_message_for_a_required_parameter_taken_by_other_code(
    ros: RosHarness, tmp_path: Path
) -> None:
    schema = tmp_path / "taken.yaml"
    schema.write_text(SCHEMA, encoding="utf-8")
    params_class = getattr(load_generated(schema, tmp_path), load_schema(schema).class_name)
    node = ros.node()
    node.declare_parameter("serial", "by other code")
    with pytest.raises(ParameterDeclarationError) as caught:
        params_class.declare(node)
    (problem,) = caught.value.problems
    assert (problem.key, problem.message) == (
        "serial",
        "already declared on this node by other code",
    )
