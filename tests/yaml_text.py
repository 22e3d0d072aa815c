"""A small YAML writer for generated test documents, independent of the loader under test.

Strings are always double-quoted; characters Python would not print raw are
written as YAML escapes, everything else raw (so files hold real Unicode).
Floats always carry a dot or are ``.inf`` / ``.nan``, so YAML 1.1 reads them
as floats. Mapping keys are written plain or quoted, as the caller asks.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

_SHORT_ESCAPES = {
    "\\": "\\\\",
    '"': '\\"',
    "\0": "\\0",
    "\a": "\\a",
    "\b": "\\b",
    "\t": "\\t",
    "\n": "\\n",
    "\v": "\\v",
    "\f": "\\f",
    "\r": "\\r",
    "\x1b": "\\e",
    "\x85": "\\N",
    "\xa0": "\\_",
    "\u2028": "\\L",
    "\u2029": "\\P",
}


def quoted(text: str) -> str:
    out = []
    for char in text:
        if char in _SHORT_ESCAPES:
            out.append(_SHORT_ESCAPES[char])
        elif char.isprintable() and char != "\ufeff":
            out.append(char)
        elif ord(char) <= 0xFF:
            out.append(f"\\x{ord(char):02x}")
        elif ord(char) <= 0xFFFF:
            out.append(f"\\u{ord(char):04x}")
        else:
            out.append(f"\\U{ord(char):08x}")
    return '"' + "".join(out) + '"'


def scalar(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return ".nan"
        if math.isinf(value):
            return ".inf" if value > 0 else "-.inf"
        text = repr(value)
        if "." not in text:  # 1e-05 -> 1.0e-05: YAML 1.1 floats need a dot
            mantissa, _, exponent = text.partition("e")
            text = f"{mantissa}.0e{exponent}" if exponent else f"{mantissa}.0"
        return text
    if isinstance(value, str):
        return quoted(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(scalar(item) for item in value) + "]"
    if isinstance(value, Mapping):
        return "{" + ", ".join(f"{quoted(str(k))}: {scalar(v)}" for k, v in value.items()) + "}"
    raise TypeError(f"cannot write {type(value).__name__} as YAML")


def key(name: str, quote: bool) -> str:
    return quoted(name) if quote else name


def block(mapping: Mapping[str, Any], indent: int = 0, quote_keys: bool = False) -> str:
    """A block mapping; nested mappings become nested blocks unless marked flow."""
    lines = []
    pad = " " * indent
    for name, value in mapping.items():
        if isinstance(value, Flow):
            lines.append(f"{pad}{key(name, quote_keys)}: {scalar(value.mapping)}")
        elif isinstance(value, Mapping):
            lines.append(f"{pad}{key(name, quote_keys)}:")
            lines.append(block(value, indent + 2, quote_keys).rstrip("\n"))
        else:
            lines.append(f"{pad}{key(name, quote_keys)}: {scalar(value)}")
    return "\n".join(lines) + "\n"


class Flow:
    """Marks a mapping to be written in flow style: ``{type: int, default: 1}``."""

    def __init__(self, mapping: Mapping[str, Any]) -> None:
        self.mapping = mapping
