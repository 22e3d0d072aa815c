"""Runtime errors, and ``GenparamsError``, the base of every error genparams raises."""

from __future__ import annotations

from collections.abc import Sequence


class GenparamsError(Exception):
    """The base of every error genparams raises (the runtime's and the compiler's)."""


class ParameterDeclarationError(GenparamsError):
    """A node's parameters cannot be declared: every problem is listed, nothing was declared."""

    def __init__(
        self, schema: str, node: str, problems: Sequence[str], doing: str = "declare"
    ) -> None:
        self.problems = tuple(problems)
        count = len(self.problems)
        noun = "problem" if count == 1 else "problems"
        lines = [f"{node}: cannot {doing} {schema} parameters ({count} {noun}):"]
        lines.extend(f"  - {p}" for p in self.problems)
        super().__init__("\n".join(lines))


class DetachedSnapshotError(GenparamsError, RuntimeError):
    """A snapshot or ``defaults()`` value was asked to do something only a declared view can."""


class RemoteParameterError(GenparamsError, RuntimeError):
    """Another node's parameters could not be read as the schema says they are."""


class RemoteSetError(RemoteParameterError):
    """A remote set was refused: by the schema before sending (``sent`` False), or by the node."""

    def __init__(self, reason: str, *, sent: bool) -> None:
        self.reason = reason
        self.sent = sent
        where = "rejected by the node" if sent else "rejected before sending"
        super().__init__(f"{where}: {reason}")
