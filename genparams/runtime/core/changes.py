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
from typing import Any, Generic, TypeVar

from genparams.runtime.core.records import Record, store

P = TypeVar("P")


class Change(Record):
    """One parameter's committed change (a frozen record)."""

    _fields = ("name", "old", "new")  # __init__ order
    __slots__ = _fields
    name: str  # dotted ROS name relative to the class's prefix
    old: Any
    new: Any

    def __init__(self, name: str, old: Any, new: Any) -> None:
        store(self, "name", name)
        store(self, "old", old)
        store(self, "new", new)


class Changes(Record, Generic[P]):
    """One accepted set: ``before`` and ``after`` are consistent snapshots."""

    _fields = ("before", "after", "changed")  # __init__ order
    __slots__ = _fields
    before: P
    after: P
    changed: tuple[Change, ...]

    def __init__(self, before: P, after: P, changed: tuple[Change, ...]) -> None:
        store(self, "before", before)
        store(self, "after", after)
        store(self, "changed", changed)

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
