"""Shared by the tune and audit tests: demo nodes in their own processes, polling, a browser."""

from __future__ import annotations

import http.client
import json
import os
import subprocess
import sys
import time
from collections.abc import Callable
from contextlib import AbstractContextManager
from pathlib import Path
from typing import TYPE_CHECKING, Any

from playwright.sync_api import Locator, Page, expect
from rclpy.parameter import Parameter

from genparams.runtime.core.json_codec import dumps
from tests.node_process import node_process
from tests.patience import WAIT_S, run_patiently
from tests.support import ROOT, RosHarness, ServiceClient

if TYPE_CHECKING:
    from genparams.tune.server import TuneServer

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


def unique(stem: str) -> str:
    """Node names no other test run on this domain uses."""
    return f"{stem}_{os.getpid()}"


def demo_nodes(
    *specs: str, ros_args: tuple[str, ...] = ()
) -> AbstractContextManager[subprocess.Popen[str]]:
    """The nodes of tests.tune.demo_nodes (NAME:KIND...), given ``ros_args``, until the block
    ends."""
    return node_process("tests.tune.demo_nodes", *specs, *(("--", *ros_args) if ros_args else ()))


def set_values_its_schema_forbids(harness: RosHarness, loose_node: str) -> None:
    """On a ``loose`` demo node, values its schema forbids (``max_speed`` 7.0 and a one-item
    ``weights``), set through the services as ``ros2 param set`` would."""
    loose = ServiceClient(harness, loose_node)
    results = loose.set(Parameter("max_speed", value=7.0), Parameter("weights", value=[0.5]))
    assert all(r.successful for r in results)


def run_genparams(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    """``genparams ARGS`` run to its end, however loaded the machine."""
    command = [sys.executable, "-m", "genparams", *args]
    return run_patiently(command, budget_s=2 * WAIT_S, cwd=cwd)


def run_audit(
    *args: str, cwd: Path = ROOT, settle: float = WAIT_S
) -> subprocess.CompletedProcess[str]:
    """``genparams audit ARGS``: it waits for each named node to appear (up to WAIT_S), then
    ``settle`` seconds for schema topics of those that publish none. On nodes that all
    publish a schema, its waits end as soon as discovery does, however long that takes."""
    wait = f"{WAIT_S:g}"
    return run_genparams("audit", "--settle", f"{settle:g}", "--timeout", wait, *args, cwd=cwd)


def eventually(probe: Callable[[], Any], timeout: float = WAIT_S, interval: float = 0.05) -> Any:
    """Poll ``probe`` until it returns a true value; its last value on timeout fails."""
    deadline = time.monotonic() + timeout
    while True:
        value = probe()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"condition not met within {timeout} s (last: {value!r})")
        time.sleep(interval)


class Answer:
    """One HTTP answer: status, headers (lower-case names) and body."""

    def __init__(self, status: int, headers: dict[str, str], body: bytes) -> None:
        self.status = status
        self.headers = headers
        self.body = body

    @property
    def ok(self) -> bool:
        return self.status == 200

    def json(self) -> Any:
        return json.loads(self.body)


def open_stream(port: int, token: str) -> tuple[http.client.HTTPConnection, int]:
    """An event stream left open (close the connection to end it), and its status."""
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    connection.request("GET", "/api/events", headers={"X-Genparams-Token": token})
    return connection, connection.getresponse().status


def http_call(
    port: int,
    method: str,
    path: str,
    *,
    body: bytes | None = None,
    headers: dict[str, str] | None = None,
    token: str | None = None,
) -> Answer:
    """A raw request to 127.0.0.1:``port``; ``headers`` may name any Host."""
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    sent = {"Host": f"127.0.0.1:{port}"}
    if body is not None:
        sent["Content-Type"] = "application/json"
    if token is not None:
        sent["X-Genparams-Token"] = token
    sent.update(headers or {})
    try:
        connection.putrequest(method, path, skip_host=True, skip_accept_encoding=True)
        for name, value in sent.items():
            connection.putheader(name, value)
        if body is not None and "Transfer-Encoding" not in sent:
            connection.putheader("Content-Length", str(len(body)))
        connection.endheaders()
        if body is not None:
            connection.send(body)
        response = connection.getresponse()
        return Answer(
            response.status,
            {name.lower(): value for name, value in response.getheaders()},
            response.read(),
        )
    finally:
        connection.close()


def api_call(server: TuneServer, path: str, body: Any = None) -> Answer:
    """A call to a tuning server's API as a client other than the page makes it: the token in
    its header; with a body (bytes, or a value the codec writes), a JSON POST, else a GET."""
    if body is not None and not isinstance(body, bytes):
        body = dumps(body).encode("ascii")
    method = "GET" if body is None else "POST"
    return http_call(server.port, method, path, body=body, token=server.token)


def open_node(page: Page, server: TuneServer, node: str) -> None:
    """Open the page, then ``node`` from the list, as a user does; return once its form shows
    and the page listens to the server's events (a change made before is in the form)."""
    page.goto(server.url)
    page.locator(f'[data-node-link="{node}"] a').click()
    expect(page.locator(f'form[data-node="{node}"]')).to_be_visible()
    expect(page.locator("body[data-listening]")).to_be_attached()


def error(page: Page, name: str) -> Locator:
    """Where the page says why a parameter's value is refused."""
    return page.locator(f'[data-param-error="{name}"]')


_CLIENTS: dict[str, ServiceClient] = {}


def service_client(ros_harness: RosHarness, node: str) -> ServiceClient:
    """One parameter client per node for the session: each opens six service clients."""
    if node not in _CLIENTS:
        _CLIENTS[node] = ServiceClient(ros_harness, node)
    return _CLIENTS[node]
