"""Idle and slow connections to the tuning server, bounded in number and time.

A connection costs a file descriptor and needs no token: a local program could
open connections that never send a request (or send it a byte at a time) until
the server can accept no more, and the page's own requests go unanswered. So:

- a connection gets ``REQUEST_TIMEOUT_S`` to send each whole request, headers and
  body, counted from when it opens or its previous answer ended; it is closed
  when that runs out;
- at most ``max_connections`` are open at once (fewer than the descriptors the
  process may still open); one more closes the oldest connection that is
  waiting for its request, or, when every connection is busy answering, the new one.

Busy connections (a request being answered, an event stream) are never closed
here: event streams are limited in number by the app.
"""

from __future__ import annotations

import asyncio
import os
import resource
import time
from typing import Any

from uvicorn.protocols.http.h11_impl import H11Protocol

REQUEST_TIMEOUT_S = 10.0
MOST_CONNECTIONS = 256
FEWEST_CONNECTIONS = 8


def open_descriptors() -> int:
    """How many file descriptors this process holds now."""
    try:
        return len(os.listdir("/proc/self/fd"))
    except OSError:
        return 64  # a guess where /proc is not mounted


def connection_limit() -> int:
    """Connections the server may hold: half the descriptors still free, within bounds."""
    soft, _hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    if soft == resource.RLIM_INFINITY:
        return MOST_CONNECTIONS
    free = soft - open_descriptors()
    return max(FEWEST_CONNECTIONS, min(MOST_CONNECTIONS, free // 2))


class BoundedH11Protocol(H11Protocol):
    """uvicorn's h11 protocol with a deadline per request and a cap on connections.

    ``request_timeout`` and ``max_connections`` are set on a subclass made by
    :func:`bounded_protocol`, as uvicorn builds the protocol itself.
    """

    request_timeout: float = REQUEST_TIMEOUT_S
    max_connections: int = MOST_CONNECTIONS

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.opened = time.monotonic()
        self.deadline: asyncio.TimerHandle | None = None

    def waiting(self) -> bool:
        """True while the connection owes a request (none is being answered)."""
        return self.deadline is not None

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
        super().connection_made(transport)
        self._start_deadline()
        if len(self.connections) > self.max_connections:
            self._make_room()

    def connection_lost(self, exc: Exception | None) -> None:
        self._stop_deadline()
        super().connection_lost(exc)

    def data_received(self, data: bytes) -> None:
        super().data_received(data)
        cycle = self.cycle
        if cycle is not None and not cycle.more_body and not cycle.response_complete:
            self._stop_deadline()  # the whole request is in: it is being answered

    def on_response_complete(self) -> None:
        super().on_response_complete()
        if not self.transport.is_closing():
            self._start_deadline()

    def _start_deadline(self) -> None:
        self._stop_deadline()
        self.deadline = self.loop.call_later(self.request_timeout, self._close)

    def _stop_deadline(self) -> None:
        if self.deadline is not None:
            self.deadline.cancel()
            self.deadline = None

    def _close(self) -> None:
        self.deadline = None
        if not self.transport.is_closing():
            self.transport.close()

    def _make_room(self) -> None:
        waiting = [c for c in self.connections if isinstance(c, BoundedH11Protocol) and c.waiting()]
        others = [c for c in waiting if c is not self]
        oldest = min(others, key=lambda c: c.opened) if others else self
        oldest._stop_deadline()
        oldest._close()


def bounded_protocol(
    request_timeout: float = REQUEST_TIMEOUT_S, max_connections: int | None = None
) -> type[BoundedH11Protocol]:
    """The protocol class to give uvicorn (``http=``), with these bounds."""
    limit = connection_limit() if max_connections is None else max_connections
    return type(
        "BoundedH11Protocol",
        (BoundedH11Protocol,),
        {"request_timeout": request_timeout, "max_connections": limit},
    )
