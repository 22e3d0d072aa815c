"""Each built-in validator alone: its verdict, its exact reason, how it describes itself,
and the argument errors of building it from a schema."""

from __future__ import annotations

import math
import re
from typing import Any

import pytest

from genparams.runtime.core.pattern_cost import PatternCostError, check_pattern_cost
from genparams.runtime.core.validator_kinds import ValidatorArgumentError, build_validator
from genparams.runtime.core.validators import (
    Bounds,
    Compare,
    Custom,
    Length,
    NotEmpty,
    OneOf,
    Pattern,
    RosRange,
    SubsetOf,
    Unique,
    Validator,
    first_failure,
)

CUSTOM_TAKES = (
    "custom takes 'package.module:function' or "
    "{function: 'package.module:function', args: [...]}, got "
)

# Functions for Custom, found by module path like a schema's `custom: module:function`.
NOT_CALLABLE = 42


def accepts_with_true(value: object) -> bool:
    return True


def refuses_with_false(value: object) -> bool:
    return False


def refuses_with_reason(value: object) -> str:
    return "too shiny"


def raises(value: object) -> None:
    raise RuntimeError("broken checker")


HERE = __name__


def test_compare_reasons_and_descriptions() -> None:
    assert Compare("gt", 0.0)(0.0) == "must be > 0.0 (gt), got 0.0"
    assert Compare("ge", 1)(0) == "must be >= 1 (ge), got 0"
    assert Compare("lt", 5)(5) == "must be < 5 (lt), got 5"
    assert Compare("le", 2.5)(2.6) == "must be <= 2.5 (le), got 2.6"
    assert [Compare(r, 1)(1) for r in ("ge", "le")] == [None, None]
    assert Compare("gt", 0.0)(math.nan) is not None  # NaN compares false
    assert Compare("le", 3).describe() == "must be <= 3"


def test_bounds_and_element_bounds() -> None:
    assert Bounds(-1.0, 1.0)(1.0) is None
    assert Bounds(-1.0, 1.0)(-1.0) is None
    assert Bounds(-1.0, 1.0)(1.5) == "must be within [-1.0, 1.0] (bounds), got 1.5"
    each = Bounds(0, 3, each=True, rule="element_bounds")
    assert each([0, 3]) is None
    assert each([0, 4]) == "item 1 must be within [0, 3] (element_bounds), got 4"
    assert Bounds(0, 3).describe() == "within [0, 3]"
    assert each.describe() == "every item within [0, 3]"


def test_ros_range_describes_its_step() -> None:
    assert RosRange(0, 10, 0, integer=True).describe() == "within [0, 10]"
    assert RosRange(0, 10, 2, integer=True).describe() == "within [0, 10] in steps of 2"
    each = RosRange(0.0, 1.0, 0.5, integer=False, each=True)
    assert each.describe() == "every item within [0.0, 1.0] in steps of 0.5"
    assert each([0.0, 0.7]) == (
        "item 1 must be 0.0 plus a whole number of steps of 0.5 (range), got 0.7"
    )
    assert RosRange(0.0, 1.0, 0.0, integer=False)(math.nan) == (
        "must be within [0.0, 1.0] (range), got nan"
    )
    assert RosRange(0, 10, 3, integer=True)(10) is None  # an edge off the step is valid
    assert RosRange(0, 10, 3, integer=True)(8) == (
        "must be 0 plus a whole number of steps of 3 (range), got 8"
    )


def test_one_of_and_subset_of() -> None:
    assert OneOf(("a", "b"))("b") is None
    assert OneOf(("a", "b"))("c") == "must be one of ['a', 'b'] (one_of), got 'c'"
    assert OneOf((1, 2)).describe() == "one of 1, 2"
    assert SubsetOf(("a", "b"))(["b", "a", "b"]) is None
    assert (
        SubsetOf(("a", "b"))(["a", "z"]) == "item 1 must be one of ['a', 'b'] (subset_of), got 'z'"
    )
    assert SubsetOf(("a", "b")).describe() == "every item one of 'a', 'b'"


def test_not_empty_unique_length() -> None:
    assert NotEmpty()([]) == "must not be empty (not_empty)"
    assert NotEmpty()("x") is None
    assert NotEmpty().describe() == "not empty"
    assert Unique()([1, 2, 1]) == "must not repeat items (unique), 1 appears twice"
    assert Unique()([1, 2]) is None
    assert Unique().describe() == "no repeated items"
    assert Length(2, 2)([1]) == "length must be exactly 2 (length), got 1"
    assert Length(2, None)([1]) == "length must be at least 2 (length), got 1"
    assert Length(None, 1)([1, 2]) == "length must be at most 1 (length), got 2"
    assert Length(1, 3).describe() == "length between 1 and 3"
    assert Length(None, 1)([]) is None and Length(2, None)([1, 2, 3]) is None


