"""The one JSON codec of genparams: the schema message, the tuning API, every JSON it writes.

JSON has no NaN or infinity, yet a double parameter may hold them (a default,
a bound, a value). Every non-finite float is written as a one-key object::

    {"$float": "nan"}    {"$float": "inf"}    {"$float": "-inf"}

and read back as that float; every other value is written as ``json`` writes
it (``-0.0`` stays ``-0.0``). Text genparams writes therefore parses with any
strict JSON reader, and a page decodes the three objects with a reviver.
An object of exactly that shape is reserved: it always reads as a float.

Reading is strict and bounded: a size limit, a nesting depth limit, no
``NaN``/``Infinity`` tokens, no number that overflows to infinity, no lone
surrogate in a string. Any breach raises :class:`JsonError` (a ValueError)
naming the rule broken.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from itertools import accumulate
from typing import Any

from genparams.runtime.core.errors import GenparamsError

FLOAT_TAG = "$float"
_FLOAT_NAMES = {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}


class JsonError(GenparamsError, ValueError):
    """Text that is not JSON genparams reads: the message names the rule it breaks."""


@dataclass(frozen=True)
class Limits:
    max_chars: int  # of the text (bytes before decoding, when given bytes)
    max_depth: int  # arrays and objects inside each other


API_LIMITS = Limits(max_chars=1 << 20, max_depth=32)
"""A request body of the tuning API."""


# ---- writing ---------------------------------------------------------------------------


def float_tag(value: float) -> dict[str, str]:
    """The object a non-finite float is written as."""
    name = "nan" if value != value else ("inf" if value > 0 else "-inf")
    return {FLOAT_TAG: name}


def tagged(value: Any) -> Any:
    """``value`` with every non-finite float as its tag; tuples as lists, bytes as ints."""
    if isinstance(value, float):
        return value if math.isfinite(value) else float_tag(value)
    if isinstance(value, list | tuple):
        return [tagged(item) for item in value]
    if isinstance(value, dict):
        return {key: tagged(item) for key, item in value.items()}
    if isinstance(value, bytes | bytearray):
        return list(value)
    return value


def _plain(value: Any) -> Any:
    """What ``json`` cannot write itself: bytes and sets, as lists."""
    if isinstance(value, bytes | bytearray | set | frozenset):
        return sorted(value) if isinstance(value, set | frozenset) else list(value)
    raise TypeError(f"{type(value).__name__} is not JSON")


def dumps(
    value: Any,
    *,
    sort_keys: bool = False,
    indent: int | None = None,
    separators: tuple[str, str] | None = None,
    ensure_ascii: bool = True,
) -> str:
    """JSON text of ``value``, non-finite floats tagged; ASCII (always valid UTF-8) by default."""
    options: dict[str, Any] = {
        "ensure_ascii": ensure_ascii,
        "sort_keys": sort_keys,
        "indent": indent,
        "separators": separators,
        "allow_nan": False,
        "default": _plain,
    }
    try:
        return json.dumps(value, **options)
    except ValueError:  # a NaN or an infinity somewhere: tag it (rare, so only then)
        return json.dumps(tagged(value), **options)


# ---- reading ---------------------------------------------------------------------------

_NOT_STRUCTURE = bytes(set(range(256)) - set(b'[]{}"'))
_STRING = re.compile(rb'"[^"]*"')
_STEP = {ord("["): 1, ord("{"): 1, ord("]"): -1, ord("}"): -1, ord('"'): 0}
_SURROGATE_ESCAPE = re.compile(r"\\u[dD][89a-fA-F]")


def nesting_depth(text: str) -> int:
    """How deep arrays and objects nest in JSON ``text``, counted without parsing it.

    Escaped backslashes and quotes go first (escapes read left to right in
    pairs), then every byte but brackets and quotes (no byte of a multi-byte
    UTF-8 character is one), then whole strings: the brackets outside strings
    are left.
    """
    data = text.encode("utf-8", "surrogatepass").replace(b"\\\\", b"").replace(b'\\"', b"")
    brackets = _STRING.sub(b"", data.translate(None, _NOT_STRUCTURE))
    return max(accumulate(map(_STEP.__getitem__, brackets)), default=0)


def _refuse_constant(name: str) -> Any:
    raise JsonError(f'{name} is not JSON (write {{"{FLOAT_TAG}": "nan"}}, "inf" or "-inf")')


def _finite_float(text: str) -> float:
    number = float(text)
    if not math.isfinite(number):
        raise JsonError(f"the number {text[:40]} is too large for a double")
    return number


def _untag(pairs: dict[str, Any]) -> Any:
    if len(pairs) == 1 and FLOAT_TAG in pairs:
        name = pairs[FLOAT_TAG]
        if isinstance(name, str) and name in _FLOAT_NAMES:
            return _FLOAT_NAMES[name]
    return pairs


def _lone_surrogate(value: Any) -> bool:
    pending = [value]
    while pending:
        item = pending.pop()
        if isinstance(item, str):
            try:
                item.encode("utf-8")
            except UnicodeEncodeError:
                return True
        elif isinstance(item, list):
            pending.extend(item)
        elif isinstance(item, dict):
            pending.extend(item)
            pending.extend(item.values())
    return False


def loads(text: str | bytes, limits: Limits = API_LIMITS) -> Any:
    """Read JSON text strictly, tags back to floats; :class:`JsonError` on anything else."""
    if len(text) > limits.max_chars:
        raise JsonError(f"{len(text)} characters, more than the limit of {limits.max_chars}")
    if isinstance(text, bytes):
        try:
            text = text.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise JsonError(f"not UTF-8 text: {exc.reason} at byte {exc.start}") from None
    depth = nesting_depth(text)
    if depth > limits.max_depth:
        raise JsonError(f"nested {depth} deep, more than the limit of {limits.max_depth}")
    try:
        value = json.loads(
            text, parse_constant=_refuse_constant, parse_float=_finite_float, object_hook=_untag
        )
    except JsonError:
        raise
    except (ValueError, RecursionError) as exc:
        raise JsonError(f"not JSON: {exc}") from None
    if _SURROGATE_ESCAPE.search(text) and _lone_surrogate(value):
        raise JsonError("a string holds a lone surrogate (\\ud800-\\udfff), not a character")
    return value
