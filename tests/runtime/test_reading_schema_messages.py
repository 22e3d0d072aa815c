"""Reading a schema message as a page or an audit receives it: every message genparams
publishes is accepted, NaN and infinities included; anything else is a problem naming
what is wrong, never an exception."""

from __future__ import annotations

import copy
import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from genparams.runtime.core.json_codec import dumps
from genparams.runtime.core.schema_message import (
    SchemaProblem,
    param_from_json,
    read_schema_message,
)
from genparams.runtime.core.spec import compile_schema
from genparams.runtime.node.schema_topic import class_text, node_message_text
from tests.support import ROOT, load_generated

NODE = "/robot/arm"
SCHEMAS = [
    ROOT / "tests/tune/nonfinite.yaml",
    ROOT / "examples/motion/motion.yaml",
    ROOT / "examples/camera_node/camera_driver.yaml",
    ROOT / "tests/cases/all_types/schema.yaml",
    ROOT / "tests/cases/gpl_features/schema.yaml",
    ROOT / "tests/cases/mapped/schema.yaml",
    ROOT / "tests/cases/rules/schema.yaml",
    ROOT / "tests/cases/validators/schema.yaml",
    ROOT / "tests/cases/conditional/schema.yaml",
]


_TEXTS: dict[Path, str] = {}


def published_text(schema: Path, tmp_path: Path) -> str:
    """The text a node declaring ``schema`` publishes (the publisher's own assembly)."""
    if schema not in _TEXTS:
        module = load_generated(schema, tmp_path)
        spec = next(v._SPEC for v in vars(module).values() if hasattr(v, "_SPEC"))
        _TEXTS[schema] = node_message_text(NODE, [class_text(compile_schema(spec), "")])
    return _TEXTS[schema]


@pytest.mark.parametrize("schema", SCHEMAS, ids=lambda p: p.parent.name)
def test_every_published_message_is_strict_json_and_reads_back(
    schema: Path, tmp_path: Path
) -> None:
    text = published_text(schema, tmp_path)
    json.loads(text, parse_constant=lambda token: pytest.fail(f"{token} in the message"))
    read = read_schema_message(text, NODE)
    assert isinstance(read, dict), read
    assert read["node"] == NODE


def test_non_finite_defaults_and_bounds_read_back_exactly(tmp_path: Path) -> None:
    read = read_schema_message(published_text(SCHEMAS[0], tmp_path), NODE)
    assert isinstance(read, dict)
    params = {p["name"]: p for p in read["classes"][0]["parameters"]}
    assert math.isnan(params["threshold"]["default"])
    assert params["ceiling"]["default"] == math.inf
    assert params["ceiling"]["validators"] == [["bounds", [0.0, math.inf]]]
    assert params["floor"]["default"] == -math.inf
    assert params["gain"]["range"] == {"min": 0.0, "max": math.inf, "step": 0}
    nan, one, minus_inf = params["samples"]["default"]
    assert math.isnan(nan) and one == 1.0 and minus_inf == -math.inf


Edit = Callable[[dict[str, Any]], Any]


def first_param(message: dict[str, Any]) -> dict[str, Any]:
    return dict(message["classes"][0]["parameters"][0])


def set_in_first_param(**fields: Any) -> Edit:
    def edit(message: dict[str, Any]) -> None:
        message["classes"][0]["parameters"][0].update(fields)

    return edit


