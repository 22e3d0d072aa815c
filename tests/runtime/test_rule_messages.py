"""A refused rule check says exactly why and where: kinds in words, arrays named by their
items, the column counted from the check as written (leading blanks and line breaks
included), and literal lists of each kind the language has."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

import genparams
from genparams.runtime.expressions import RuleError, compile_expression
from genparams.runtime.rules import compile_rule
from genparams.schema.errors import SchemaError

TYPES = {
    "width": "int",
    "ratio": "double",
    "enabled": "bool",
    "mode": "string",
    "topics": "string_array",
    "weights": "double_array",
    "flags": "bool_array",
    "camera.fps": "double",
}
VALUES: dict[str, Any] = {
    "width": 640,
    "ratio": 1.5,
    "enabled": True,
    "mode": "fast",
    "topics": ("/a", "/b"),
    "weights": (0.25, 0.75),
    "flags": (True, False),
    "camera.fps": 30.0,
}


@pytest.mark.parametrize(
    ("check", "message"),
    [
        (
            "mode in weights",
            "'in' needs an item and an array of its kind (or two strings), "
            "not a string and an array of number (at character 1)",
        ),
        (
            "flags == topics",
            "== compares values of one kind, not an array of bool and an array of string "
            "(at character 1)",
        ),
        ("topics", "a check must be true or false (a comparison, say), not an array of string"),
        (
            "(weights if enabled else topics) == topics",
            "both branches of 'if' must be of one kind, not an array of number and an array "
            "of string (at character 2)",
        ),
        ("", "a check cannot be empty"),
        (" \n\r ", "a check cannot be empty"),
        (
            "() == ()",
            "a literal list needs at least one item, all numbers, strings or bools "
            "(at character 1)",
        ),
        (
            "camera.fps.real > 0",
            "'camera.fps.real' is not a parameter: attribute access is not allowed "
            "('camera.fps' is a parameter) (at character 1)",
        ),
        (
            "width.real > 0",
            "'width.real' is not a parameter: attribute access is not allowed "
            "('width' is a parameter) (at character 1)",
        ),
    ],
)
def test_refused_checks_give_the_whole_reason(check: str, message: str) -> None:
    with pytest.raises(RuleError) as caught:
        compile_rule("r", check, "", TYPES)
    assert str(caught.value) == message


@pytest.mark.parametrize(
    ("check", "offset"),
    [
        ("widht > 0", 0),
        ("   widht > 0", 3),
        ("\n  widht > 0", 3),
        ("width > 0 and\n  widht > 0", 16),
        ("  width > 0 and\n widht > 0", 17),
        ("width > 0 and\r\n widht > 0", 16),
        ("\r\nwidht > 0", 2),
    ],
)
def test_the_column_counts_leading_blanks_and_line_breaks(check: str, offset: int) -> None:
    with pytest.raises(RuleError) as caught:
        compile_rule("r", check, "", TYPES)
    assert caught.value.offset == offset
    assert check.replace("\r", " ").replace("\n", " ")[offset:].startswith("widht")
    assert str(caught.value) == (
        f"unknown parameter 'widht' (did you mean 'width'?) (at character {offset + 1})"
    )


@pytest.mark.parametrize(
    ("check", "expected"),
    [
        ("width in (640, 480)", True),
        ("ratio in [0.5, 1]", False),
        ("enabled in (true, false)", True),
        ("flags == (true, false)", True),
        ("flags == [false, false]", False),
        ("weights == (0.25, 0.75)", True),
        ("mode in ('fast', 'slow')", True),
        ("topics == ['/a']", False),
    ],
)
def test_literal_lists_of_each_kind_are_accepted(check: str, expected: bool) -> None:
    rule = compile_rule("r", check, "", TYPES)
    assert rule.expression.evaluate(VALUES) is expected


def test_a_check_of_the_maximum_length_is_accepted() -> None:
    check = "width > 0"
    check += " " * (2000 - len(check))
    assert compile_rule("r", check, "", TYPES).expression.evaluate(VALUES) is True
    with pytest.raises(RuleError, match=r"^a check is limited to 2000 characters$"):
        compile_rule("r", check + " ", "", TYPES)


def test_a_bad_check_is_reported_beside_a_parameter_left_out(tmp_path: Path) -> None:
    schema = tmp_path / "demo.yaml"
    schema.write_text(
        "genparams: 1\nname: demo\nparameters:\n"
        '  "": {type: int, default: 1}\n'
        "  speed: {type: int, default: 1}\n"
        'rules:\n  - {name: r, check: "speed <"}\n'
    )
    with pytest.raises(SchemaError) as caught:
        genparams.generate(schema)
    assert str(caught.value).splitlines()[1:] == [
        f"{schema}:7:22: rules[0].check: invalid expression: invalid syntax"
    ]


@pytest.mark.parametrize(
    ("check", "message"),
    [
        ("width <", "invalid expression: invalid syntax"),
        ("width < (1", "invalid expression: '(' was never closed (at character 9)"),
        ("  width < (1", "invalid expression: '(' was never closed (at character 11)"),
        ("-" * 1990 + "width > 0", "invalid expression: too deeply nested"),
    ],
)
def test_invalid_expressions_say_where_they_can(check: str, message: str) -> None:
    with pytest.raises(RuleError) as caught:
        compile_rule("r", check, "", TYPES)
    assert str(caught.value) == message


def test_an_expression_keeps_the_check_as_written() -> None:
    text = " width >\n  0"
    expression = compile_expression(text, TYPES)
    assert (expression.text, expression.kind, expression.parameters) == (text, "bool", ("width",))
