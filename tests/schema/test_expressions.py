"""The rule expression language: what it accepts, what it refuses, what it means."""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from genparams.runtime.core.expressions import RuleError, compile_expression
from genparams.runtime.core.rules import compile_rule

TYPES = {
    "width": "int",
    "height": "int",
    "aspect_ratio": "double",
    "min_speed": "double",
    "max_speed": "double",
    "enabled": "bool",
    "mode": "string",
    "topics": "string_array",
    "weights": "double_array",
    "flags": "bool_array",
    "blob": "byte_array",
    "camera.fps": "double",
    "camera.from": "int",
}
VALUES: dict[str, Any] = {
    "width": 640,
    "height": 480,
    "aspect_ratio": 1.3333,
    "min_speed": 0.5,
    "max_speed": 2.0,
    "enabled": True,
    "mode": "fast",
    "topics": ("/a", "/b"),
    "weights": (0.25, 0.75),
    "flags": (True, False),
    "blob": b"\x01\x02",
    "camera.fps": 30.0,
    "camera.from": 3,
}


@pytest.mark.parametrize(
    ("check", "expected", "reads"),
    [
        ("abs(aspect_ratio - width / height) <= 0.01", True, ("aspect_ratio", "width", "height")),
        ("min_speed <= max_speed", True, ("min_speed", "max_speed")),
        ("len(topics) == len(weights)", True, ("topics", "weights")),
        ("0 < min_speed <= max_speed < 1", False, ("min_speed", "max_speed")),
        ("camera.fps >= 60 if enabled else true", False, ("enabled", "camera.fps")),
        ("not enabled or camera.fps > 10", True, ("enabled", "camera.fps")),
        ("camera.from_ == 3", True, ("camera.from",)),
        ("'/a' in topics and '/c' not in topics", True, ("topics",)),
        ("mode in ('fast', 'slow')", True, ("mode",)),
        ("mode in ['slow']", False, ("mode",)),
        ("'as' in mode", True, ("mode",)),
        ("max(weights) <= 1.0 and min(weights) >= 0", True, ("weights",)),
        ("max(width, height, 100) == 640 and min(width, height) == 480", True, ("width", "height")),
        ("len(blob) == 2 and len(flags) == 2 and len(mode) == 4", True, ("blob", "flags", "mode")),
        ("width % 3 == 1 and width // 3 == 213 and -width < +height", True, ("width", "height")),
        ("enabled == True and (enabled != false)", True, ("enabled",)),
        ("mode >= 'fast'", True, ("mode",)),
        ("min_speed\n  <= max_speed", True, ("min_speed", "max_speed")),
        ("  width > height", True, ("width", "height")),
    ],
)
def test_accepted_checks_evaluate(check: str, expected: bool, reads: tuple[str, ...]) -> None:
    rule = compile_rule("r", check, "", TYPES)
    assert rule.parameters == reads
    assert rule.expression.evaluate(VALUES) is expected
    assert (rule.violation(VALUES) is None) is expected


@pytest.mark.parametrize(
    ("check", "message"),
    [
        ("width <", "invalid expression: invalid syntax"),
        ("width < (1", "invalid expression: '(' was never closed (at character 9)"),
        ("widht > 0", "unknown parameter 'widht' (did you mean 'width'?) (at character 1)"),
        ("camera > 0", "unknown parameter 'camera' (did you mean 'camera.fps'?) (at character 1)"),
        ("width > 0 and camera.from > 0", "invalid expression: invalid syntax (at character 22)"),
        ("width.real > 0", "'width.real' is not a parameter: attribute access is not allowed"),
        ("len > 0", "'len' is a function: call it, as in len(...) (at character 1)"),
        ("width", "a check must be true or false (a comparison, say), not a number"),
        ("len(width) > 0", "len() takes one string or array, not a number (at character 1)"),
        ("abs(mode) > 0", "abs() takes one number, not a string (at character 1)"),
        (
            "min(width) > 0",
            "min() takes two or more numbers, or one array of numbers, not a number",
        ),
        ("max(topics) == 'a'", "max() takes two or more numbers, or one array of numbers"),
        ("abs(x=1) > 0", "abs() takes plain positional arguments (at character 1)"),
        ("mode < 3", "< compares two numbers or two strings, not a string and a number"),
        ("enabled == 1", "== compares values of one kind, not true/false and a number"),
        ("mode in weights", "'in' needs an item and an array of its kind (or two strings)"),
        ("mode + 'x' == 'y'", "the operator + needs a number, not a string (at character 1)"),
        ("not width", "'not' needs true/false, not a number (at character 5)"),
        ("width and enabled", "'and' needs true/false, not a number (at character 1)"),
        ("(width if enabled else mode) == 1", "both branches of 'if' must be of one kind"),
        ("width if width else height", "the condition of 'if' needs true/false, not a number"),
        ("() == ()", "a literal list needs at least one item, all numbers, strings or bools"),
        ("(1, 'a') == (1, 'a')", "a literal list needs at least one item"),
        ("None == None", "rules cannot use the constant None (at character 1)"),
        ("b'x' == blob", "rules cannot use the constant b'x' (at character 1)"),
        ("width is 1", "rules cannot use 'is' (use ==)"),
        ("width ** 2 > 1", "rules cannot use the operator ** (at character 1)"),
        ("width << 2 > 1", "rules cannot use the operator <<"),
        ("~width > 1", "rules cannot use the operator ~"),
        ("topics[0] == '/a'", "rules cannot use indexing (at character 1)"),
        ("{1: 2} == {1: 2}", "rules cannot use dict literals"),
        ("(x := 1) == 1", "rules cannot use ':='"),
        ("[t for t in topics] == []", "rules cannot use comprehensions"),
        ("__import__('os') == 1", "rules cannot call '__import__': the functions are abs, len"),
        ("width.__class__ == 1", "'width.__class__' is not a parameter"),
        ("''.join(topics) == ''", "rules cannot call methods: the functions are abs, len, max"),
        ("", "a check cannot be empty"),
        ("width > 0 and " * 200 + "true", "a check is limited to 2000 characters"),
        ("(" * 300 + "width" + ")" * 300 + " > 0", "invalid expression: too many nested"),
        ("é == 1 or __import__('os')", "unknown parameter 'é' (at character 1)"),
        (
            "'é' == mode and widht > 0",
            "unknown parameter 'widht' (did you mean 'width'?) (at character 17)",
        ),
    ],
)
def test_refused_checks_say_why(check: str, message: str) -> None:
    with pytest.raises(RuleError) as caught:
        compile_rule("r", check, "", TYPES)
    assert message in str(caught.value)