BAD_EDITS: list[tuple[str, Edit, str]] = [
    ("a list as node", lambda m: m.update(node=["x"]), "message.node: expected a string"),
    ("format 99", lambda m: m.update(format=99), "format 99: this genparams reads format 1"),
    ("format 2", lambda m: m.update(format=2), "format 2: this genparams reads format 1"),
    ("format as text", lambda m: m.update(format="1"), "format a string: this genparams"),
    ("format true", lambda m: m.update(format=True), "format a boolean"),
    ("no format", lambda m: m.pop("format"), "no 'format'"),
    ("classes none", lambda m: m.update(classes="none"), "classes: expected a list, got a string"),
    ("a class as number", lambda m: m.update(classes=[3]), "classes[0]: expected an object"),
    ("another node", lambda m: m.update(node="/robot/other"), "names node '/robot/other'"),
    (
        "float32",
        set_in_first_param(type="float32"),
        "parameters[0] (ceiling).type: unknown type 'float32'",
    ),
    ("required as text", set_in_first_param(required="no"), ".required: expected a boolean"),
    ("default of another type", set_in_first_param(default="high"), "(ceiling): "),
    ("range without max", set_in_first_param(range={"min": 0, "step": 0}), "range: no 'max'"),
    ("range of text", set_in_first_param(range={"min": 0, "max": "9", "step": 0}), "range.max"),
    ("unknown validator", set_in_first_param(validators=[["drop_table", 1]]), "unknown validator"),
    ("validator as text", set_in_first_param(validators=["gt"]), "validators[0]: expected [rule"),
    ("bad validator argument", set_in_first_param(validators=[["gt", "x"]]), "(ceiling): gt"),
    (
        "a pattern that expands to a gigabyte",
        set_in_first_param(validators=[["pattern", "(?:x{2000}){2000}"]]),
        "(ceiling): pattern '(?:x{2000}){2000}' expands to more than 100,000 items",
    ),
    (
        "a pattern the matching engine refuses",
        set_in_first_param(validators=[["pattern", "{s3"]]),
        "(ceiling): expected } at position 2",
    ),
    ("no default", lambda m: m["classes"][0]["parameters"][0].pop("default"), "no 'default'"),
    ("rules as object", lambda m: m["classes"][0].update(rules={}), "rules: expected a list"),
    ("when as a list", set_in_first_param(when=["gain"]), "(ceiling).when: expected a non-empty"),
    ("when without tests", set_in_first_param(when={}), "(ceiling).when: expected a non-empty"),
    ("a test of no values", set_in_first_param(when={"gain": []}), "when.gain: expected a non"),
    (
        "a negation of no values",
        set_in_first_param(when={"gain": {"not": []}}),
        "(ceiling).when.gain.not: expected a non-empty list of booleans, numbers or strings",
    ),
    (
        "a negation with another key",
        set_in_first_param(when={"gain": {"not": [1.0], "or": [2.0]}}),
        "(ceiling).when.gain: a negated test is an object with only 'not'",
    ),
    (
        "an object as a value",
        set_in_first_param(when={"gain": [{"not": [1.0]}]}),
        "(ceiling).when.gain: expected a non-empty list",
    ),
    (
        "a condition on no parameter",
        set_in_first_param(when={"nothing": {"not": [1.0]}}),
        "classes[0]: 'ceiling': when names 'nothing', not a parameter",
    ),
    (
        "a parameter outside the prefix",
        lambda m: m["classes"][0].update(prefix="arm"),
        "classes[0]: 'ceiling' is not under the class prefix 'arm'",
    ),
]


@pytest.mark.parametrize(
    ("edit", "detail"), [e[1:] for e in BAD_EDITS], ids=[e[0] for e in BAD_EDITS]
)
def test_a_malformed_message_is_a_problem_naming_the_field(
    edit: Edit, detail: str, tmp_path: Path
) -> None:
    message = copy.deepcopy(json.loads(published_text(SCHEMAS[0], tmp_path)))
    edit(message)
    read = read_schema_message(dumps(message), NODE)
    assert isinstance(read, SchemaProblem), read
    assert detail in read.detail


@pytest.mark.parametrize(
    ("text", "detail"),
    [
        ('{"node": ["x"]}', "no 'format'"),
        ("[" * 100_000 + "]" * 100_000, "nested 100000 deep, more than the limit of 32"),
        ('{"format": 1, "node": NaN}', "NaN is not JSON"),
        ("not json", "not JSON"),
        ("", "not JSON"),
        ("[1, 2]", "expected an object, got a list"),
        ("null", "expected an object, got null"),
        (" " * (16 << 20) + "{}", "more than the limit"),
    ],
    ids=["list node", "deep", "nan token", "text", "empty", "list", "null", "oversized"],
)
def test_hostile_text_is_a_problem(text: str, detail: str) -> None:
    read = read_schema_message(text, NODE)
    assert isinstance(read, SchemaProblem)
    assert read.detail.startswith("schema message: ")
    assert detail in read.detail


def test_conditions_read_back_as_the_node_declared_them(tmp_path: Path) -> None:
    schema = ROOT / "tests/cases/conditional/schema.yaml"
    read = read_schema_message(published_text(schema, tmp_path), NODE)
    assert isinstance(read, dict), read
    described = {p["name"]: p for p in read["classes"][0]["parameters"]}
    assert described["gain"]["when"] == {"mode": ["advanced", "expert"]}
    assert described["lease_rate"]["when"] == {"mode": {"not": ["expert"]}}
    spec = next(
        v._SPEC for v in vars(load_generated(schema, tmp_path)).values() if hasattr(v, "_SPEC")
    )
    declared = {param.name: param for param in spec.parameters}
    for name, param in described.items():
        reread = param_from_json(param, name)
        assert reread.when == declared[name].when, name
        for mode in ("basic", "advanced", "expert"):
            values = {"mode": mode, "use_filter": False}
            assert reread.declared_with(values) == declared[name].declared_with(values)
    assert not param_from_json(described["lease_rate"], "lease_rate").declared_with(
        {"mode": "expert"}
    )
