"""The one error model: every error genparams raises is a ``GenparamsError``.

A problem is a record of four fields, ``place`` (``FILE:LINE:COL`` or a node
name), ``key`` (the dotted parameter or schema key, may be empty), ``rule``
(the rule broken, shown in brackets when given) and ``message``; every problem
reaches a user as one line written by ``render_problem``. Commands raise
``CommandError``, which carries the exit code; ``genparams.cli.main`` prints it.

The base class, the problem record and its renderer live with the runtime
(``genparams.runtime.core.errors``, ``genparams.runtime.core.problems``), so generated
modules need nothing of the compiler; the compiler and the commands import
them from here.
"""

from __future__ import annotations

from genparams.runtime.core.errors import GenparamsError
from genparams.runtime.core.problems import (
    ParameterProblem,
    Problem,
    render_problem,
    render_problems,
)
from genparams.runtime.core.visible import visible

__all__ = [
    "CommandError",
    "GenparamsError",
    "ParameterProblem",
    "Problem",
    "render_problem",
    "render_problems",
]


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
