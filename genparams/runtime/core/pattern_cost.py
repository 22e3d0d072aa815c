"""What a pattern costs to compile, bounded before any engine compiles it.

The ``regex`` engine writes out the required copies of a counted repeat when it
compiles: ``(?:x{2000}){2000}`` becomes four million nodes, about a gigabyte.
A schema, or a schema message any node on the graph can publish, must not
make the generator, a node, ``genparams tune`` or ``audit`` compile that.
:func:`check_pattern_cost` counts the items a pattern expands to (each counted
repeat multiplies what it repeats by its required count) on the parse tree of
Python's ``re``, which compiles nothing, and refuses a pattern above
``MAX_PATTERN_ITEMS``.
"""

from __future__ import annotations

import importlib
from typing import Any

from genparams.runtime.core.errors import GenparamsError

# 100,000 items compile in about 0.2 s and 25 MB; real patterns count a few hundred.
MAX_PATTERN_ITEMS = 100_000
# Parsing alone costs time in the pattern's length: real patterns are far shorter.
MAX_PATTERN_LENGTH = 10_000

# Python's own pattern parser (``re._parser``, the syntax ``re`` reads): it builds a
# tree and compiles nothing. Private, so it is typed loosely here.
_PARSER: Any = importlib.import_module("re._parser")
_CONSTANTS: Any = importlib.import_module("re._constants")
_REPEATS = frozenset(
    getattr(_CONSTANTS, name)
    for name in ("MAX_REPEAT", "MIN_REPEAT", "POSSESSIVE_REPEAT")
    if hasattr(_CONSTANTS, name)
)
_SUBPATTERN = _CONSTANTS.SUBPATTERN
_BRANCH = _CONSTANTS.BRANCH
_ASSERTS = frozenset({_CONSTANTS.ASSERT, _CONSTANTS.ASSERT_NOT})
_GROUPREF_EXISTS = _CONSTANTS.GROUPREF_EXISTS
_ATOMIC_GROUP = getattr(_CONSTANTS, "ATOMIC_GROUP", None)


class PatternCostError(GenparamsError, ValueError):
    """A pattern too long, too deeply nested, or whose counted repeats expand too far."""


def _items(tree: Any, cap: int) -> int:
    """Items ``tree`` expands to; stops counting once past ``cap``."""
    total = 0
    for op, argument in tree:
        if op in _REPEATS:
            low, high, body = argument
            # The engine writes out the ``low`` required copies and keeps one more for
            # the optional rest: count them all.
            copies = low + (1 if high != low else 0)
            inner = _items(body, cap)
            total += inner * copies if copies else inner
        elif op is _SUBPATTERN:
            total += _items(argument[-1], cap)
        elif op is _BRANCH:
            total += sum(_items(branch, cap) for branch in argument[1])
        elif op in _ASSERTS:
            total += _items(argument[1], cap)
        elif op is _GROUPREF_EXISTS:
            total += sum(_items(arm, cap) for arm in argument[1:] if arm is not None)
        elif _ATOMIC_GROUP is not None and op is _ATOMIC_GROUP:
            total += _items(argument, cap)
        else:
            total += 1
        if total > cap:
            return total
    return total


def pattern_items(pattern: str) -> int:
    """How many items ``pattern`` expands to when compiled, counted up to just past the bound.

    Raises ``re.error`` for a pattern ``re`` cannot read (with ``re``'s message).
    """
    return _items(_PARSER.parse(pattern), MAX_PATTERN_ITEMS)


def check_pattern_cost(pattern: str) -> None:
    """Refuse ``pattern`` (PatternCostError) when compiling it would cost too much.

    Too much is longer than ``MAX_PATTERN_LENGTH``, nested deeper than Python can parse,
    or expanding beyond ``MAX_PATTERN_ITEMS`` items. Call it before any ``regex`` or ``re``
    compile of a pattern that comes from a schema, a schema message or a user.
    Raises ``re.error`` for a pattern ``re`` cannot read.
    """
    shown = f"{pattern[:60]!r}{'...' if len(pattern) > 60 else ''}"
    if len(pattern) > MAX_PATTERN_LENGTH:
        raise PatternCostError(
            f"pattern {shown} is {len(pattern):,} characters long, more than the "
            f"{MAX_PATTERN_LENGTH:,} a pattern may have"
        )
    try:
        items = pattern_items(pattern)
    except RecursionError:
        raise PatternCostError(f"pattern {shown} nests its groups too deeply") from None
    if items > MAX_PATTERN_ITEMS:
        raise PatternCostError(
            f"pattern {shown} expands to more than {MAX_PATTERN_ITEMS:,} items when "
            "compiled (its counted repeats multiply): use fewer or smaller repeat counts"
        )
