"""How far a static reading of Python source computes, for every reader of it (import-rclpy's
evaluator, the launch-file reader): what it would take too much memory or time to work out
is left to run time instead."""

from __future__ import annotations

import ast
from typing import Any

MAX_ITEMS = 4096  # a list or text repeated, a loop's items, a range
MAX_EXPONENT = 64  # a power's exponent (``10 ** 10 ** 9`` is never computed)


def _count(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def computable(op: ast.operator, left: Any, right: Any) -> bool:
    """Whether ``left <op> right`` is small enough to work out while reading: a power's
    exponent at most MAX_EXPONENT, a text, list or tuple repeated to at most MAX_ITEMS."""
    if isinstance(op, ast.Pow):
        number = isinstance(right, int | float) and not isinstance(right, bool)
        return not (number and abs(right) > MAX_EXPONENT)
    if isinstance(op, ast.Mult):
        for count, repeated in ((left, right), (right, left)):
            if _count(count) and isinstance(repeated, str | list | tuple):
                return bool(count * len(repeated) <= MAX_ITEMS)
    return True
