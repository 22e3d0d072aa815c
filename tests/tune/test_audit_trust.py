"""The audit runs a custom validator named by a schema message only from a trusted package:
any node can publish a message naming `os:system`."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from genparams.audit.findings import NOT_CHECKED, VIOLATION
from genparams.audit.schema_checks import check_node
from genparams.runtime.core.json_codec import dumps
from genparams.runtime.core.schema_message import read_schema_message

NODE = "/probe"


def message(type_name: str, default: Any, custom: Any) -> dict[str, Any]:
    """A message of one parameter ``p`` with one custom validator, read as a tool reads it."""
    parameter = {
        "name": "p",
        "type": type_name,
        "required": False,
        "default": default,
        "description": "",
        "unit": "",
        "read_only": False,
        "range": None,
        "choices": None,
        "validators": [["custom", custom]],
        "constraints": [],
        "additional_constraints": "",
        "deprecated": "",
        "aliases": [],
    }
    described = {"class": "probe", "prefix": "", "hash": "0", "parameters": [parameter]}
    text = dumps(
        {
            "format": 1,
            "genparams": "0",
            "hash": "0",
            "node": NODE,
            "classes": [described | {"maps": [], "rules": []}],
        }
    )
    read = read_schema_message(text, NODE)
    assert isinstance(read, dict), read
    return read


def test_a_custom_validator_of_an_untrusted_package_is_not_run(tmp_path: Path) -> None:
    marker = tmp_path / "ran"
    schema = message("string", "", "os:system")
    findings = check_node(NODE, schema, {"p": f"touch '{marker}'"})
    assert not marker.exists()
    assert [(f.kind, f.parameter) for f in findings if f.kind != "drift-from-default"] == [
        (NOT_CHECKED, "p")
    ]
    assert "not trusted (--trust-package os)" in findings[0].detail


def test_a_custom_validator_of_a_trusted_package_runs() -> None:
    schema = message("int", 2, "tests.custom_checks:is_even")
    untrusted = check_node(NODE, schema, {"p": 3})
    assert {f.kind for f in untrusted} == {NOT_CHECKED, "drift-from-default"}
    for packages in (("tests",), ("tests.custom_checks",)):
        findings = check_node(NODE, schema, {"p": 3}, packages)
        assert [(f.kind, f.detail) for f in findings if f.kind == VIOLATION] == [
            (VIOLATION, "3 is odd (tests.custom_checks:is_even)")
        ]
    # A package's name is whole: `test` does not trust `tests`.
    assert VIOLATION not in {f.kind for f in check_node(NODE, schema, {"p": 3}, ("test",))}
