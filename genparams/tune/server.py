"""Run the tuning page on uvicorn: in the foreground (the command) or a thread (tests, benches)."""

from __future__ import annotations

import ipaddress
import secrets
import threading
import time

import uvicorn

from genparams.tune.app import TuneApp
from genparams.tune.graph import Graph


def is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


class TuneServer:
    """The page for the live graph at ``url``; any host but loopback gets a token."""

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
    ) -> None:
        if token is None and not is_loopback(host):
            token = secrets.token_urlsafe(24)
        self.host = host
        self.token = token
        self.owns_graph = graph is None
        self.graph = graph if graph is not None else Graph()
        app = TuneApp(
            self.graph,
            token=token,
            read_only=read_only,
            nodes=nodes,
            trusted_packages=trusted_packages,
        )
        config = uvicorn.Config(
            app.starlette(),
            host=host,
            port=port,
            log_level="warning",
            lifespan="off",
            timeout_graceful_shutdown=1,
        )
        self.server = uvicorn.Server(config)
        self.thread: threading.Thread | None = None

    @property
    def url(self) -> str:
        port = self.server.servers[0].sockets[0].getsockname()[1]
        shown = f"[{self.host}]" if ":" in self.host else self.host
        query = f"/?token={self.token}" if self.token else "/"
        return f"http://{shown}:{port}{query}"

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
