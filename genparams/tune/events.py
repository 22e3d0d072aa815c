"""Server-sent events for open pages: few streams, each with a bounded buffer.

Events come from the graph's executor thread. Each stream holds at most
``MAX_QUEUED`` events not yet written; a page that stops reading is dropped
(its browser reconnects and reloads the node), never buffered without bound.
At most ``MAX_STREAMS`` streams are open at once; the next one gets 503.
Each event is written by the one JSON codec, as every answer of the API.
"""

from __future__ import annotations

import asyncio
import threading
from collections.abc import AsyncIterator, Callable
from typing import Any

from starlette.responses import Response, StreamingResponse
from starlette.types import Receive, Scope, Send

from genparams.live.graph import Graph
from genparams.runtime.core.json_codec import dumps
from genparams.tune.json_response import JSONResponse

KEEPALIVE_SECONDS = 15.0
MAX_STREAMS = 16
MAX_QUEUED = 1000
DROPPED = {"kind": "dropped"}


class EventStreams:
    """The open event streams over one graph; ``shown`` says which nodes' events go out."""

    def __init__(
        self,
        graph: Graph,
        shown: Callable[[str], bool],
        *,
        max_streams: int = MAX_STREAMS,
        max_queued: int = MAX_QUEUED,
    ) -> None:
        self.graph = graph
        self.shown = shown
        self.max_streams = max_streams
        self.max_queued = max_queued
        self.lock = threading.Lock()
        self.open = 0

    def response(self) -> Response:
        with self.lock:
            if self.open >= self.max_streams:
                return JSONResponse(
                    {"error": f"at most {self.max_streams} event streams at once"},
                    status_code=503,
                )
            self.open += 1
        return Stream(self.stream(), self.release)

    def release(self) -> None:
        with self.lock:
            self.open -= 1

    async def stream(self) -> AsyncIterator[str]:
        loop = asyncio.get_running_loop()
        queue: asyncio.Queue[dict[str, Any]] = asyncio.Queue(self.max_queued + 1)

        def put(event: dict[str, Any]) -> None:
            if queue.qsize() >= self.max_queued:
                if queue.qsize() == self.max_queued:
                    queue.put_nowait(DROPPED)
                return
            queue.put_nowait(event)

        def listener(event: dict[str, Any]) -> None:
            if self.shown(str(event.get("node", ""))):
                loop.call_soon_threadsafe(put, event)

        unsubscribe = self.graph.subscribe(listener)
        try:
            yield ": connected\n\n"
            while True:
                try:
                    event = await asyncio.wait_for(queue.get(), KEEPALIVE_SECONDS)
                except TimeoutError:
                    yield ": keepalive\n\n"
                    continue
                if event is DROPPED:
                    return  # a reader this slow reconnects and reads the node again
                yield f"data: {dumps(event)}\n\n"  # the codec: NaN and infinities as tags
        finally:
            unsubscribe()


class Stream(StreamingResponse):
    """An event stream that gives its place back however it ends (even never started)."""

    def __init__(self, events: AsyncIterator[str], release: Callable[[], None]) -> None:
        super().__init__(
            events, media_type="text/event-stream", headers={"cache-control": "no-store"}
        )
        self.release = release

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        try:
            await super().__call__(scope, receive, send)
        finally:
            self.release()
