"""The checker compiles whatever a node publishes without trusting it."""

from __future__ import annotations

from typing import Any

import pytest

from genparams.tune.checking import (
    MAX_COMPILED,
    CheckedByNode,
    Checker,
    SchemaMessageError,
    compile_message,
)
from tests.support import RosHarness


def message(*parameters: dict[str, Any], prefix: str = "", **body: Any) -> dict[str, Any]:
    described = {"class": "t", "prefix": prefix, "parameters": list(parameters)}
    return {"classes": [{**described, "maps": [], "rules": [], **body}]}


def param(name: str, type_name: str = "int", **more: Any) -> dict[str, Any]:
    described = {"required": False, "default": 0, "read_only": False, "range": None}
    return {"name": name, "type": type_name, **described, "choices": None, "validators": [], **more}


@pytest.mark.parametrize(
    "bad",
    [
        {"classes": "none"},
        {"node": ["x"]},
        message(param("x", "float32")),
        message(param("x", validators=[["bounds", [3, 1]]])),
        message(param("x", validators=[["no_such_rule", 1]])),
        message(param("x"), rules=[{"name": "r", "check": "y >"}]),
        message(param("x"), prefix="arm"),  # a name outside its class's prefix
        message(param("x", range={"min": "a"})),
    ],
    ids=repr,
)
def test_a_message_that_is_not_a_schema_is_refused_with_a_reason(bad: dict[str, Any]) -> None:
    with pytest.raises(SchemaMessageError):
        compile_message(bad, trusted=())


def test_custom_validators_run_only_from_trusted_modules_that_import() -> None:
    validators = [["custom", "tests.custom_checks:always_raises"]]
    untrusted = compile_message(message(param("x", validators=validators)), trusted=())
    (check,) = untrusted[0].compiled.parameters["x"].checks
    assert isinstance(check, CheckedByNode)
    assert check(1) is None  # not run: the node checks it on apply
    assert "not trusted" in check.describe()
    trusted = compile_message(message(param("x", validators=validators)), ("tests",))
    assert "raised RuntimeError" in str(trusted[0].compiled.parameters["x"].check(1))
    missing = [["custom", "tests.no_such_module:f"]]
    absent = compile_message(message(param("x", validators=missing)), ("tests",))
    (check,) = absent[0].compiled.parameters["x"].checks
    assert isinstance(check, CheckedByNode)
    assert "does not import here" in check.describe()


def test_a_node_with_a_bad_message_is_still_checked_by_its_descriptors(ros: RosHarness) -> None:
    checker = Checker(ros.node())
    current = [{"name": "x", "type": "int", "value": 1, "read_only": False, "range": None}]
    answer = checker.check("/n", {"classes": 5}, current, [("x", "int", 2), ("x", "int", True)])
    assert answer["schema"] is False
    assert "cannot be checked here" in answer["schema_problem"]
    assert answer["reason"] == "x: expected integer, got bool True"
    unknown = checker.check("/n", None, current, [("y", "int", 2)])
    assert unknown["reason"].startswith("Invalid access to undeclared parameter(s)")
    assert not unknown["results"][0]["successful"]


def test_trusted_packages_are_named_alike_for_tune_and_audit() -> None:
    from genparams.cli import build_parser

    for command in ("tune", "audit"):
        args = build_parser().parse_args(
            [command, "--trust-package", "my_robot.checks", "--trust-package", "other"]
        )
        assert args.trust_package == ["my_robot.checks", "other"]
        assert build_parser().parse_args([command]).trust_package == []


def test_compiled_messages_of_nodes_that_come_and_go_stay_bounded(ros: RosHarness) -> None:
    checker = Checker(ros.node())
    for index in range(3 * MAX_COMPILED):
        classes, problem = checker.classes(f"/churn_{index}", message(param("x")))
        assert problem is None and classes[0].param("x") is not None
    assert len(checker.compiled) == MAX_COMPILED
    last = f"/churn_{3 * MAX_COMPILED - 1}"
    assert "/churn_0" not in checker.compiled and last in checker.compiled
