"""Runtime errors."""

from __future__ import annotations

from collections.abc import Sequence


class ParameterDeclarationError(Exception):
    """A node's parameters cannot be declared: every problem is listed, nothing was declared."""

    def __init__(self, schema: str, node: str, problems: Sequence[str]) -> None:
        self.problems = tuple(problems)
        count = len(self.problems)
        noun = "problem" if count == 1 else "problems"
        lines = [f"{node}: cannot declare {schema} parameters ({count} {noun}):"]
        lines.extend(f"  - {p}" for p in self.problems)
        super().__init__("\n".join(lines))


class DetachedSnapshotError(RuntimeError):
    """A snapshot or ``defaults()`` value was asked to do something only a declared view can."""
