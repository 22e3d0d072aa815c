"""The cost of compiling a pattern a node's schema message names, told before it is compiled.

The rule is the runtime's own (:func:`genparams.runtime.core.pattern_cost.check_pattern_cost`);
this is the question the reader asks of every pattern in a message, answered as a
problem text: a pattern that costs too much makes the message a problem, never a stall.
"""

from __future__ import annotations

import re

from genparams.runtime.core.pattern_cost import PatternCostError, check_pattern_cost


def pattern_cost_problem(pattern: str) -> str | None:
    """Why compiling ``pattern`` costs too much, if it does (its syntax is checked later)."""
    try:
        check_pattern_cost(pattern)
    except PatternCostError as exc:
        return str(exc)
    except (re.error, OverflowError, ValueError):
        return None  # not a pattern: the runtime's own check names the error
    return None