def test_failures_name_the_rule_and_every_value_read() -> None:
    rule = compile_rule("aspect", "abs(aspect_ratio - width / height) <= 0.01", "", TYPES)
    values = {**VALUES, "aspect_ratio": 1.5}
    assert rule.violation(values, lambda name: f"front.{name}") == (
        "rule 'aspect' broken: abs(aspect_ratio - width / height) <= 0.01 is false for "
        "front.aspect_ratio=1.5, front.width=640, front.height=480"
    )
    assert rule.violation({**VALUES, "height": 0}) == (
        "rule 'aspect' broken: abs(aspect_ratio - width / height) <= 0.01 cannot be evaluated "
        "for aspect_ratio=1.3333, width=640, height=0: division by zero"
    )
    empty = compile_rule("bounded", "max(weights) <= 1", "", TYPES)
    failure = empty.violation({**VALUES, "weights": ()})
    assert failure is not None and failure.startswith(
        "rule 'bounded' broken: max(weights) <= 1 cannot be evaluated for weights=(): max()"
    )


def test_chained_comparison_reads_each_operand_once_and_stops_early() -> None:
    reads: list[str] = []

    class Recording(dict[str, Any]):
        def __getitem__(self, name: str) -> Any:
            reads.append(name)
            return super().__getitem__(name)

    rule = compile_rule("r", "width < height < min_speed < max_speed", "", TYPES)
    assert rule.expression.evaluate(Recording(VALUES)) is False
    assert reads == ["width", "height"]


# Differential test: random arithmetic and logic over a few parameters means what Python
# means. The test builds the expressions itself, so evaluating them with Python is safe here.
NUMBER_NAMES = ("width", "height", "min_speed", "max_speed")


def _numbers() -> st.SearchStrategy[str]:
    leaves = st.one_of(
        st.sampled_from(NUMBER_NAMES),
        st.integers(-5, 5).map(str),
        st.sampled_from(["0.5", "2.25", "1e3"]),
    )

    def extend(children: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
        binary = st.tuples(children, st.sampled_from(["+", "-", "*", "/", "//", "%"]), children)
        return st.one_of(
            binary.map(lambda t: f"({t[0]} {t[1]} {t[2]})"),
            children.map(lambda c: f"-{c}"),
            children.map(lambda c: f"abs({c})"),
            st.tuples(children, children).map(lambda t: f"max({t[0]}, {t[1]})"),
            st.tuples(children, children).map(lambda t: f"min({t[0]}, {t[1]})"),
        )

    return st.recursive(leaves, extend, max_leaves=8)


def _conditions() -> st.SearchStrategy[str]:
    comparison = st.tuples(
        _numbers(), st.sampled_from(["<", "<=", ">", ">=", "==", "!="]), _numbers()
    ).map(lambda t: f"{t[0]} {t[1]} {t[2]}")

    def extend(children: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
        return st.one_of(
            st.tuples(children, st.sampled_from(["and", "or"]), children).map(
                lambda t: f"({t[0]} {t[1]} {t[2]})"
            ),
            children.map(lambda c: f"(not {c})"),
            st.tuples(children, children, children).map(
                lambda t: f"({t[0]} if {t[1]} else {t[2]})"
            ),
        )

    return st.recursive(comparison, extend, max_leaves=4)


@settings(max_examples=200, deadline=None)
@given(
    check=_conditions(),
    width=st.integers(-3, 700),
    height=st.integers(-3, 500),
    speeds=st.tuples(st.floats(-10, 10), st.floats(-10, 10)),
)
def test_meaning_matches_python(
    check: str, width: int, height: int, speeds: tuple[float, float]
) -> None:
    values = {**VALUES, "width": width, "height": height}
    values["min_speed"], values["max_speed"] = speeds
    expression = compile_expression(check, TYPES)
    assert expression.kind == "bool"
    try:
        expected: Any = eval(check, {"__builtins__": {"abs": abs, "min": min, "max": max}}, values)
    except ArithmeticError as exc:
        with pytest.raises(type(exc)):
            expression.evaluate(values)
        return
    assert expression.evaluate(values) == expected
