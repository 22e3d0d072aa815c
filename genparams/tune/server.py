"""Run the tuning page on uvicorn: in the foreground (the command) or a thread (tests, benches)."""

from __future__ import annotations

import secrets
import threading
import time
from pathlib import Path

import uvicorn

from genparams.live.graph import Graph
from genparams.tune.app import TuneApp
from genparams.tune.connections import bounded_protocol
from genparams.tune.security import token_problem, url_host


def new_token() -> str:
    return secrets.token_urlsafe(24)


class TuneServer:
    """The page for the live graph at ``url``, which carries the token (a new one per run).

    Every API call needs the token, on loopback too: any local program, and any
    web page the browser shows, can reach a loopback port.
    """

    def __init__(
        self,
        host: str = "127.0.0.1",
        port: int = 0,
        *,
        nodes: tuple[str, ...] = (),
        read_only: bool = False,
        token: str | None = None,
        graph: Graph | None = None,
        trusted_packages: tuple[str, ...] = (),
        include_hidden: bool = False,
        keep: tuple[tuple[Path, ...], Path | None] = ((), None),  # params files, new values
    ) -> None:
        if token is None:
            token = new_token()
        elif (problem := token_problem(token)) is not None:
            raise ValueError(problem)
        self.host = host
        self.token = token
        self.owns_graph = graph is None
        self.graph = graph if graph is not None else Graph()
        self.app = TuneApp(
            self.graph,
            token=token,
            read_only=read_only,
            nodes=nodes,
            host=host,
            trusted_packages=trusted_packages,
            include_hidden=include_hidden,
            keep=keep,
        )
        config = uvicorn.Config(
            self.app.starlette(),
            host=host,
            port=port,
            http=bounded_protocol(),  # idle and slow connections bounded in number and time
            log_level="warning",
            access_log=False,  # a request line could carry the token
            server_header=False,
            lifespan="off",
            timeout_graceful_shutdown=1,
        )
        self.server = uvicorn.Server(config)
        self.thread: threading.Thread | None = None

    @property
    def port(self) -> int:
        return int(self.server.servers[0].sockets[0].getsockname()[1])

    @property
    def base(self) -> str:
        """``http://HOST:PORT`` without the token: for API calls that send it in a header."""
        shown = (
            "127.0.0.1"
            if self.host in ("0.0.0.0", "")
            else "[::1]"
            if self.host == "::"
            else self.host
        )
        return f"http://{url_host(shown)}:{self.port}"

    @property
    def url(self) -> str:
        """The page's address with the token, for the browser (which keeps it in a cookie)."""
        return f"{self.base}/?token={self.token}"

    def start(self, timeout: float = 10.0) -> str:
        """Serve from a background thread; return the URL once the socket listens."""
        self.thread = threading.Thread(target=self.server.run, name="genparams-tune", daemon=True)
        self.thread.start()
        deadline = time.monotonic() + timeout
        while not self.server.started:
            if time.monotonic() > deadline or not self.thread.is_alive():
                raise RuntimeError("the tuning server did not start")
            time.sleep(0.01)
        return self.url

    def stop(self) -> None:
        self.server.should_exit = True
        if self.thread is not None:
            self.thread.join(timeout=5.0)
        if self.owns_graph:
            self.graph.close()
