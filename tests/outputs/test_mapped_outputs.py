"""Params-file tools on mapped groups and old names: JSON Schema, docs, defaults."""

from __future__ import annotations

import jsonschema
import pytest
import yaml

from genparams.api import load_schema
from genparams.outputs.docs_model import docs_page
from genparams.outputs.json_schema import params_file_schema
from tests.golden import OUTPUT_CASES

SCHEMA = OUTPUT_CASES / "mapped" / "schema.yaml"


@pytest.fixture(scope="module")
def validator() -> jsonschema.Draft202012Validator:
    document = params_file_schema(load_schema(SCHEMA), partial=True)
    jsonschema.Draft202012Validator.check_schema(document)
    return jsonschema.Draft202012Validator(document)


def errors(validator: jsonschema.Draft202012Validator, params: str) -> list[str]:
    data = {"/**": {"ros__parameters": yaml.safe_load(params)}}
    return sorted(f"{error.validator}: {error.message}" for error in validator.iter_errors(data))


@pytest.mark.parametrize(
    "params",
    [
        "gains: {wrist: {p: 2.0, limits: {effort: 1.0}, tips: {pinky: {force: 1.0}}}}",
        "gains.wrist.p: 2.0",
        "gains.wrist.limits.effort: 1.0",
        "gains: {wrist.tips.pinky.force: 1.0}",
        "gains.wrist: {tips: {pinky.force: 1.0}}",
        "gains: {wrist.tips: {pinky: {force: 1.0}}}",
        "tool: {hammer: {weight: 0.5}}",
        "joints: [left, right_2]",
        "joints: [left-arm, 1st]",
        "gains: {left-arm: {p: 2.0}, 1st: {tips: {index-2: {force: 1.0}}}}",
        "gains.left-arm.limits.effort: 1.0",
        "speed_limit: 2.0",
        "limits: {speed: 2.0}",
        "limits.speed: 2.0",
        "camera: {rate: 30.0, fps: 30.0}",
        "camera.rate: 30.0",
        "frame_rate: 30.0",
    ],
)
def test_entries_for_any_key_and_old_names_validate(
    validator: jsonschema.Draft202012Validator, params: str
) -> None:
    assert errors(validator, params) == []


@pytest.mark.parametrize(
    ("params", "expected"),
    [
        ("gains: {left arm: {p: 1.0}}", "additionalProperties: 'left arm' does not match"),
        ("gains: {wrist: {q: 1.0}}", "additionalProperties: 'q' does not match"),
        ("gains.wrist.q: 1.0", "additionalProperties: 'gains.wrist.q' does not match"),
        ("gains: {wrist: {p: -1.0}}", "minimum: -1.0 is less than the minimum of 0.0"),
        ("gains.wrist.limits.effort: 9.0", "maximum: 9.0 is greater than the maximum of 5.0"),
        ("joints: [a, a]", "uniqueItems: ['a', 'a'] has non-unique elements"),
        ("joints: [left.arm]", "pattern: 'left.arm' does not match"),
        (
            "limits: {sped: 1.0}",
            "additionalProperties: Additional properties are not allowed ('sped'",
        ),
        ("speed_limit: 9.0", "maximum: 9.0 is greater than the maximum of 3.0"),
    ],
)
def test_mistakes_in_entries_and_old_names_are_flagged(
    validator: jsonschema.Draft202012Validator, params: str, expected: str
) -> None:
    (error,) = errors(validator, params)
    assert error.startswith(expected)


def test_old_names_are_marked_deprecated() -> None:
    group = params_file_schema(load_schema(SCHEMA))["$defs"]["group"]["properties"]
    assert group["speed_limit"] == {
        "$ref": "#/$defs/param.max_speed",
        "deprecated": True,
        "description": "Old name of max_speed: write max_speed.",
    }
    assert group["limits"]["properties"]["speed"]["deprecated"] is True


def test_docs_name_the_key_parameter_and_old_names() -> None:
    page = docs_page(load_schema(SCHEMA))
    by_name = {ns.name: ns for ns in page.namespaces}
    assert (
        by_name["gains"].note == "One entry per item of joints; in the names below, * is the item."
    )
    assert [p.name for p in by_name["gains.*.tips"].parameters] == ["gains.*.tips.*.force"]
    (max_speed,) = [p for p in by_name[""].parameters if p.name == "max_speed"]
    assert max_speed.old_names == "speed_limit, limits.speed"
    (joints,) = [p for p in by_name[""].parameters if p.name == "joints"]
    assert joints.constraints == (
        "each item names an entry of gains: any text but '.', '*', spaces and control "
        "characters; no repeats",
    )
