"""The futures the remote client returns: rclpy Futures that say what they resolve to."""

from __future__ import annotations

from collections.abc import Generator
from typing import Generic, TypeVar, cast

from rclpy.task import Future

T = TypeVar("T")


class TypedFuture(Future, Generic[T]):
    """An rclpy Future that says what it resolves to."""

    def result(self) -> T | None:
        """The result once done (None before); raises the failure if there was one."""
        return cast("T | None", super().result())

    def __await__(self) -> Generator[None, None, T]:
        result = yield from super().__await__()
        return cast(T, result)
