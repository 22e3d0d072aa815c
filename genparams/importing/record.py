"""The record of one import: the schema as plain data, each parameter's fate, and what the
user must read about it (warnings: something lost; notes: a change of form, nothing lost;
errors: something the source's own tool refuses, so nothing is written)."""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any, Literal

from genparams.errors import Problem

Fate = Literal["exact", "approximate", "left out"]
EXACT: Fate = "exact"  # every field the source states is in the schema
APPROXIMATE: Fate = "approximate"  # in the schema, part of it unread (a warning says which)
LEFT_OUT: Fate = "left out"  # not in the schema (a warning says why)


@dataclass(frozen=True)
class Outcome:
    """What became of one parameter of the source."""

    name: str  # as the source names it (dotted)
    fate: Fate
    key: str = ""  # its key in the schema ("" when left out): ``gains.*.p`` in a mapped group


@dataclass(frozen=True)
class Imported:
    """One source read into a schema. Warnings, notes and errors are problems whose key
    names the parameter (or the source's key) they are about."""

    name: str  # the schema's name
    data: Mapping[str, Any]  # the schema as plain data, keys in order
    outcomes: tuple[Outcome, ...] = ()  # one per parameter of the source, in source order
    warnings: tuple[Problem, ...] = ()
    notes: tuple[Problem, ...] = ()
    errors: tuple[Problem, ...] = ()

    @property
    def parameters(self) -> int:
        """How many parameters the source holds."""
        return len(self.outcomes)

    @property
    def imported(self) -> int:
        """How many of them the schema holds."""
        return sum(1 for outcome in self.outcomes if outcome.fate != LEFT_OUT)

    def count(self, fate: Fate) -> int:
        return sum(1 for outcome in self.outcomes if outcome.fate == fate)

    def findings(self) -> list[Problem]:
        """Notes and warnings in the order a reader meets them: by place (a FILE:LINE:COL
        by file, then line and column as numbers), notes first at one place, each kind
        otherwise in the order the importer found them."""
        return sorted([*self.notes, *self.warnings], key=_place_order)

    def summary(self) -> str:
        """``imported 3 of 4 parameters (1 approximately); 1 left out (see warnings)``."""
        lost = self.count(LEFT_OUT)
        approximate = self.count(APPROXIMATE)
        return (
            f"imported {self.parameters - lost} of {self.parameters} parameters"
            + (f" ({approximate} approximately)" if approximate else "")
            + (f"; {lost} left out (see warnings)" if lost else "")
        )


_LOCATION = re.compile(r"(?P<file>.*):(?P<line>\d+):(?P<column>\d+)")


def _place_order(problem: Problem) -> tuple[str, int, int]:
    match = _LOCATION.fullmatch(problem.place)
    if match is None:
        return (problem.place, 0, 0)
    return (match["file"], int(match["line"]), int(match["column"]))


def in_order(problems: Iterable[Problem]) -> list[Problem]:
    """Problems sorted by place as ``Imported.findings`` sorts them."""
    return sorted(problems, key=_place_order)
