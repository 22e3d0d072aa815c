"""A value of the wrong type is named by its kind and shown whole up to 60 characters,
cut to 57 and an ellipsis beyond: in schema defaults and in values from ROS alike."""

from __future__ import annotations

from typing import Any

import pytest

from genparams.runtime.types import TYPES, ValueTypeError


@pytest.mark.parametrize(
    ("type_name", "value", "message"),
    [
        ("int", [1, 2], "expected integer, got list [1, 2]"),
        ("double", {"a": 1}, "expected double, got dict {'a': 1}"),
        ("string", None, "expected string, got NoneType None"),
        ("bool", 1.5, "expected bool, got double 1.5"),
        ("int_array", "ab", "expected int_array, got string 'ab'"),
        ("string_array", [1], "item 0: expected string, got integer 1"),
        ("byte_array", [1, (2,)], "item 1: expected a byte (0..255), got tuple (2,)"),
        ("byte_array", 3.0, "expected byte_array, got double 3.0"),
    ],
)
def test_wrong_types_are_named(type_name: str, value: Any, message: str) -> None:
    with pytest.raises(ValueTypeError) as caught:
        TYPES[type_name].coerce_default(value)
    assert str(caught.value) == message


def test_values_are_shown_whole_up_to_60_characters() -> None:
    whole = "x" * 58  # its repr, quotes included, is 60 characters
    with pytest.raises(ValueTypeError) as caught:
        TYPES["int"].from_ros(whole)
    assert str(caught.value) == f"expected integer, got string '{whole}'"
    with pytest.raises(ValueTypeError) as caught:
        TYPES["int"].from_ros(whole + "y")
    assert str(caught.value) == f"expected integer, got string '{'x' * 56}..."
