"""A value of the wrong type is named by its kind and shown whole up to 60 characters,
cut to 57 and an ellipsis beyond: in schema defaults and in values from ROS alike."""

from __future__ import annotations

from array import array
from dataclasses import dataclass
from typing import Any

import pytest

from genparams.runtime.core.types import TYPES, TYPES_BY_ROS_TYPE, ValueTypeError


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


BIG = 2**63
HUGE = 10**400


@dataclass(frozen=True)
class Refused:
    """The conversion raises ValueTypeError with a message that starts with this."""

    message: str


NUL = Refused("text cannot contain NUL (\\x00): ROS strings end at the first NUL")
SURROGATE = Refused("text must be valid UTF-8 (it contains a lone surrogate)")


def _item(index: int, what: str) -> Refused:
    return Refused(f"item {index}: expected a byte (0..255), got {what}")


@pytest.mark.parametrize(
    ("type_name", "value", "default", "from_ros"),
    [
        ("bool", True, True, True),
        ("bool", 1, Refused("expected bool, got integer 1"), Refused("expected bool, got i")),
        ("int", BIG - 1, BIG - 1, BIG - 1),
        ("int", -BIG, -BIG, -BIG),
        ("int", BIG, Refused(f"integer {BIG} does not fit in int64"), Refused("integer ")),
        ("int", -BIG - 1, Refused(f"integer {-BIG - 1} does not fit"), Refused("integer -")),
        ("int", True, Refused("expected integer, got bool True"), Refused("expected integer")),
        ("int", 2.0, Refused("expected integer, got double 2.0"), Refused("expected integer")),
        (
            "double",
            30,
            30.0,
            Refused("expected double, got integer 30 (ROS does not convert: write 30.0)"),
        ),
        ("double", 0.5, 0.5, 0.5),
        ("double", False, Refused("expected double, got bool False"), Refused("expected d")),
        (
            "double",
            HUGE,
            Refused(f"integer {repr(HUGE)[:57]}... is too large for a double"),
            Refused(f"expected double, got integer {HUGE} (ROS does not convert"),
        ),
        ("string", "a", "a", "a"),
        ("string", "a\x00b", NUL, NUL),
        ("string", "a\ud800", SURROGATE, SURROGATE),
        ("string_array", ["a", "\x00"], Refused(f"item 1: {NUL.message}"), Refused("item 1: ")),
        ("double_array", [1, 2.5], (1.0, 2.5), Refused("item 0: expected double, got integer")),
        ("bool_array", (True,), (True,), (True,)),
        ("int_array", array("q", [1, -2]), (1, -2), (1, -2)),  # as rclpy hands them over
        ("double_array", array("d", [0.5]), (0.5,), (0.5,)),
        ("string_array", [], (), ()),
        ("int_array", None, Refused("expected int_array, got NoneType None"), ()),
        ("byte_array", [b"\x01", 255, bytearray(b"\x00")], b"\x01\xff\x00", b"\x01\xff\x00"),
        ("byte_array", bytearray(b"ab"), b"ab", b"ab"),
        ("byte_array", [], b"", b""),
        ("byte_array", None, Refused("expected byte_array, got NoneType None"), b""),
        ("byte_array", [256], _item(0, "integer 256"), _item(0, "integer 256")),
        ("byte_array", [0, -1], _item(1, "integer -1"), _item(1, "integer -1")),
        ("byte_array", [True], _item(0, "bool True"), _item(0, "bool True")),
        ("byte_array", [b"ab"], _item(0, "bytes b'ab'"), _item(0, "bytes b'ab'")),
        ("byte_array", [b""], _item(0, "bytes b''"), _item(0, "bytes b''")),
    ],
)
def test_defaults_are_lenient_and_ros_values_exact(
    type_name: str, value: Any, default: Any, from_ros: Any
) -> None:
    param_type = TYPES[type_name]
    for convert, expected in (
        (param_type.coerce_default, default),
        (param_type.from_ros, from_ros),
    ):
        if isinstance(expected, Refused):
            with pytest.raises(ValueTypeError) as caught:
                convert(value)
            assert str(caught.value).startswith(expected.message)
        else:
            converted = convert(value)
            assert converted == expected and type(converted) is type(expected)


@pytest.mark.parametrize(
    ("type_name", "typed", "ros"),
    [
        ("byte_array", b"\x01\xff", [b"\x01", b"\xff"]),
        ("int_array", (1, 2), [1, 2]),
        ("string_array", (), []),
        ("double", 1.5, 1.5),
        ("string", "a", "a"),
    ],
)
def test_typed_values_go_back_to_ros(type_name: str, typed: Any, ros: Any) -> None:
    assert TYPES[type_name].to_ros(typed) == ros


def test_the_table_describes_each_type() -> None:
    rows = {
        name: (t.is_array, t.scalar_kind, t.is_numeric, t.ros_type) for name, t in TYPES.items()
    }
    assert rows == {
        "bool": (False, "bool", False, 1),
        "int": (False, "int", True, 2),
        "double": (False, "double", True, 3),
        "string": (False, "string", False, 4),
        "byte_array": (True, "byte", False, 5),
        "bool_array": (True, "bool", False, 6),
        "int_array": (True, "int", True, 7),
        "double_array": (True, "double", True, 8),
        "string_array": (True, "string", False, 9),
        "any": (False, "any", False, 0),  # dynamic typing: each value has its own type
    }
    assert {t: p.name for t, p in TYPES_BY_ROS_TYPE.items()} == {
        p.ros_type: name for name, p in TYPES.items() if not p.is_dynamic
    }


@pytest.mark.parametrize(
    ("value", "kind", "typed"),
    [
        (True, "bool", True),
        (3, "int", 3),
        (0.5, "double", 0.5),
        ("x", "string", "x"),
        ([1, 2], "int_array", (1, 2)),
        ([b"\x01", b"\x02"], "byte_array", b"\x01\x02"),
        ([], "byte_array", b""),  # rclpy's inference for an empty list
        (["a"], "string_array", ("a",)),
    ],
)
def test_a_value_of_type_any_has_its_own_type(value: Any, kind: str, typed: Any) -> None:
    dynamic = TYPES["any"]
    converted = dynamic.from_ros(value)
    assert converted == typed and type(converted) is type(typed)
    assert dynamic.of_value(converted).name == kind


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ([1, "a"], "the items of a list must share one type"),
        ([1, 2.0], "the items of a list must share one type"),  # ROS does not convert
        ({"a": 1}, "expected a value of a ROS parameter type"),
        (None, "expected a value of a ROS parameter type"),
    ],
)
def test_a_value_of_type_any_must_be_a_ros_value(value: Any, message: str) -> None:
    with pytest.raises(ValueTypeError, match=message):
        TYPES["any"].from_ros(value)
    assert TYPES["any"].coerce_default([1, 2.0]) == (1.0, 2.0)  # a schema default may mix
