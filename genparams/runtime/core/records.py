"""Small immutable records, compared, hashed and shown by value like frozen dataclasses.

``@dataclass`` writes each class's methods as source text and compiles it when the
module is imported, about 0.2 ms a class; a process that declares a class pays it
for every record type the runtime has. A record here is a slotted class with a
hand-written ``__init__`` (storing through ``object.__setattr__``, as a frozen
dataclass does) and this base's generic equality, hash, repr and pickling over
``_fields``, the fields given to ``__init__`` in its order.
"""

from __future__ import annotations

from typing import Any, ClassVar

store = object.__setattr__
"""How a record's ``__init__`` sets a field of a frozen record."""


class Record:
    __slots__ = ()
    _fields: ClassVar[tuple[str, ...]] = ()

    def _values(self) -> tuple[Any, ...]:
        return tuple([getattr(self, name) for name in self._fields])

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Record) and other.__class__ is self.__class__:
            return self._values() == other._values()
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self._values())

    def __repr__(self) -> str:
        shown = ", ".join(f"{name}={getattr(self, name)!r}" for name in self._fields)
        return f"{type(self).__qualname__}({shown})"

    def __setattr__(self, name: str, value: Any) -> None:
        from dataclasses import FrozenInstanceError  # what a frozen dataclass raises

        raise FrozenInstanceError(f"cannot assign to field {name!r}")

    def __delattr__(self, name: str) -> None:
        from dataclasses import FrozenInstanceError  # what a frozen dataclass raises

        raise FrozenInstanceError(f"cannot delete field {name!r}")

    def __reduce__(self) -> tuple[Any, ...]:
        return (type(self), self._values())
