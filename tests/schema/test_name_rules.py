"""Name rules live in runtime.naming; the JSON Schemas that restate them must agree."""

from __future__ import annotations

import json
import re

import jsonschema

from genparams.outputs.json_schema import NODE_KEY_PATTERN
from genparams.outputs.schema_paths import ENTRY_KEY_PATTERN
from genparams.runtime.core import naming
from genparams.schema.resources import resource_dir
from genparams.schema.shape import is_parameter


def test_schema_file_json_schema_states_the_schema_and_rule_name_rules() -> None:
    path = resource_dir("schemas") / "genparams.schema.json"
    document = json.loads(path.read_text(encoding="utf-8"))
    assert document["properties"]["name"]["pattern"] == f"^{naming.SCHEMA_NAME.pattern}$"
    rule_name = document["$defs"]["rule"]["properties"]["name"]["pattern"]
    assert rule_name == f"^{naming.RULE_NAME.pattern}$"


def test_params_file_json_schema_patterns_agree_with_naming() -> None:
    samples = ["left-arm", "1st", "a_b", "", "a.b", "a b", "*", "é"]
    for key in samples:
        expected = naming.is_entry_key(key)
        assert (re.search(ENTRY_KEY_PATTERN, key) is not None) == expected, key
    nodes = ["/ns/camera", "camera", "/**", "/*/cam", "/ns//cam", "/1ns/cam", "/ns/cam-1"]
    for node in nodes:
        accepted = naming.node_pattern_problem(node) is None
        assert (re.search(NODE_KEY_PATTERN, node) is not None) == accepted, node
    jsonschema.Draft202012Validator.check_schema({"pattern": NODE_KEY_PATTERN})


def test_schema_file_json_schema_tells_parameters_from_namespaces_as_the_model_does() -> None:
    """A mapping whose `type:` holds a mapping is a namespace, in both."""
    path = resource_dir("schemas") / "genparams.schema.json"
    document = json.loads(path.read_text(encoding="utf-8"))
    condition = {**document["$defs"]["node"]["if"], "$schema": document["$schema"]}
    samples: list[object] = [
        {"type": "int"},
        {"type": "strng"},
        {"type": [1]},
        {"type": None},
        {"type": {"type": "string"}},
        {"type": {}},
        {"open": True},
        {"mode": {"type": "int"}},
        3,
    ]
    for sample in samples:
        as_leaf = jsonschema.Draft202012Validator(condition).is_valid(sample)
        assert as_leaf == is_parameter(sample), sample
