"""The page's "Keep these values": a node's current values written back into the params
files ``genparams tune --params-file`` named, at the place each value came from
(genparams.outputs.keep_values); values no file gave, off their schema default, go to
``--new-values``. ``GET /api/keep?node=N`` shows the diff; ``POST /api/keep`` with
``{"node": N}`` writes it. Both need the page's token, and the write is refused on a
read-only page, like every other change.
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import Response
from starlette.routing import Route

from genparams.integration.writing import write_all
from genparams.outputs.keep_values import Change, KeepError, NodeValues, apply, plan, read_texts
from genparams.paramsfile.params_reader import ParamsDocument, read_params_file
from genparams.runtime.core.json_codec import loads
from genparams.runtime.core.schema_message import param_from_json
from genparams.tune.bodies import RequestError
from genparams.tune.json_response import JSONResponse

KEEP_PATH = "/api/keep"


class Keeper:
    def __init__(self, app: Any, files: tuple[Path, ...], new_values: Path | None) -> None:
        self.app = app  # the TuneApp: its graph, its node checks, its read-only flag
        self.files = files
        self.new_values = new_values

    def routes(self) -> list[Route]:
        return [
            Route(KEEP_PATH, self.preview, methods=["GET"]),
            Route(KEEP_PATH, self.write, methods=["POST"]),
        ]

    def changes(self, node: str) -> tuple[list[Change], dict[str, str], dict[str, str]]:
        """What keeping ``node``'s values changes: the changes, files' texts before, after."""
        parameters = self.app.graph.read_node(node)
        values = {p["name"]: p["value"] for p in parameters if p["type"] != "unset"}
        defaults = off_default(self.app.graph.schema(node), values)
        paths = [*self.files, *([self.new_values] if self.new_values else [])]
        before = read_texts([str(p) for p in paths])
        documents = [_document(before, str(p)) for p in paths if str(p) in before]
        new_file = None if self.new_values is None else str(self.new_values)
        changes = plan([NodeValues(node, values, defaults)], documents, new_file)
        after = apply(changes, before)
        return changes, before, after

    async def preview(self, request: Request) -> Response:
        node = await self.app.target(request.query_params.get("node"))
        try:
            changes, before, after = await run_in_threadpool(self.changes, node)
        except (TimeoutError, KeepError) as exc:
            return JSONResponse({"error": str(exc)}, status_code=409)
        diff = "".join(
            "".join(
                difflib.unified_diff(
                    before.get(file, "").splitlines(keepends=True),
                    text.splitlines(keepends=True),
                    fromfile=file,
                    tofile=file,
                )
            )
            for file, text in after.items()
        )
        return JSONResponse({"node": node, "changes": [str(c) for c in changes], "diff": diff})

    async def write(self, request: Request) -> Response:
        if self.app.read_only:
            return JSONResponse({"error": "this page is read-only"}, status_code=403)
        body = loads((await request.body()).decode("utf-8", "replace") or "null")
        if not isinstance(body, dict):
            raise RequestError('expected {"node": "/ns/name"}')
        node = await self.app.target(body.get("node"))
        try:
            changes, _, after = await run_in_threadpool(self.changes, node)
            await run_in_threadpool(write_all, {Path(f): t for f, t in after.items()})
        except (TimeoutError, KeepError, OSError) as exc:
            return JSONResponse({"error": str(exc)}, status_code=409)
        return JSONResponse({"node": node, "changes": [str(c) for c in changes]})


def _document(texts: Mapping[str, str], file: str) -> ParamsDocument:
    return read_params_file(texts[file], file)


def off_default(schema: Mapping[str, Any] | None, values: Mapping[str, Any]) -> dict[str, Any]:
    """Name -> default for each parameter of the schema message that has one (the plan
    keeps those whose value differs); mapped entries are left out."""
    defaults: dict[str, Any] = {}
    for described in (schema or {}).get("classes", []):
        for param in described["parameters"]:
            name = param["name"]
            if "default" in param and name in values:
                spec = param_from_json(param, name)
                if spec.default is not None:
                    defaults[name] = spec.default
    return defaults
