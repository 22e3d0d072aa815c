"""What ``on_change`` subscribers receive: the committed change, with values before and after."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any, Generic, TypeVar

P = TypeVar("P")


@dataclass(frozen=True)
class Change:
    name: str  # dotted ROS name relative to the class's prefix
    old: Any
    new: Any


@dataclass(frozen=True)
class Changes(Generic[P]):
    """One accepted set: ``before`` and ``after`` are consistent snapshots."""

    before: P
    after: P
    changed: tuple[Change, ...]

    @property
    def names(self) -> frozenset[str]:
        return frozenset(c.name for c in self.changed)

    def __contains__(self, name: object) -> bool:
        return any(c.name == name for c in self.changed)

    def __iter__(self) -> Iterator[Change]:
        return iter(self.changed)

    def __len__(self) -> int:
        return len(self.changed)
