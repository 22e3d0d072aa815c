"""The JSON codec: non-finite floats round-trip exactly, and reading is strict and bounded."""

from __future__ import annotations

import json
import math
from typing import Any

import pytest

from genparams.runtime.core.json_codec import (
    API_LIMITS,
    JsonError,
    Limits,
    dumps,
    loads,
    nesting_depth,
)


def strict(text: str) -> Any:
    """What any strict JSON reader makes of ``text``: NaN and Infinity tokens refused."""

    def refuse(token: str) -> Any:
        raise AssertionError(f"{token} in the output")

    return json.loads(text, parse_constant=refuse)


def same(a: Any, b: Any) -> bool:
    """Equal, NaN equal to NaN and -0.0 apart from 0.0."""
    if isinstance(a, float) and isinstance(b, float):
        if math.isnan(a) or math.isnan(b):
            return math.isnan(a) and math.isnan(b)
        return a == b and math.copysign(1.0, a) == math.copysign(1.0, b)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(map(same, a, b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    return type(a) is type(b) and bool(a == b)


@pytest.mark.parametrize(
    "value",
    [
        math.nan,
        math.inf,
        -math.inf,
        -0.0,
        0.0,
        1e308,
        5e-324,
        [math.nan, -math.inf, -0.0, 1.5],
        {"default": math.nan, "range": {"min": -math.inf, "max": math.inf, "step": 0.0}},
        {"nested": [[math.inf], [[-math.inf, "inf", "nan"]]]},
        2**63 - 1,
        -(2**63),
        "NaN",
    ],
)
def test_values_round_trip_exactly_through_strict_json(value: Any) -> None:
    text = dumps(value)
    strict(text)
    assert same(loads(text), value)


def test_non_finite_floats_are_written_as_tagged_objects() -> None:
    text = dumps([math.nan, math.inf, -math.inf])
    assert strict(text) == [{"$float": "nan"}, {"$float": "inf"}, {"$float": "-inf"}]


def test_tuples_and_bytes_are_written_as_lists() -> None:
    assert strict(dumps({"a": (1, (math.inf,)), "b": b"\x00\xff"})) == {
        "a": [1, [{"$float": "inf"}]],
        "b": [0, 255],
    }


def test_finite_output_is_what_json_writes() -> None:
    value = {"b": [1, 2.5, "é"], "a": None}
    assert dumps(value, sort_keys=True) == json.dumps(value, sort_keys=True)
    assert dumps(value, ensure_ascii=False) == json.dumps(value, ensure_ascii=False)


def test_output_is_ascii_by_default_even_for_a_lone_surrogate() -> None:
    assert dumps("\ud800é").isascii()


@pytest.mark.parametrize(
    ("text", "rule"),
    [
        ("NaN", "NaN is not JSON"),
        ("[1, Infinity]", "Infinity is not JSON"),
        ('{"x": -Infinity}', "-Infinity is not JSON"),
        ("1e400", "too large for a double"),
        ("[-1e999]", "too large for a double"),
        ('"\\ud800"', "lone surrogate"),
        ('["a", {"k": "\\udfff x"}]', "lone surrogate"),
        ("[1,", "not JSON"),
        ("", "not JSON"),
        ("{'a': 1}", "not JSON"),
        ("1" * 5000, "not JSON"),
    ],
)
def test_reading_refuses_what_is_not_strict_json(text: str, rule: str) -> None:
    with pytest.raises(JsonError, match=rule):
        loads(text)


def test_a_paired_surrogate_escape_is_a_character() -> None:
    assert loads('"\\ud83d\\ude00"') == "\U0001f600"


def test_size_limit() -> None:
    limits = Limits(max_chars=10, max_depth=5)
    assert loads("[1, 2, 3]", limits) == [1, 2, 3]
    with pytest.raises(JsonError, match="12 characters, more than the limit of 10"):
        loads("[1, 2, 3, 4]", limits)
    with pytest.raises(JsonError, match="more than the limit of 10"):
        loads(b"[1, 2, 3, 4]", limits)  # bytes: counted before decoding


def test_depth_limit() -> None:
    limits = Limits(max_chars=API_LIMITS.max_chars, max_depth=3)
    assert loads("[[[1]]]", limits) == [[[1]]]
    with pytest.raises(JsonError, match="nested 4 deep, more than the limit of 3"):
        loads('[{"a": [[1]]}]', limits)
    # Deeper than Python's recursion limit: refused by the count, never a RecursionError.
    with pytest.raises(JsonError, match="nested 200000 deep, more than the limit of 32"):
        loads("[" * 200_000 + "]" * 200_000, Limits(max_chars=10**6, max_depth=32))


@pytest.mark.parametrize(
    ("text", "depth"),
    [
        ('[[[1]], {"a": [{}]}]', 4),
        ("7", 0),
        ('["[[[[", "]]]]"]', 1),
        ('["\\\\", ["\\"[[["]]', 2),  # an escaped backslash, then an escaped quote
        ('["\\\\"]', 1),  # an escaped backslash ends the string: the quote after it closes
        ('"\\u005b[["', 0),
    ],
)
def test_nesting_depth_skips_strings(text: str, depth: int) -> None:
    assert nesting_depth(text) == depth


def test_brackets_inside_strings_do_not_count() -> None:
    limits = Limits(max_chars=100, max_depth=2)
    assert loads('["[[[[", "\\"]]]{{{", {"k": "[["}]', limits) == ["[[[[", '"]]]{{{', {"k": "[["}]


def test_bytes_must_be_utf8() -> None:
    assert loads('{"é": 1}'.encode()) == {"é": 1}
    with pytest.raises(JsonError, match="not UTF-8 text"):
        loads(b'"\xff"')


def test_only_the_exact_tag_reads_as_a_float() -> None:
    assert loads('{"$float": "nan", "x": 1}') == {"$float": "nan", "x": 1}
    assert loads('{"$float": "NaN"}') == {"$float": "NaN"}
    assert loads('{"$float": 1}') == {"$float": 1}


def test_every_error_is_a_value_error() -> None:
    # Callers that refuse bad input with `except ValueError` (a 400, a finding) catch it.
    assert issubclass(JsonError, ValueError)
