"""The validator names have one table, ``runtime.validators.KINDS``: the JSON Schema that
checks schema files and the JSON Schema keywords of params files must agree with it."""

from __future__ import annotations

import json
from typing import Any

from genparams.outputs.json_schema import _KEYWORD_BUILDERS
from genparams.runtime.core.validator_kinds import KINDS, build_validator
from genparams.runtime.core.validators import Custom
from genparams.schema.resources import resource_dir

SAMPLE_ARGUMENTS: dict[str, Any] = {
    "gt": 0,
    "ge": 0,
    "lt": 1,
    "le": 1,
    "bounds": (0, 1),
    "element_bounds": (0, 1),
    "one_of": ("a",),
    "subset_of": ("a",),
    "not_empty": None,
    "unique": None,
    "length": 2,
    "pattern": "^a",
    "custom": "package.module:function",
}


def _validator_schema() -> dict[str, Any]:
    path = resource_dir("schemas") / "genparams.schema.json"
    return json.loads(path.read_text(encoding="utf-8"))["$defs"]["validator"]  # type: ignore[no-any-return]


def test_schema_file_json_schema_names_every_validator_and_no_other() -> None:
    bare, with_argument = _validator_schema()["anyOf"]
    assert set(with_argument["propertyNames"]["enum"]) == set(KINDS)
    assert set(bare["enum"]) == {name for name, kind in KINDS.items() if not kind.takes_argument}


def test_every_validator_has_params_file_json_schema_keywords() -> None:
    assert set(SAMPLE_ARGUMENTS) == set(KINDS)
    for name, kind in KINDS.items():
        param_type = sorted(kind.applies_to)[0]
        validator = build_validator(name, SAMPLE_ARGUMENTS[name], param_type)
        # A custom check runs user code: no keyword can state it, the hover text does.
        assert type(validator) in _KEYWORD_BUILDERS or isinstance(validator, Custom), name
