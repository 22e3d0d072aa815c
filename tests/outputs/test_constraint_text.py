"""Every output states each parameter's constraints in the same words.

The words come from one place, the runtime's compiled parameter
(``Parameter.constraints``); this reads them back out of every golden file of every
case (module docstrings, docs page, defaults file, JSON Schema) and out of the
descriptors a real node serves, so no output can drift from the others.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from rcl_interfaces.msg import ParameterType
from rclpy.parameter import Parameter as RosParameter

from genparams.api import load_schema
from genparams.outputs.json_schema import _parameter_name
from genparams.outputs.markup import md_text
from genparams.outputs.render import python_literal
from genparams.runtime.core.spec import CompiledParam, compile_schema
from genparams.runtime.core.types import TYPES
from genparams.runtime.core.validators import RosRange
from genparams.runtime.node.declaring import descriptor_for, rule_text
from genparams.schema.model import Parameter, Schema
from tests.golden import OutputCase, all_output_cases, case_dirs, case_schema, runtime_cases
from tests.readback import params_class
from tests.support import RosHarness, import_file

OUTPUTS = {case.schema: case for case in all_output_cases()}


def _text(parameter: Parameter) -> str:
    return "; ".join(parameter.constraints)


def _descriptor_text(descriptor: Any) -> str:
    """The constraints a descriptor states: its range fields, then additional_constraints.

    An array's range only mirrors its item bounds (ROS applies it to no item), which
    additional_constraints states in full."""
    parts = []
    array = descriptor.type >= ParameterType.PARAMETER_BYTE_ARRAY
    for ros_range, integer in (
        ([] if array else descriptor.integer_range, True),
        ([] if array else descriptor.floating_point_range, False),
    ):
        for r in ros_range:
            parts.append(RosRange(r.from_value, r.to_value, r.step, integer=integer).describe())
    if descriptor.additional_constraints:
        parts.append(descriptor.additional_constraints)
    return "; ".join(parts)


def _case(case: Path) -> tuple[Schema, OutputCase]:
    schema_path = case_schema(case)
    return load_schema(schema_path), OUTPUTS[schema_path]


@pytest.mark.parametrize("case", case_dirs(), ids=lambda case: case.name)
def test_golden_files_state_the_same_constraints(case: Path) -> None:
    schema, outputs = _case(case)
    module = (case / "expected_params.py").read_text(encoding="utf-8")
    markdown = outputs.golden("markdown").read_text(encoding="utf-8")
    defaults = outputs.golden("defaults").read_text(encoding="utf-8")
    definitions = json.loads(outputs.golden("json-schema").read_text(encoding="utf-8"))["$defs"]
    assert schema.parameters
    for parameter in schema.parameters:
        text, name = _text(parameter), parameter.ros_name
        hover = definitions[_parameter_name(parameter)]["description"]
        assert python_literal(parameter.docstring) in module, name
        if not text:
            assert "Constraints:" not in parameter.docstring, name
            assert "Constraints:" not in hover, name
            continue
        stated = f"Constraints: {text}."
        assert stated in parameter.docstring, name
        assert stated in hover, name
        assert stated in defaults, name
        row = next(line for line in markdown.splitlines() if line.startswith(f"| `{name}` |"))
        assert f"| {'<br>'.join(md_text(c) for c in parameter.constraints)} |" in row, name


@pytest.mark.parametrize("case", case_dirs(), ids=lambda case: case.name)
def test_descriptors_of_the_generated_module_state_the_same_constraints(case: Path) -> None:
    schema, _outputs = _case(case)
    compiled = compile_schema(params_class(import_file(case / "expected_params.py"))._SPEC)
    by_name: dict[str, CompiledParam] = {**compiled.parameters, **compiled.templates}
    for parameter in schema.parameters:
        descriptor = descriptor_for(by_name[parameter.ros_name], parameter.ros_name)
        assert _descriptor_text(descriptor) == _text(parameter), parameter.ros_name


@pytest.mark.parametrize("case", runtime_cases(), ids=lambda case: case.name)
def test_a_real_node_describes_the_same_constraints(ros: RosHarness, case: Path) -> None:
    schema, _outputs = _case(case)
    cls = params_class(import_file(case / "expected_params.py"))
    overrides = case / "overrides.yaml"
    given = {}
    if overrides.exists():
        import yaml

        given = yaml.safe_load(overrides.read_text(encoding="utf-8"))
    types = {p.ros_name: TYPES[p.type.name] for p in schema.parameters}
    node = ros.node(
        parameter_overrides=[
            RosParameter(name, RosParameter.Type(kind.ros_type), kind.to_ros(typed))
            for name, value in given.items()
            for typed in [types[name].coerce_default(value)]
            for kind in [types[name].of_value(typed)]  # a value of type any: its own type
        ]
    )
    cls.declare(node)
    # A parameter whose condition (when) does not hold is not declared: nothing to describe.
    declared = [p for p in schema.parameters if node.has_parameter(p.ros_name)]
    assert len(declared) >= len(schema.parameters) - sum(bool(p.when) for p in schema.parameters)
    descriptors = ros.client(node).describe(*(p.ros_name for p in declared))
    # A node's descriptor also states the rules that read the parameter, after its own.
    reading = compile_schema(cls._SPEC).rules_by_parameter
    for parameter, descriptor in zip(declared, descriptors, strict=True):
        rules = [rule_text(rule) for rule in reading.get(parameter.ros_name, ())]
        expected = "; ".join(filter(None, [_text(parameter), *rules]))
        assert _descriptor_text(descriptor) == expected, parameter.ros_name
