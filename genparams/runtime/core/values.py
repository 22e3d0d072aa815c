"""Equality of typed values as a change means it: a NaN equals a NaN.

IEEE says NaN != NaN, so a parameter holding NaN would count as changed by
every set of NaN, waking ``on_change`` with (nan, nan) and making a snapshot
unequal to itself. A parameter either holds NaN or not: re-applying the same
value, NaN included, is no change.
"""

from __future__ import annotations

from typing import Any


def same_value(a: Any, b: Any) -> bool:
    """``a == b``, with NaN equal to NaN, in scalars and in arrays (tuples)."""
    if a == b:
        return True
    if type(a) is float:
        return type(b) is float and a != a and b != b
    if type(a) is tuple and type(b) is tuple and len(a) == len(b):
        return all(same_value(x, y) for x, y in zip(a, b, strict=True))
    return False


def same_typed_value(a: Any, b: Any) -> bool:
    """``same_value`` of two values of the same type: for a parameter of type ``any``,
    1 and 1.0 (an int then a double), or (1,) and (1.0,), are a change."""
    if type(a) is not type(b) or not same_value(a, b):
        return False
    return type(a) is not tuple or not a or type(a[0]) is type(b[0])
