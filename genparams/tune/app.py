"""The tuning page's web app (Starlette): static page, JSON API, server-sent events.

Every call to ROS blocks on a service answer, so it runs in Starlette's thread
pool; events from ``/parameter_events`` reach each open page through
:mod:`genparams.tune.events`. Every request passes :mod:`genparams.tune.security`
first; :mod:`genparams.tune.bodies` reads what it sends, and every answer is
written by the one JSON codec (:mod:`genparams.tune.json_response`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import FileResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles
from starlette.types import ASGIApp

from genparams._version import __version__
from genparams.live.answers import NodeAnswerError
from genparams.live.graph import Graph
from genparams.live.services import StillWorkingError
from genparams.tune.bodies import RequestError, edits, node_name, set_request
from genparams.tune.checking import Checker
from genparams.tune.events import EventStreams
from genparams.tune.json_response import JSONResponse
from genparams.tune.keep import KEEP_PATH, Keeper
from genparams.tune.params_dump import params_file_text
from genparams.tune.places import entry_places
from genparams.tune.security import Gate, Policy

STATIC = Path(__file__).resolve().parent / "static"
SET_WAIT_SECONDS = 5.0  # a set not answered by then is told as still working (202), not failed
WRITES = frozenset(
    {"/api/set", KEEP_PATH}
)  # /api/check changes nothing: a read-only page may ask it


class TuneApp:
    """The routes over one :class:`Graph`, behind the :class:`Gate` of ``token``.

    Naming ``nodes`` restricts every route to them: others are not listed, not
    read, not set, and their events are not sent. Hidden nodes (names starting
    with ``_``) are listed with ``include_hidden`` only; any node can be named.
    """

    def __init__(
        self,
        graph: Graph,
        *,
        token: str,
        read_only: bool = False,
        nodes: tuple[str, ...] = (),
        host: str = "127.0.0.1",
        trusted_packages: tuple[str, ...] = (),
        include_hidden: bool = False,
        keep: tuple[tuple[Path, ...], Path | None] = ((), None),
    ) -> None:
        self.graph = graph
        self.include_hidden = include_hidden
        self.keeper = Keeper(self, *keep)
        self.policy = Policy(token=token, bound_host=host, read_only=read_only, writes=WRITES)
        self.checker = Checker(graph.node, trusted_packages)
        self.read_only = read_only
        self.only_nodes = nodes
        self.streams = EventStreams(graph, self.shown)

    def starlette(self) -> ASGIApp:
        app = Starlette(
            routes=[
                Route("/", self.index),
                Route("/api/config", self.config),
                Route("/api/nodes", self.nodes),
                Route("/api/node", self.node),
                Route("/api/set", self.set, methods=["POST"]),
                Route("/api/check", self.check, methods=["POST"]),
                Route("/api/params-file", self.params_file),
                Route("/api/events", self.events),
                *self.keeper.routes(),
                Mount("/static", StaticFiles(directory=STATIC), name="static"),
            ],
            exception_handlers={RequestError: bad_request, NodeAnswerError: bad_answer},
        )
        return Gate(app, self.policy)

    def shown(self, name: str) -> bool:
        return not self.only_nodes or name in self.only_nodes

    async def target(self, given: object) -> str:
        """The node a request names: valid, served here and in the graph, or a refusal."""
        name = node_name(given)
        if not self.shown(name):
            raise NotServedError(403, f"{name} is not served by this page")
        if name not in await run_in_threadpool(self.graph.node_names):
            # No service clients for a node that is not there: each would stay behind.
            raise NotServedError(404, f"{name} is not in the graph")
        return name

    async def index(self, request: Request) -> Response:
        return FileResponse(STATIC / "index.html", headers={"cache-control": "no-store"})

    async def config(self, request: Request) -> Response:
        return JSONResponse({"read_only": self.read_only, "version": __version__})

    async def nodes(self, request: Request) -> Response:
        def listed() -> list[dict[str, Any]]:
            found = []
            hidden = self.include_hidden or bool(self.only_nodes)  # a node named is listed
            for n in filter(self.shown, self.graph.node_names(hidden=hidden)):
                schema, problem = self.graph.schema_state(n)
                found.append(
                    {"name": n, "genparams": schema is not None, "schema_problem": problem}
                )
            return found

        return JSONResponse({"nodes": await run_in_threadpool(listed)})

    async def node(self, request: Request) -> Response:
        """A node's parameters, schema and entry places: all of it read off the event loop."""
        name = await self.target(request.query_params.get("name"))

        def answer() -> dict[str, Any]:
            parameters = self.graph.read_node(name)
            schema, problem = self.graph.schema_state(name)
            return {
                "node": name,
                "schema": schema,
                "schema_problem": problem,
                "parameters": parameters,
                "places": entry_places(schema, parameters),
            }

        try:
            return JSONResponse(await run_in_threadpool(answer))
        except TimeoutError as exc:
            return JSONResponse({"error": str(exc)}, status_code=504)

    async def set(self, request: Request) -> Response:
        if self.read_only:  # the gate refuses it first; a second lock on the one write
            return JSONResponse({"error": "this page is read-only"}, status_code=403)
        wanted = set_request(await request.body())
        node = await self.target(wanted.node)
        try:
            results = await run_in_threadpool(
                self.graph.set_parameters,
                node,
                wanted.parameters,
                wanted.atomic,
                SET_WAIT_SECONDS,
            )
        except StillWorkingError as exc:  # sent once; its outcome comes as a "set" event
            body = {"pending": True, "detail": str(exc), "set": exc.set_id, "results": []}
            return JSONResponse(body, 202)
        except TimeoutError as exc:
            return JSONResponse({"error": str(exc)}, status_code=504)
        return JSONResponse({"results": results})

    async def check(self, request: Request) -> Response:
        """What the node would answer to an atomic set of ``params``, without setting them."""
        wanted = edits(await request.body())
        node = await self.target(wanted.node)

        def answer() -> dict[str, Any]:
            message = self.graph.schema(node)
            reads = self.checker.wanted(node, message, wanted.params)
            declared, current = self.graph.read_parameters(node, reads)
            return self.checker.check(node, message, current, wanted.params, declared)

        try:
            return JSONResponse(await run_in_threadpool(answer))
        except TimeoutError as exc:
            return JSONResponse({"error": str(exc)}, status_code=504)

    async def params_file(self, request: Request) -> Response:
        name = await self.target(request.query_params.get("node"))

        def answer() -> str:
            parameters = self.graph.read_node(name)
            return params_file_text(name, parameters, self.graph.schema(name))

        try:
            text = await run_in_threadpool(answer)
        except TimeoutError as exc:
            return JSONResponse({"error": str(exc)}, status_code=504)
        filename = name.strip("/").replace("/", "_") or "node"
        return Response(
            text,
            media_type="application/x-yaml",
            headers={"content-disposition": f'attachment; filename="{filename}.yaml"'},
        )

    async def events(self, request: Request) -> Response:
        return self.streams.response()


class NotServedError(RequestError):
    """A well-formed request this page will not serve (403) or cannot find (404)."""

    def __init__(self, status: int, reason: str) -> None:
        super().__init__(reason)
        self.status = status


async def bad_request(request: Request, exc: Exception) -> Response:
    status = exc.status if isinstance(exc, NotServedError) else 400
    return JSONResponse({"error": str(exc)}, status_code=status)


async def bad_answer(request: Request, exc: Exception) -> Response:
    """A node answered what cannot be used: the request was fine, the node is not (422)."""
    return JSONResponse({"error": str(exc)}, status_code=422)