def test_pattern_on_strings_and_items() -> None:
    pattern = Pattern("^[a-z]+$")
    assert pattern("abc") is None
    assert pattern("ab1") == "must match '^[a-z]+$' (pattern), got 'ab1'"
    assert pattern(["ok", "NO"]) == "item 1 must match '^[a-z]+$' (pattern), got 'NO'"
    assert pattern.describe() == "matches '^[a-z]+$'"
    long = pattern("x" * 100 + "1")
    assert long is not None and long.endswith(", got '" + "x" * 56 + "...")  # cut at 60


def test_custom_outcomes() -> None:
    assert Custom(f"{HERE}:accepts_with_true")(1) is None
    assert Custom(f"{HERE}:refuses_with_false")(1) == (
        f"rejected by custom validator {HERE}:refuses_with_false"
    )
    assert Custom(f"{HERE}:refuses_with_reason")(1) == (f"too shiny ({HERE}:refuses_with_reason)")
    assert Custom(f"{HERE}:raises")(1) == (
        f"custom validator {HERE}:raises raised RuntimeError: broken checker"
    )
    assert Custom(f"{HERE}:NOT_CALLABLE")(1) == (
        f"custom validator {HERE}:NOT_CALLABLE raised TypeError: "
        f"{HERE}:NOT_CALLABLE is not callable"
    )
    assert Custom(f"{HERE}:raises").describe() == f"passes {HERE}:raises"
    assert Custom(f"{HERE}:raises").resolve() is raises


def test_first_failure_is_the_first_in_order() -> None:
    validators: list[Validator] = [Compare("ge", 0), Compare("le", 10), OneOf((1, 2))]
    assert first_failure(validators, 11) == "must be <= 10 (le), got 11"
    assert first_failure(validators, -1) == "must be >= 0 (ge), got -1"
    assert first_failure(validators, 2) is None


@pytest.mark.parametrize(
    ("rule", "argument", "param_type", "built"),
    [
        ("gt", 1, "int", Compare("gt", 1)),
        ("le", 2.5, "double", Compare("le", 2.5)),
        ("bounds", [0, 1], "double", Bounds(0, 1)),
        ("element_bounds", (0, 1), "int_array", Bounds(0, 1, each=True, rule="element_bounds")),
        ("one_of", ["a"], "string", OneOf(("a",))),
        ("subset_of", (1, 2), "int_array", SubsetOf((1, 2))),
        ("not_empty", None, "string", NotEmpty()),
        ("unique", None, "int_array", Unique()),
        ("length", 3, "string", Length(3, 3)),
        ("length", 0, "string_array", Length(0, 0)),
        ("length", 1, "string", Length(1, 1)),
        ("length", {"exact": 0}, "string", Length(0, 0)),
        ("bounds", [2, 2], "int", Bounds(2, 2)),
        ("length", {"exact": 2}, "string", Length(2, 2)),
        ("length", {"min": 1}, "string", Length(1, None)),
        ("length", {"max": 4}, "string", Length(None, 4)),
        ("length", {"min": 2, "max": 2}, "string", Length(2, 2)),
        ("custom", "pkg.mod:check", "int", Custom("pkg.mod:check")),
        ("pattern", "^a", "string", Pattern("^a")),
    ],
)
def test_build_validator(rule: str, argument: Any, param_type: str, built: object) -> None:
    assert build_validator(rule, argument, param_type) == built


