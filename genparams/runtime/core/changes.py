"""What counts as a change, and what ``on_change`` subscribers receive of one.

A value is changed unless it is the same: a NaN is the same as a NaN.

IEEE says NaN != NaN, so a parameter holding NaN would count as changed by
every set of NaN, waking ``on_change`` with (nan, nan) and making a snapshot
unequal to itself. A parameter either holds NaN or not: re-applying the same
value, NaN included, is no change.

Subscribers receive the committed change, with values before and after.
"""

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


def same_value(a: Any, b: Any) -> bool:
    """``a == b``, with NaN equal to NaN, in scalars and in arrays (tuples)."""
    if a == b:
        return True
    if type(a) is float:
        return type(b) is float and a != a and b != b
    if type(a) is tuple and type(b) is tuple and len(a) == len(b):
        return all(same_value(x, y) for x, y in zip(a, b, strict=True))
    return False


def same_typed_value(a: Any, b: Any) -> bool:
    """``same_value`` of two values of the same type: for a parameter of type ``any``,
    1 and 1.0 (an int then a double), or (1,) and (1.0,), are a change."""
    if type(a) is not type(b) or not same_value(a, b):
        return False
    return type(a) is not tuple or not a or type(a[0]) is type(b[0])
