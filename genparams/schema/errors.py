"""Schema errors that name their place: FILE:LINE:COL: dotted.key: what is wrong."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from genparams.errors import GenparamsError, render_problem


@dataclass(frozen=True, order=True)
class Location:
    file: str
    line: int  # 1-based
    column: int  # 1-based

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}"


@dataclass(frozen=True, order=True)
class SchemaProblem:
    location: Location
    key: str  # dotted path in the document, "" for the document itself
    message: str

    rule = ""  # a schema problem's message names its rule

    @property
    def place(self) -> str:
        return str(self.location)

    def __str__(self) -> str:
        return render_problem(self)  # one line, every char shown


class SchemaError(GenparamsError):
    """One or more problems in a schema file; all are reported at once."""

    def __init__(self, problems: Iterable[SchemaProblem]) -> None:
        self.problems = tuple(sorted(set(problems)))
        super().__init__("\n".join(str(p) for p in self.problems))
