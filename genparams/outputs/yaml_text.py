"""Spelling values and keys for params files, so that ROS reads back exactly what was meant.

Every spelling here is read the same way by ROS's own parser (see ros_yaml),
by YAML 1.1 readers (PyYAML) and by YAML 1.2 readers (editors): doubles always
carry a decimal point and a signed exponent, strings that any of them would
read as something else are double-quoted, and quoting escapes every character
that YAML would fold or refuse.
"""

from __future__ import annotations

import math
import re
from typing import Any

from genparams.paramsfile.ros_yaml import ros_scalar
from genparams.runtime.core.types import ParamType

# Plain (unquoted) strings: a conservative alphabet that no YAML reader treats specially.
_PLAIN_STRING = re.compile(r"[A-Za-z_/][A-Za-z0-9_./+-]*")
_NODE_KEY = re.compile(r"/?[A-Za-z0-9_*]+(/[A-Za-z0-9_*]+)*")
# Words YAML 1.1 or 1.2 reads as null or bool although ROS would read them as strings.
_YAML_WORDS = frozenset(
    {"null", "Null", "NULL", "~", "y", "Y", "n", "N", "yes", "Yes", "YES", "no", "No", "NO"}
    | {"true", "True", "TRUE", "false", "False", "FALSE", "on", "On", "ON", "off", "Off", "OFF"}
)
# Line breaks in YAML (1.1 counts NEL and the Unicode separators too) and other
# characters a YAML stream may not hold raw.
_ESCAPES = {'"': '\\"', "\\": "\\\\", "\n": "\\n", "\t": "\\t", "\r": "\\r"}


def double_text(value: float) -> str:
    """``30.0``, ``1.0e-05``, ``-.inf``, ``.nan``: read as a double by ROS and by YAML."""
    if math.isnan(value):
        return ".nan"
    if math.isinf(value):
        return ".inf" if value > 0 else "-.inf"
    mantissa, _, exponent = repr(value).partition("e")
    if "." not in mantissa:
        mantissa += ".0"
    return f"{mantissa}e{exponent}" if exponent else mantissa


def quoted(text: str) -> str:
    """A double-quoted YAML scalar holding exactly ``text``."""
    out = []
    for char in text:
        if char in _ESCAPES:
            out.append(_ESCAPES[char])
        elif _printable(char):
            out.append(char)
        elif ord(char) <= 0xFF:
            out.append(f"\\x{ord(char):02x}")
        elif ord(char) <= 0xFFFF:
            out.append(f"\\u{ord(char):04x}")
        else:
            out.append(f"\\U{ord(char):08x}")
    return '"' + "".join(out) + '"'


def _printable(char: str) -> bool:
    code = ord(char)
    if code in (0x85, 0x2028, 0x2029, 0xFEFF):
        return False  # line breaks in YAML 1.1, and the byte-order mark
    return (
        0x20 <= code <= 0x7E
        or 0xA0 <= code <= 0xD7FF
        or 0xE000 <= code <= 0xFFFD
        or 0x10000 <= code <= 0x10FFFF
    )


def string_text(value: str) -> str:
    """A string, plain when every reader keeps it a string, else double-quoted."""
    if (
        _PLAIN_STRING.fullmatch(value)
        and value not in _YAML_WORDS
        and ros_scalar(value, None) == value
    ):
        return value
    return quoted(value)


def scalar_text(value: Any, kind: str) -> str:
    """One value of kind bool, int, double, string or byte, spelled for a params file."""
    if kind == "bool":
        return "true" if value else "false"
    if kind == "double":
        return double_text(float(value))
    if kind in ("int", "byte"):
        return str(int(value))
    return string_text(str(value))


def value_text(value: Any, param_type: ParamType) -> str:
    """A typed-view value spelled for a params file.

    A byte_array is written as a list of integers: ROS's params-file parser has
    no byte type, and the runtime accepts integers 0..255 for a byte_array.
    A value of type ``any`` is spelled as its own type.
    """
    param_type = param_type.of_value(value)
    if not param_type.is_array:
        return scalar_text(value, param_type.name)
    kind = param_type.scalar_kind
    return "[" + ", ".join(scalar_text(item, kind) for item in value) + "]"


def key_text(name: str) -> str:
    """A mapping key: plain unless a YAML reader would take it for a bool or null."""
    if _PLAIN_STRING.fullmatch(name) and name not in _YAML_WORDS:
        return name
    return quoted(name)


def node_key_text(name: str) -> str:
    """A node-name key such as ``/**`` or ``/robot/camera``."""
    return name if _NODE_KEY.fullmatch(name) else quoted(name)


def comment_lines(text: str) -> tuple[str, ...]:
    """``text`` as the bodies of YAML comment lines: one per line, nothing YAML would break."""
    lines = []
    for line in text.splitlines():
        lines.append("".join(char if _printable(char) or char == "\t" else "?" for char in line))
    return tuple(line.rstrip() for line in lines)
