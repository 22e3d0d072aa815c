"""genparams json-schema: a valid 2020-12 schema that accepts the defaults and flags mistakes."""

from __future__ import annotations

import io
import json
from collections.abc import Iterator
from contextlib import redirect_stdout
from pathlib import Path
from typing import Any

import jsonschema
import pytest
import yaml

from genparams.api import load_schema
from genparams.cli import main
from genparams.outputs.json_schema import params_file_schema
from genparams.outputs.params_file import default_params_file
from genparams.outputs.render import render_params_file
from tests.golden import CASES, CHECK_PARAMS, EXAMPLE_SCHEMA, output_cases


def _validator(schema_path: Path, *, partial: bool = False) -> jsonschema.Draft202012Validator:
    document = params_file_schema(load_schema(schema_path), partial=partial)
    jsonschema.Draft202012Validator.check_schema(document)
    return jsonschema.Draft202012Validator(document)


def _errors(validator: jsonschema.Draft202012Validator, text: str) -> list[tuple[str, str]]:
    data = yaml.safe_load(text)
    return sorted(
        (".".join(str(p) for p in error.absolute_path), error.validator)
        for error in validator.iter_errors(data)
    )


def _file(params: str, node: str = "/**") -> str:
    body = "".join(f"    {line}\n" for line in params.strip().splitlines())
    return f"{node}:\n  ros__parameters:\n{body}"


@pytest.mark.parametrize("case", output_cases(), ids=lambda case: case.name)
def test_defaults_file_validates(case: Any) -> None:
    schema = load_schema(case.schema)
    defaults = render_params_file(default_params_file(schema))
    # As written, required parameters are missing: only a partial file is complete.
    assert _errors(_validator(case.schema, partial=True), defaults) == []
    missing = _errors(_validator(case.schema), defaults)
    assert missing and all(error[1] in ("required", "anyOf") for error in missing)


def test_complete_file_validates_and_mistakes_are_flagged() -> None:
    validator = _validator(EXAMPLE_SCHEMA)
    good = """
serial: ABCD1234
use_sim_time: true
camera:
  fps: 60.0
camera.width: 1280
control.pid: {kp: 2.0}
control: {pid.kd: 0.5}
topics: [/a, /b]
qos_overrides./tf.publisher.depth: 10
"""
    assert _errors(validator, _file(good, "/robot/camera_driver")) == []
    assert _errors(validator, _file("serial: ABCD1234\ncamera:\n  fsp: 30.0")) == [
        ("/**.ros__parameters.camera", "additionalProperties")
    ]
    assert _errors(validator, _file('serial: ABCD1234\ncamera.width: "640"')) == [
        ("/**.ros__parameters.camera.width", "type")
    ]
    assert _errors(validator, _file("serial: ABCD1234\ncamera: {fps: 500.0, width: 10}")) == [
        ("/**.ros__parameters.camera.fps", "maximum"),
        ("/**.ros__parameters.camera.width", "minimum"),
    ]
    assert _errors(validator, _file("serial: abc\ncamera.encoding: yuv\ntopics: []")) == [
        ("/**.ros__parameters.camera.encoding", "enum"),
        ("/**.ros__parameters.serial", "pattern"),
        ("/**.ros__parameters.topics", "minItems"),
    ]
    assert _errors(validator, _file("serial: ABCD1234", "/**")) == []
    assert _errors(validator, "/**:\n  ros_parameters:\n    serial: ABCD1234\n") == [
        ("/**", "additionalProperties"),
        ("/**", "required"),
    ]
    assert _errors(validator, _file("serial: ABCD1234", "/robot/camera-1")) == [("", "pattern")]


def test_required_parameter_in_a_namespace_may_be_nested_or_dotted(tmp_path: Path) -> None:
    schema = tmp_path / "s.yaml"
    schema.write_text(
        "genparams: 1\nname: s\nparameters:\n  a:\n    b:\n      c: {type: int}\n", "utf-8"
    )
    validator = _validator(schema)
    for spelling in ("a.b.c: 1", "a: {b.c: 1}", "a.b: {c: 1}", "a: {b: {c: 1}}"):
        assert _errors(validator, _file(spelling)) == [], spelling
    assert _errors(validator, _file("a: {b: {}}")) != []
    assert _errors(validator, _file("a.b: {}")) != []


def test_descriptions_carry_hover_text_and_defaults() -> None:
    document = params_file_schema(load_schema(EXAMPLE_SCHEMA))
    fps = document["$defs"]["param.camera.fps"]
    assert fps["type"] == "number" and fps["default"] == 30.0
    assert fps["minimum"] == 1.0 and fps["maximum"] == 120.0
    assert fps["description"] == (
        "Frame rate.\nUnit: Hz. Constraints: within [1.0, 120.0] in steps of 0.5.\n"
        "Type: double. Write a decimal point (30.0, not 30): ROS does not convert. Default: 30.0."
    )
    topics = document["$defs"]["param.topics"]
    assert topics["items"] == {"type": "string", "pattern": "^/"}
    assert topics["uniqueItems"] is True and topics["minItems"] == 1


def test_command_prints_json(capsys: pytest.CaptureFixture[str]) -> None:
    out = io.StringIO()
    with redirect_stdout(out):
        assert main(["json-schema", str(EXAMPLE_SCHEMA), "--partial"]) == 0
    document = json.loads(out.getvalue())
    assert document["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    assert "required" not in document["$defs"]["group"]


def test_names_holding_dashes_slashes_and_type_are_checked_by_their_own_definitions() -> None:
    """`input_shape/height` is a `$defs` name holding '/': its `$ref` escapes it (`~1`)."""
    case = CASES / "ros_names"
    validator = _validator(case / "schema.yaml")
    good = (case / CHECK_PARAMS / "ros_names_good" / "params.yaml").read_text("utf-8")
    assert _errors(validator, good) == []
    bad = (case / CHECK_PARAMS / "ros_names_bad" / "params.yaml").read_text("utf-8")
    prefix = "/**.ros__parameters."
    assert _errors(validator, bad) == [
        ("/**.ros__parameters", "additionalProperties"),  # max_speed
        (f"{prefix}buttons.deadman-switch.button-id", "type"),
        (f"{prefix}input_shape/height", "minimum"),
        (f"{prefix}walk_button.axis_mappings", "additionalProperties"),  # twist_angular_z
        (f"{prefix}walk_button.axis_mappings.twist-linear-x.axis", "type"),
        (f"{prefix}walk_button.type", "enum"),
    ]
    document = params_file_schema(load_schema(case / "schema.yaml"))
    refs = [v for k, v in _walk(document) if k == "$ref"]
    assert "#/$defs/param.input_shape~1height" in refs
    patterns = [v for k, v in _walk(document) if k == "pattern"]
    patterns += [p for k, v in _walk(document) if k == "patternProperties" for p in v]
    assert patterns and not any("\\-" in p for p in patterns)  # ECMAScript's unicode mode


def _walk(value: Any) -> Iterator[tuple[str, Any]]:
    if isinstance(value, dict):
        for key, item in value.items():
            yield key, item
            yield from _walk(item)
    elif isinstance(value, list):
        for item in value:
            yield from _walk(item)
