"""How ROS reads a params file: scalar typing and node-name patterns.

ROS does not use YAML's types. Its params-file parser (rcl_yaml_param_parser)
types every unquoted scalar itself: a fixed list of bool words, then anything C
``strtol(text, 0)`` reads whole (so ``0x10`` is 16 and ``010`` is 8), then
anything ``strtod`` reads whole (``1e3``, ``nan``, ``.inf``), else a string.
Quoted scalars are always strings. An empty list reaches the node as "not
set". These rules were checked against rclpy on Jazzy; offline checks and the
defaults writer both follow them, so what they say is what a node receives.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction

# Node names and their wildcards are name rules: runtime.naming holds them.
from genparams.runtime.core.naming import WILDCARD_ANY, WILDCARD_ONE
from genparams.runtime.core.naming import absolute as absolute
from genparams.runtime.core.naming import node_name_problem as node_name_problem
from genparams.runtime.core.naming import node_pattern_problem as node_pattern_problem

PARAMS_KEY = "ros__parameters"


_TRUE_WORDS = frozenset({"Y", "y", "yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON"})
_FALSE_WORDS = frozenset(
    {"N", "n", "no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF"}
)
_SPECIAL_FLOATS = {
    f"{sign}.{word}": value
    for word, magnitude in (
        ("nan", math.nan),
        ("NaN", math.nan),
        ("NAN", math.nan),
        ("inf", math.inf),
        ("Inf", math.inf),
        ("INF", math.inf),
    )
    for sign, value in (("", magnitude), ("+", magnitude), ("-", -magnitude))
    if not (sign and math.isnan(magnitude))
}
_SPACE = "[ \t\n\v\f\r]*"  # what strtol and strtod skip before a number
_STRTOL = re.compile(_SPACE + r"([+-]?)(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)")
_STRTOD_DECIMAL = re.compile(_SPACE + r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?")
_STRTOD_HEX = re.compile(
    _SPACE + r"[+-]?0[xX]([0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)([pP][+-]?[0-9]+)?"
)
_STRTOD_WORD = re.compile(_SPACE + r"([+-]?)(inf|infinity|nan(\([0-9A-Za-z_]*\))?)", re.IGNORECASE)
_INT64_MIN, _INT64_MAX = -(2**63), 2**63 - 1
_SMALLEST_NORMAL = 2.2250738585072014e-308

ScalarValue = bool | int | float | str


@dataclass(frozen=True)
class NoValue:
    """An unquoted empty scalar (``fps:`` with nothing after it): ROS refuses the file."""


def is_quoted(style: str | None) -> bool:
    return style in ("'", '"')


def ros_scalar(text: str, style: str | None) -> ScalarValue | NoValue:
    """The value ROS reads from one scalar written as ``text`` in YAML style ``style``.

    ``style`` is PyYAML's: None for plain, ``'`` or ``"`` for quoted, ``|`` or
    ``>`` for block scalars (which ROS types like plain ones).
    """
    if is_quoted(style):
        return text
    if text == "":
        return NoValue()
    if text in _TRUE_WORDS:
        return True
    if text in _FALSE_WORDS:
        return False
    integer = _strtol(text)
    if integer is not None:
        return integer
    number = _strtod(text)
    if number is not None:
        return number
    return text


# int64 needs at most 19 decimal, 16 hex or 22 octal digits.
_INT64_DIGITS = 22


def _strtol(text: str) -> int | None:
    match = _STRTOL.fullmatch(text)
    if match is None:
        return None
    sign, digits = match.groups()
    if len(digits.lstrip("0xX")) > _INT64_DIGITS:
        return None  # past int64 in any base (strtol's ERANGE), without converting it
    if digits[:2] in ("0x", "0X"):
        value = int(digits[2:], 16)
    elif len(digits) > 1 and digits[0] == "0":
        value = int(digits[1:], 8)
    else:
        value = int(digits)
    value = -value if sign == "-" else value
    if not _INT64_MIN <= value <= _INT64_MAX:
        return None  # strtol reports ERANGE; ROS then tries strtod
    return value


def _strtod(text: str) -> float | None:
    if text in _SPECIAL_FLOATS:
        return _SPECIAL_FLOATS[text]
    word = _STRTOD_WORD.fullmatch(text)
    if word is not None:
        negative = word.group(1) == "-"
        value = math.nan if word.group(2).lower().startswith("nan") else math.inf
        return -value if negative else value
    hexadecimal = _STRTOD_HEX.fullmatch(text) is not None
    cleaned = text.strip()
    if hexadecimal:
        sign = -1.0 if cleaned.startswith("-") else 1.0
        body = cleaned.lstrip("+-")
        if "p" not in body.lower():
            body += "p0"
        try:
            value = sign * float.fromhex(body)
        except OverflowError:
            return None
    elif _STRTOD_DECIMAL.fullmatch(text):
        value = float(cleaned)
    else:
        return None
    # strtod reports ERANGE on overflow, and on underflow (a result below the smallest
    # normal double) unless the result is exact; ROS then keeps the text as a string.
    if math.isinf(value):
        return None
    if value == 0.0:
        mantissa = re.split("[pP]" if hexadecimal else "[eE]", cleaned)[0]
        return None if re.search("[1-9a-fA-F]" if hexadecimal else "[1-9]", mantissa) else value
    if abs(value) < _SMALLEST_NORMAL and Fraction(value) != _exact(cleaned, hexadecimal):
        return None
    return value


def _exact(number: str, hexadecimal: bool) -> Fraction:
    """The number a strtod spelling stands for, before rounding to a double."""
    if not hexadecimal:  # through Decimal: Fraction(str) refuses more than 4,300 digits
        return Fraction(*Decimal(number).as_integer_ratio())
    sign = -1 if number.startswith("-") else 1
    digits, _, exponent = number.lstrip("+-")[2:].lower().partition("p")
    whole, _, fraction = digits.partition(".")
    power = int(exponent or "0") - 4 * len(fraction)
    return sign * int(whole + fraction, 16) * Fraction(2) ** power


def ros_type_name(value: ScalarValue) -> str:
    """ROS's name for the type of a scalar read from a params file."""
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "integer"
    if isinstance(value, float):
        return "double"
    return "string"


# ---- node names -----------------------------------------------------------------------


def node_matches(pattern: str, node: str) -> bool:
    """Whether a params-file section named ``pattern`` applies to the node ``node``."""
    return _match(absolute(pattern)[1:].split("/"), absolute(node)[1:].split("/"))


def _match(pattern: list[str], tokens: list[str]) -> bool:
    if not pattern:
        return not tokens
    head, rest = pattern[0], pattern[1:]
    if head == WILDCARD_ANY:
        return any(_match(rest, tokens[skip:]) for skip in range(len(tokens) + 1))
    if not tokens:
        return False
    if head == WILDCARD_ONE or head == tokens[0]:
        return _match(rest, tokens[1:])
    return False
