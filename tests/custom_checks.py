"""Custom validators used by the tests' schemas (imported by module path at declare)."""

from __future__ import annotations


def is_even(value: int) -> str | None:
    return None if value % 2 == 0 else f"{value} is odd"


def always_raises(value: object) -> None:
    raise RuntimeError("checker is broken")
