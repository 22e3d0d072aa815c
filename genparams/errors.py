"""The one error model: every error genparams raises is a ``GenparamsError``.

A problem is a record of four fields, ``place`` (``FILE:LINE:COL`` or a node
name), ``key`` (the dotted parameter or schema key, may be empty), ``rule``
(the rule broken, shown in brackets when given) and ``message``; every problem
reaches a user as one line written by ``render_problem``. Commands raise
``CommandError``, which carries the exit code; ``genparams.cli.main`` prints it.

The base class lives with the runtime's errors, so generated modules need
nothing of the compiler; the compiler and the commands import it from here.
"""

from __future__ import annotations

from typing import Protocol

from genparams.runtime.core.errors import GenparamsError
from genparams.runtime.core.visible import visible

__all__ = ["CommandError", "GenparamsError", "Problem", "render_problem"]


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


def render_problem(problem: Problem) -> str:
    """``place: key: message [rule]`` on one line, every character shown (see ``visible``)."""
    text = ": ".join(part for part in (problem.place, problem.key, problem.message) if part)
    if problem.rule:
        text += f" [{problem.rule}]"
    return visible(text)


class CommandError(GenparamsError):
    """A command cannot do what it was asked: its messages go to stderr, it exits ``exit_code``.

    A ``str`` message is one line written by the command, shown with every
    character visible; an exception message is that error's own text, each of
    its lines shown the same way.
    """

    def __init__(self, *messages: str | BaseException, exit_code: int = 2) -> None:
        self.exit_code = exit_code
        lines: list[str] = []
        for message in messages:
            if isinstance(message, BaseException):
                lines.extend(visible(line) for line in str(message).split("\n"))
            else:
                lines.append(visible(message))
        self.lines = tuple(lines)
        super().__init__("\n".join(lines))