@pytest.mark.parametrize(
    ("rule", "argument", "message"),
    [
        ("gt", "1", "gt must be a number, got '1'"),
        ("gt", True, "gt must be a number, got True"),
        ("ge", math.nan, "ge must be a number, not NaN (nothing compares to NaN)"),
        ("bounds", [0], "bounds takes [low, high], got [0]"),
        ("bounds", 3, "bounds takes [low, high], got 3"),
        ("bounds", [2, 1], "bounds low 2 is greater than high 1"),
        ("bounds", ["a", 1], "bounds low must be a number, got 'a'"),
        ("bounds", [0, "b"], "bounds high must be a number, got 'b'"),
        ("one_of", [], "one_of takes a non-empty list, got []"),
        ("one_of", "ab", "one_of takes a non-empty list, got 'ab'"),
        ("length", -1, "length must be >= 0, got -1"),
        ("length", {"min": -1}, "length min must be an integer >= 0"),
        ("length", {"max": True}, "length max must be an integer >= 0"),
        ("length", {"exact": 1, "min": 0}, "length takes exact, or min and/or max, not both"),
        ("length", {"min": 3, "max": 2}, "length min 3 is greater than max 2"),
        ("length", {"size": 2}, "length takes an integer or {min, max, exact}, got {'size': 2}"),
        ("length", {}, "length takes an integer or {min, max, exact}, got {}"),
        ("length", ["min"], "length takes an integer or {min, max, exact}, got ['min']"),
        (
            "length",
            {"min": 0, "max": 1, "exact": 1},
            "length takes exact, or min and/or max, not both",
        ),
        ("length", True, "length takes an integer or {min, max, exact}, got True"),
        ("pattern", 5, "pattern must be a string, got 5"),
        (
            "custom",
            "no_colon",
            CUSTOM_TAKES + "'no_colon'",
        ),
        (
            "custom",
            3,
            CUSTOM_TAKES + "3",
        ),
        (
            "custom",
            "a.b:c.d",
            CUSTOM_TAKES + "'a.b:c.d'",
        ),
    ],
)
def test_bad_arguments_say_why(rule: str, argument: Any, message: str) -> None:
    with pytest.raises(ValidatorArgumentError) as caught:
        build_validator(rule, argument, "int")
    assert str(caught.value) == message


def test_a_pattern_that_does_not_compile_is_an_argument_error() -> None:
    with pytest.raises(ValidatorArgumentError, match=r"pattern '\(' is not a valid regex: "):
        build_validator("pattern", "(", "string")


@pytest.mark.parametrize(
    ("pattern", "message"),
    [
        ("(?:x{400}){400}", "expands to more than 100,000 items when compiled"),
        ("(?:(?:x{50}){50}){50}", "expands to more than 100,000 items when compiled"),
        ("(?:a|(?:b{400}){400})", "expands to more than 100,000 items when compiled"),
        ("(?=(?:x{400}){400})", "expands to more than 100,000 items when compiled"),
        ("(?:" * 2000 + "x" + ")" * 2000, "nests its groups too deeply"),
        ("x" * 10_001, "is 10,001 characters long, more than the 10,000 a pattern may have"),
    ],
    ids=["product", "three deep", "in a branch", "in a lookahead", "deep", "long"],
)
def test_a_pattern_too_costly_to_compile_is_refused_before_compiling(
    pattern: str, message: str
) -> None:
    with pytest.raises(ValidatorArgumentError, match=re.escape(message)):
        build_validator("pattern", pattern, "string")
    with pytest.raises(PatternCostError, match=re.escape(message)):
        Pattern(pattern)


@pytest.mark.parametrize(
    "pattern", ["^[a-z]{1,63}$", "x{100000}", "(?:x{0,2000}){0,2000}", "(?:ab){2,}" * 100]
)
def test_patterns_within_the_bound_compile(pattern: str) -> None:
    check_pattern_cost(pattern)
    assert Pattern(pattern)("ab" * 2) in (None, f"must match {pattern!r} (pattern), got 'abab'")


def test_the_pattern_time_limit_is_one_budget_for_a_whole_array() -> None:
    """Each item takes about 2 ms to refuse: 400 of them together take far more than 50 ms."""
    slow_item = "a" * 18 + "!"
    assert Pattern("^(a|aa)+$|!")(slow_item) is None  # one item alone is well within the limit
    reason = Pattern("^(a|aa)+$|!")(["!", *([slow_item] * 400)])
    assert reason is not None
    assert reason.startswith("item ")
    assert "could not be matched against '^(a|aa)+$|!' (pattern) within 50 ms" in reason


def test_values_are_shown_whole_up_to_60_characters() -> None:
    shown = "x" * 58  # its repr, quotes included, is 60 characters
    assert OneOf(("a",))(shown) == f"must be one of ['a'] (one_of), got {shown!r}"
    cut = "x" * 59
    assert OneOf(("a",))(cut) == f"must be one of ['a'] (one_of), got '{'x' * 56}..."


def test_int_steps_count_from_the_low_edge() -> None:
    stepped = RosRange(1, 11, 3, integer=True)
    assert [stepped(v) is None for v in (1, 4, 7, 10, 11)] == [True] * 5
    assert stepped(3) == "must be 1 plus a whole number of steps of 3 (range), got 3"


def test_doubles_within_the_tolerance_of_either_edge_are_on_it() -> None:
    bounded = RosRange(1.0, 2.0, 0.0, integer=False)
    assert bounded(1.0 - 1e-7) is None and bounded(2.0 + 1e-7) is None
    assert bounded(1.0 - 1e-5) == "must be within [1.0, 2.0] (range), got 0.99999"
