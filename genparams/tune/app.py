"""The tuning page's web app (Starlette): static page, JSON API, server-sent events.

Every call to ROS blocks on a service answer, so it runs in Starlette's thread
pool; events from ``/parameter_events`` reach each open page through an
asyncio queue fed from the graph's executor thread.
"""

from __future__ import annotations

import asyncio
import hmac
from collections.abc import AsyncIterator
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import FileResponse, Response, StreamingResponse
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from genparams import __version__
from genparams.runtime.json_codec import API_LIMITS, dumps, loads
from genparams.tune.checking import Checker, json_parameter
from genparams.tune.graph import Graph
from genparams.tune.json_response import JSONResponse
from genparams.tune.params_dump import params_file_text

STATIC = Path(__file__).resolve().parent / "static"
KEEPALIVE_SECONDS = 15.0


class TuneApp:
    """The routes over one :class:`Graph`; ``token`` guards every API call when set."""

    def __init__(
        self,
        graph: Graph,
        *,
        token: str | None = None,
        read_only: bool = False,
        nodes: tuple[str, ...] = (),
        trusted_packages: tuple[str, ...] = (),
    ) -> None:
        self.graph = graph
        self.checker = Checker(graph.node, trusted_packages)
        self.token = token
        self.read_only = read_only
        self.only_nodes = nodes

    def starlette(self) -> Starlette:
        return Starlette(
            routes=[
                Route("/", self.index),
                Route("/api/config", self.config),
                Route("/api/nodes", self.nodes),
                Route("/api/node", self.node),
                Route("/api/set", self.set, methods=["POST"]),
                Route("/api/check", self.check, methods=["POST"]),
                Route("/api/params-file", self.params_file),
                Route("/api/events", self.events),
                Mount("/static", StaticFiles(directory=STATIC), name="static"),
            ]
        )

    def denied(self, request: Request) -> Response | None:
        """A 403 unless the request carries the token (header or query), when one is set."""
        if self.token is None:
            return None
        given = request.headers.get("x-genparams-token") or request.query_params.get("token", "")
        if hmac.compare_digest(given.encode(), self.token.encode()):
            return None
        return JSONResponse({"error": "missing or wrong token"}, status_code=403)

    async def index(self, request: Request) -> Response:
        return FileResponse(STATIC / "index.html", headers={"cache-control": "no-store"})

    async def config(self, request: Request) -> Response:
        if (denied := self.denied(request)) is not None:
            return denied
        return JSONResponse({"read_only": self.read_only, "version": __version__})

    async def nodes(self, request: Request) -> Response:
        if (denied := self.denied(request)) is not None:
            return denied
        names = await run_in_threadpool(self.graph.node_names)
        if self.only_nodes:
            names = [n for n in names if n in self.only_nodes]
        listed = []
        for n in names:
            schema, problem = self.graph.schema_state(n)
            listed.append({"name": n, "genparams": schema is not None, "schema_problem": problem})
        return JSONResponse({"nodes": listed})

    async def node(self, request: Request) -> Response:
        if (denied := self.denied(request)) is not None:
            return denied
        name = request.query_params.get("name", "")
        try:
            parameters = await run_in_threadpool(self.graph.read_node, name)
        except TimeoutError as exc:
            return JSONResponse({"error": str(exc)}, status_code=504)
        schema, problem = self.graph.schema_state(name)
        return JSONResponse(
            {"node": name, "schema": schema, "schema_problem": problem, "parameters": parameters}
        )

    async def set(self, request: Request) -> Response:
        if (denied := self.denied(request)) is not None:
            return denied
        if self.read_only:
            return JSONResponse({"error": "this page is read-only"}, status_code=403)
        try:
            body = loads(await request.body(), API_LIMITS)
            node = str(body["node"])
            parameters = [json_parameter(p["name"], p["type"], p["value"]) for p in body["params"]]
            atomic = bool(body.get("atomic", False))
        except (ValueError, KeyError, TypeError) as exc:
            return JSONResponse({"error": f"bad request: {exc}"}, status_code=400)
        try:
            results = await run_in_threadpool(self.graph.set_parameters, node, parameters, atomic)
        except TimeoutError as exc:
            return JSONResponse({"error": str(exc)}, status_code=504)
        return JSONResponse({"results": results})

    async def check(self, request: Request) -> Response:
        """What the node would answer to an atomic set of ``params``, without setting them."""
        if (denied := self.denied(request)) is not None:
            return denied
        try:
            body = loads(await request.body(), API_LIMITS)
            node = str(body["node"])
            edits = [(str(p["name"]), p["type"], p["value"]) for p in body["params"]]
        except (ValueError, KeyError, TypeError) as exc:
            return JSONResponse({"error": f"bad request: {exc}"}, status_code=400)

        def answer() -> dict[str, Any]:
            message = self.graph.schema(node)
            wanted = self.checker.wanted(node, message, edits)
            declared, current = self.graph.read_parameters(node, wanted)
            return self.checker.check(node, message, current, edits, declared)

        try:
            return JSONResponse(await run_in_threadpool(answer))
        except TimeoutError as exc:
            return JSONResponse({"error": str(exc)}, status_code=504)

    async def params_file(self, request: Request) -> Response:
        if (denied := self.denied(request)) is not None:
            return denied
        name = request.query_params.get("node", "")
        try:
            parameters = await run_in_threadpool(self.graph.read_node, name)
        except TimeoutError as exc:
            return JSONResponse({"error": str(exc)}, status_code=504)
        text = params_file_text(name, parameters, self.graph.schema(name))
        filename = name.strip("/").replace("/", "_") or "node"
        return Response(
            text,
            media_type="application/x-yaml",
            headers={"content-disposition": f'attachment; filename="{filename}.yaml"'},
        )

    async def events(self, request: Request) -> Response:
        if (denied := self.denied(request)) is not None:
            return denied
        loop = asyncio.get_running_loop()
        queue: asyncio.Queue[dict[str, Any]] = asyncio.Queue()

        def listener(event: dict[str, Any]) -> None:
            loop.call_soon_threadsafe(queue.put_nowait, event)

        unsubscribe = self.graph.subscribe(listener)

        async def stream() -> AsyncIterator[str]:
            try:
                yield ": connected\n\n"
                while True:
                    try:
                        event = await asyncio.wait_for(queue.get(), KEEPALIVE_SECONDS)
                    except TimeoutError:
                        yield ": keepalive\n\n"
                        continue
                    yield f"data: {dumps(event)}\n\n"
            finally:
                unsubscribe()

        return StreamingResponse(
            stream(), media_type="text/event-stream", headers={"cache-control": "no-store"}
        )
