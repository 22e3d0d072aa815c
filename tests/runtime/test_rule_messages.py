"""A refused rule check says exactly why and where: kinds in words, arrays named by their
items, the column counted from the check as written (leading blanks and line breaks
included), and literal lists of each kind the language has."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

import genparams
from genparams.runtime.core.expressions import RuleError, compile_expression
from genparams.runtime.core.rules import compile_rule
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
    "blob": "byte_array",
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
    "blob": b"ab",
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
        ("640 in (width, 1) and (ratio, 2.0) == (1.5, 2)", True),
        ("mode in mode and 'as' in mode", True),
        ("'fast' not in mode", False),
        ("(width if enabled else ratio) > 1", True),
        ("(width if not enabled else ratio) > 100", False),
        ("len(blob) == 2 and len(mode) == 4 and len(flags) == 2", True),
        ("width not in weights", True),
        ("weights != (0.25, 0.75)", False),
        ("-width < 0 and +width > 0 and -(-ratio) == ratio", True),
        ("min(weights) == 0.25 and max(weights) == 0.75", True),
        ("min(width, ratio, 3) == ratio and max(1, width) == 640", True),
        ("abs(-ratio) == ratio and abs(width - 641) == 1", True),
        ("enabled and width > 600 and ratio > 1", True),
        ("enabled and width > 600 and ratio > 2", False),
        ("not enabled or ratio > 2", False),
        ("not (width < 0)", True),
        ("not enabled or ratio > 2 or mode == 'fast'", True),
        ("1 < width < 1000 > ratio", True),
        ("0 < width < 1000", True),
        ("0 < width < 10", False),
        ("1 < width < 100 > ratio", False),
        ("width // 100 == 6 and width % 100 == 40 and width / 64 == 10", True),
        ("width * 2 - 80 == 1200 and width + 0.5 == 640.5", True),
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


def test_a_bad_check_is_reported_beside_a_bad_name(tmp_path: Path) -> None:
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
    rule = compile_rule("wide", text, "Wide enough.", TYPES)
    assert (rule.name, rule.check, rule.description) == ("wide", text, "Wide enough.")


@pytest.mark.parametrize(
    ("check", "message"),
    [
        ("1j == width", "rules cannot use the constant 1j (at character 1)"),
        (
            "'a'.x > 0",
            "attribute access is not allowed: only dotted parameter names such as a.b (at "
            "character 1)",
        ),
        ("width + mode > 0", "the operator + needs a number, not a string (at character 9)"),
        ("+mode > 0", "unary minus or plus needs a number, not a string (at character 2)"),
        ("-enabled < 0", "unary minus or plus needs a number, not true/false (at character 2)"),
        ("~width > 0", "rules cannot use the operator ~ (at character 1)"),
        ("not mode", "'not' needs true/false, not a string (at character 5)"),
        ("mode and enabled", "'and' needs true/false, not a string (at character 1)"),
        ("enabled or width", "'or' needs true/false, not a number (at character 12)"),
        ("len() > 0", "len() takes one string or array, not nothing (at character 1)"),
        (
            "len(width, mode) > 0",
            "len() takes one string or array, not a number, a string (at character 1)",
        ),
        (
            "min() > 0",
            "min() takes two or more numbers, or one array of numbers, not nothing (at "
            "character 1)",
        ),
        (
            "max(width, mode) > 0",
            "max() takes two or more numbers, or one array of numbers, not a number, a "
            "string (at character 1)",
        ),
        (
            "abs(width, width) > 0",
            "abs() takes one number, not a number, a number (at character 1)",
        ),
        ("max(*topics) > 0", "max() takes plain positional arguments (at character 1)"),
        (
            "width.foo() > 0",
            "rules cannot call methods: the functions are abs, len, max, min (at character 1)",
        ),
        (
            "print(width)",
            "rules cannot call 'print': the functions are abs, len, max, min (at character 1)",
        ),
        (
            "width < mode",
            "< compares two numbers or two strings, not a number and a string (at character 1)",
        ),
        (
            "enabled < enabled",
            "< compares two numbers or two strings, not true/false and true/false (at character 1)",
        ),
        (
            "topics < topics",
            "< compares two numbers or two strings, not an array of string and an array of "
            "string (at character 1)",
        ),
        (
            "width in mode",
            "'in' needs an item and an array of its kind (or two strings), not a number and "
            "a string (at character 1)",
        ),
        ("width @ width > 0", "rules cannot use the operator @ (at character 1)"),
        ("width | 1 > 0", "rules cannot use the operator | (at character 1)"),
        ("width is not 1", "rules cannot use 'is not' (use !=) (at character 1)"),
        ("lambda: 1", "rules cannot use lambda (at character 1)"),
        ('f"{width}" == mode', "rules cannot use f-strings (at character 1)"),
        ("{1} == {1}", "rules cannot use set literals (at character 1)"),
        ("(x for x in topics) == 1", "rules cannot use comprehensions (at character 1)"),
        ("width[0:1] == 1", "rules cannot use indexing (at character 1)"),
        (
            "ratio if width else ratio",
            "the condition of 'if' needs true/false, not a number (at character 10)",
        ),
        ('1 == "1"', "== compares values of one kind, not a number and a string (at character 1)"),
        (
            "(true, 1) == (true, 1)",
            "a literal list needs at least one item, all numbers, strings or bools (at "
            "character 1)",
        ),
        ("fps > 0", "unknown parameter 'fps' (at character 1)"),
        (
            "camera.fsp > 0",
            "unknown parameter 'camera.fsp' (did you mean 'camera.fps'?) (at character 1)",
        ),
        ("min > 0", "'min' is a function: call it, as in min(...) (at character 1)"),
    ],
)
def test_each_construct_is_refused_with_its_reason(check: str, message: str) -> None:
    with pytest.raises(RuleError) as caught:
        compile_rule("r", check, "", TYPES)
    assert str(caught.value) == message


def test_a_rule_reading_a_parameter_left_out_is_not_reported_again(tmp_path: Path) -> None:
    schema = tmp_path / "demo.yaml"
    schema.write_text(
        "genparams: 1\nname: demo\nparameters:\n"
        "  speed: {type: integer, default: 1}\n"
        "  limit: {type: int, default: 3}\n"
        'rules:\n  - {name: r, check: "speed < limit"}\n'
    )
    with pytest.raises(SchemaError) as caught:
        genparams.generate(schema)
    assert str(caught.value).splitlines() == [
        f"{schema}:4:17: parameters.speed.type: 'integer' is not one of bool, int, double, "
        "string, byte_array, bool_array, int_array, double_array, string_array, any "
        "(did you mean 'int'?)"
    ]
