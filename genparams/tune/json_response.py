"""The tuning API's JSON responses, written by the codec: NaN and infinities as tagged objects.

Starlette's own JSONResponse refuses them (``allow_nan=False``), which ended the
connection for any node holding a NaN or an infinite default or bound.
"""

from __future__ import annotations

from typing import Any

from starlette.responses import JSONResponse as StarletteJSONResponse

from genparams.runtime.core.json_codec import dumps


class JSONResponse(StarletteJSONResponse):
    def render(self, content: Any) -> bytes:
        return dumps(content, separators=(",", ":")).encode("ascii")
