"""Connections that never send a request, or send it slowly, cannot starve the page.

They need no token, so the server bounds them: in number (below what its file
descriptors allow) and in time (each request must arrive whole within a deadline).
"""

from __future__ import annotations

import resource
import socket
import subprocess
import sys
from collections.abc import Iterator

import pytest

from genparams.tune.connections import REQUEST_TIMEOUT_S, connection_limit
from genparams.tune.server import TuneServer
from tests.node_process import STOP_S
from tests.support import ROOT
from tests.tune.support import http_call

TOKEN = "connections-token-0123456789"
DESCRIPTORS = 160
IDLE_CONNECTIONS = 200


def low_descriptor_limit() -> None:
    resource.setrlimit(resource.RLIMIT_NOFILE, (DESCRIPTORS, DESCRIPTORS))


@pytest.fixture
def tune_port() -> Iterator[int]:
    """``genparams tune`` in a process that may open only ``DESCRIPTORS`` files."""
    command = [sys.executable, "-m", "genparams", "tune", "--port", "0", "--token", TOKEN]
    process = subprocess.Popen(
        command,
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
        preexec_fn=low_descriptor_limit,
    )
    try:
        assert process.stdout is not None
        line = process.stdout.readline()
        assert line.startswith("genparams tune: serving http://127.0.0.1:"), line
        yield int(line.split(":")[3].split("/")[0])
    finally:
        process.terminate()
        try:
            process.communicate(timeout=STOP_S)
        except subprocess.TimeoutExpired:  # a loaded machine: stop it the hard way
            process.kill()
            process.communicate()


def test_idle_connections_do_not_starve_requests_with_the_token(tune_port: int) -> None:
    idle = [socket.create_connection(("127.0.0.1", tune_port)) for _ in range(IDLE_CONNECTIONS)]
    try:
        for _ in range(5):
            answer = http_call(tune_port, "GET", "/api/nodes", token=TOKEN)
            assert answer.status == 200, answer.body
    finally:
        for connection in idle:
            connection.close()


@pytest.fixture(scope="module")
def server() -> Iterator[TuneServer]:
    tune = TuneServer(token=TOKEN)
    tune.start()
    try:
        yield tune
    finally:
        tune.stop()


@pytest.mark.parametrize(
    "sent", [b"", b"GET /api/nodes HTTP/1.1\r\nHost: 127", b"POST /api/set HTTP/1.1\r\n"]
)
def test_a_request_that_never_arrives_whole_is_closed(server: TuneServer, sent: bytes) -> None:
    if sent.startswith(b"POST"):  # admitted, then its body never comes whole
        sent += (
            f"Host: 127.0.0.1:{server.port}\r\nX-Genparams-Token: {TOKEN}\r\n"
            "Content-Type: application/json\r\nContent-Length: 9\r\n\r\n{"
        ).encode()
    with socket.create_connection(("127.0.0.1", server.port), timeout=REQUEST_TIMEOUT_S * 6) as c:
        c.sendall(sent)
        assert c.recv(1 << 16) == b""  # closed by the server, without an answer


def test_the_connection_limit_leaves_descriptors_free() -> None:
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    assert 8 <= connection_limit() <= 256
    resource.setrlimit(resource.RLIMIT_NOFILE, (DESCRIPTORS, hard))
    try:
        assert connection_limit() <= DESCRIPTORS // 2
    finally:
        resource.setrlimit(resource.RLIMIT_NOFILE, (soft, hard))
