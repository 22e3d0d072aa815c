"""The cost of compiling a pattern a node's schema message names, told before it is compiled.

The ``regex`` engine expands counted repeats when it compiles: ``(?:x{2000}){2000}``
becomes four million nodes and about a gigabyte. :func:`pattern_cost_problem` is the
one question the reader asks of every pattern in a message before the runtime compiles
it; a pattern that costs too much makes the message a problem, never a stall.
"""

from __future__ import annotations

import re
from re import _parser as sre_parse  # type: ignore[attr-defined]  # Python's own regex parser
from typing import Any

MAX_PATTERN_NODES = 100_000
"""What a pattern may expand to: far above any written by hand (``\\d{1,3}`` is 3)."""


def _expanded(items: Any) -> int:
    """The nodes a parsed pattern expands to, counted repeats multiplied out."""
    total = 0
    for op, arg in items:
        if op in (sre_parse.MAX_REPEAT, sre_parse.MIN_REPEAT, sre_parse.POSSESSIVE_REPEAT):
            low, high, body = arg
            copies = low + 1 if high == sre_parse.MAXREPEAT else max(low, high)
            total += max(1, copies) * _expanded(body)
        elif op is sre_parse.SUBPATTERN:
            total += _expanded(arg[-1])
        elif op is sre_parse.BRANCH:
            total += sum(_expanded(branch) for branch in arg[1])
        elif op in (sre_parse.ASSERT, sre_parse.ASSERT_NOT):
            total += _expanded(arg[1])
        elif op is sre_parse.ATOMIC_GROUP:
            total += _expanded(arg)
        elif op is sre_parse.GROUPREF_EXISTS:
            total += sum(_expanded(branch) for branch in arg[1:] if branch is not None)
        else:
            total += 1
        if total > MAX_PATTERN_NODES:
            return total
    return total


def pattern_cost_problem(pattern: str) -> str | None:
    """Why compiling ``pattern`` costs too much, if it does (its syntax is checked later)."""
    try:
        nodes = _expanded(sre_parse.parse(pattern))
    except (re.error, RecursionError, OverflowError, ValueError):
        return None  # not a pattern: the runtime's own check names the error
    if nodes > MAX_PATTERN_NODES:
        return (
            f"pattern {pattern[:60]!r} expands to more than {MAX_PATTERN_NODES} nodes when"
            " compiled (its counted repeats multiply)"
        )
    return None
