"""Runtime errors, and ``GenparamsError``, the base of every error genparams raises."""

from __future__ import annotations

from collections.abc import Sequence

from genparams.runtime.core.problems import Problem, render_problem, render_problems


class GenparamsError(Exception):
    """The base of every error genparams raises (the runtime's and the compiler's)."""


class ParameterDeclarationError(GenparamsError):
    """A node's parameters cannot be declared: every problem is listed, nothing was declared.

    ``problems`` are records (``key``, ``message``: see ``genparams.runtime.core.problems``),
    each shown on a line of its own.
    """

    def __init__(
        self, schema: str, node: str, problems: Sequence[Problem], doing: str = "declare"
    ) -> None:
        self.problems = tuple(problems)
        count = len(self.problems)
        noun = "problem" if count == 1 else "problems"
        lines = [f"{node}: cannot {doing} {schema} parameters ({count} {noun}):"]
        lines.extend(f"  - {render_problem(p)}" for p in self.problems)
        Exception.__init__(self, "\n".join(lines))  # whatever else a subclass derives from


class DetachedSnapshotError(GenparamsError, RuntimeError):
    """A snapshot or ``defaults()`` value was asked to do something only a declared view can."""


class RemoteParameterError(GenparamsError, RuntimeError):
    """Another node's parameters could not be read as the schema says they are."""


class RemoteSetError(RemoteParameterError):
    """A remote set was refused: by the schema before sending (``sent`` False), or by the node.

    ``reason`` is the text the node gives (or would give); ``problems`` the records it
    was written from when the schema refused before sending (empty for the node's own
    reason, which arrives as text).
    """

    def __init__(self, reason: str, *, sent: bool) -> None:
        self.reason = reason
        self.sent = sent
        self.problems: tuple[Problem, ...] = ()
        where = "rejected by the node" if sent else "rejected before sending"
        super().__init__(f"{where}: {reason}")

    @classmethod
    def before_sending(cls, problems: Sequence[Problem]) -> RemoteSetError:
        """The schema refused the values: nothing was sent."""
        error = cls(render_problems(problems), sent=False)
        error.problems = tuple(problems)
        return error
