"""Problems as records, and the one way a problem is written for a user.

A problem is four fields: ``place`` (``FILE:LINE:COL``, a node name, or empty
where the reader already knows it), ``key`` (the dotted parameter or schema
key, may be empty), ``rule`` (the rule broken, shown in brackets when given;
empty when the message names it in its own words) and ``message``.
``render_problem`` writes every problem genparams reports, whoever found it:
schema errors, params-file checks, audit findings, a node's refusal of a set
(the ``SetParametersResult`` reason) and its refusal to start
(``ParameterDeclarationError``).

This module is the runtime's, so a generated module needs nothing of the
compiler to report a problem; ``genparams.errors`` exports it to the rest.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Protocol

from genparams.runtime.core.records import Record, store
from genparams.runtime.core.visible import visible


class Problem(Protocol):
    """One thing wrong (or worth knowing), where it is and which rule it breaks."""

    @property
    def place(self) -> str: ...

    @property
    def key(self) -> str: ...

    @property
    def rule(self) -> str: ...

    @property
    def message(self) -> str: ...


READ_ONLY = "read-only: set it when the node starts (-p, a params file or launch)"
"""Why a set of a ``read_only`` parameter is refused, by the node and by a remote client."""


class ParameterProblem(Record):
    """A problem with a parameter: one the runtime finds with a value (at a set, at declare,
    remotely), or one a command finds with a parameter of a running node.

    ``key`` is the full ROS name as the node knows it (with its prefix), empty for
    a rule between parameters (its message names the rule and every value it read).
    ``place`` is empty in the runtime's problems, whose reader knows the node, and the
    node's name in a command's. The runtime makes one only when something is refused:
    a set that passes builds none.
    """

    _fields = ("key", "message", "rule", "place")  # __init__ order
    __slots__ = _fields
    key: str
    message: str
    rule: str
    place: str

    def __init__(self, key: str, message: str, rule: str = "", place: str = "") -> None:
        store(self, "key", key)
        store(self, "message", message)
        store(self, "rule", rule)
        store(self, "place", place)

    def __str__(self) -> str:
        return render_problem(self)


def render_problem(problem: Problem) -> str:
    """``place: key: message [rule]`` on one line, every character shown (see ``visible``)."""
    # Written out rather than joined: a refused set renders its reason on the node's
    # parameter service thread, and this is three times quicker than a join.
    key, message = problem.key, problem.message
    text = f"{key}: {message}" if key and message else key or message
    place = problem.place
    if place:
        text = f"{place}: {text}" if text else place
    rule = problem.rule
    return visible(f"{text} [{rule}]" if rule else text)


def render_problems(problems: Iterable[Problem]) -> str:
    """Problems on one line, as a refused set's reason: each rendered, ``; `` between them."""
    return "; ".join([render_problem(problem) for problem in problems])
