"""The tuning server's gate, rule by rule, over plain HTTP against real nodes.

Each refused request is checked twice where it could change something: by its
status, and by reading the node's value through its parameter services.
"""

from __future__ import annotations

import http.client
import json
import logging
import subprocess
import sys
import threading
from collections.abc import Iterator

import pytest
from rclpy.parameter import Parameter

from genparams.cli import main as cli_main
from genparams.live.graph import Graph
from genparams.tune.server import TuneServer
from tests.node_process import STOP_S
from tests.support import ROOT, RosHarness, ServiceClient
from tests.tune.support import Answer, demo_nodes, eventually, http_call, open_stream, unique

SERVED, OTHER = (f"/{unique(s)}" for s in ("gate_served", "gate_other"))
TOKEN = "gate-test-token-0123456789"
API_GETS = (
    "/api/config",
    "/api/nodes",
    f"/api/node?name={SERVED}",
    f"/api/params-file?node={SERVED}",
    f"/api/keep?node={SERVED}",
)


@pytest.fixture(scope="module")
def nodes() -> Iterator[None]:
    with demo_nodes(f"{SERVED[1:]}:plain", f"{OTHER[1:]}:plain"):
        yield


@pytest.fixture(scope="module")
def server(nodes: None) -> Iterator[TuneServer]:
    tune = TuneServer(nodes=(SERVED,), token=TOKEN)
    tune.start()
    eventually(lambda: {SERVED, OTHER} <= set(tune.graph.node_names()), timeout=30)
    try:
        yield tune
    finally:
        tune.stop()


@pytest.fixture(scope="module")
def served(ros_harness: RosHarness, nodes: None) -> ServiceClient:
    return ServiceClient(ros_harness, SERVED)


@pytest.fixture(scope="module")
def other(ros_harness: RosHarness, nodes: None) -> ServiceClient:
    return ServiceClient(ros_harness, OTHER)


def set_body(node: str = SERVED, value: object = 4.5, name: str = "gain") -> bytes:
    params = [{"name": name, "type": "double", "value": value}]
    return json.dumps({"node": node, "params": params}).encode()


def post(server: TuneServer, body: bytes, path: str = "/api/set", **headers: str) -> Answer:
    return http_call(server.port, "POST", path, body=body, headers=headers, token=TOKEN)


# /api/check takes a set's body and changes nothing; /api/keep reads its node from it
POSTS = ("/api/set", "/api/check", "/api/keep")


def test_every_route_but_the_assets_needs_the_token(server: TuneServer) -> None:
    for path in ("/", *API_GETS, "/api/events"):
        assert http_call(server.port, "GET", path).status == 403, path
        assert http_call(server.port, "GET", path, token="wrong-" + TOKEN).status == 403, path
        cookie = {"Cookie": f"genparams-tune-{server.port}=wrong"}
        assert http_call(server.port, "GET", path, headers=cookie).status == 403, path
    assert http_call(server.port, "GET", f"/api/config?token={TOKEN}").status == 403
    for path in POSTS:
        assert http_call(server.port, "POST", path, body=set_body()).status == 403, path
        assert post(server, set_body(), path).status == 200, path
    for path in API_GETS:
        assert http_call(server.port, "GET", path, token=TOKEN).status == 200, path
    assert http_call(server.port, "GET", "/static/app.js").status == 200
    # Every route the app has is one of those above: a new one is added here too.
    routes = {route.path for route in server.app.starlette().app.routes}  # type: ignore[attr-defined]
    tested = {"/", "/static", "/api/events", *POSTS, *(p.split("?")[0] for p in API_GETS)}
    assert routes == tested


def test_the_url_token_becomes_a_strict_http_only_cookie(server: TuneServer) -> None:
    page = http_call(server.port, "GET", f"/?token={TOKEN}")
    assert page.status == 200
    cookie = page.headers["set-cookie"]
    name = f"genparams-tune-{server.port}"  # browsers share cookies across ports
    assert cookie.startswith(f"{name}={TOKEN};")
    assert "HttpOnly" in cookie and "SameSite=Strict" in cookie
    assert http_call(server.port, "GET", "/api/config", headers={"Cookie": f"{name}={TOKEN}"}).ok


def test_host_must_name_this_server(server: TuneServer) -> None:
    port = server.port
    for host in (f"localhost:{port}", f"127.0.0.1:{port}", f"[::1]:{port}"):
        assert http_call(port, "GET", "/api/config", token=TOKEN, headers={"Host": host}).ok
    for host in (f"rebind.test:{port}", f"127.0.0.1:{port + 1}", "127.0.0.1", "", "evil.test"):
        answer = http_call(port, "GET", "/api/config", token=TOKEN, headers={"Host": host})
        assert answer.status == 403, host
        assert b"not this server" in answer.body


@pytest.mark.parametrize(
    "host", ["127.0.0.1:\u00b2", "[::1]:\u00b9", "localhost:1\u00b2", "127.0.0.1:" + "9" * 5000]
)
def test_a_host_port_that_is_not_a_number_is_400(server: TuneServer, host: str) -> None:
    """'²' is a digit to str.isdigit but not to int(): refused before the token is checked."""
    answer = http_call(server.port, "GET", "/api/config", token=TOKEN, headers={"Host": host})
    assert answer.status == 400, answer.body
    assert b"is not a port number" in answer.body


@pytest.mark.parametrize(
    "others",
    ['prefs={"theme":"dark"}', "session=a b", "seen", 'a="unclosed', "=x", "\u00e9t\u00e9=1"],
)
def test_a_cookie_no_parser_reads_does_not_hide_the_token_cookie(
    server: TuneServer, others: str
) -> None:
    name = f"genparams-tune-{server.port}"
    for cookie in (f"{others}; {name}={TOKEN}", f"{name}={TOKEN}; {others}"):
        answer = http_call(server.port, "GET", "/api/config", headers={"Cookie": cookie})
        assert answer.status == 200, (cookie, answer.body)
    wrong = http_call(server.port, "GET", "/api/config", headers={"Cookie": f"{others}; {name}=x"})
    assert wrong.status == 403


def test_origin_must_be_this_server(server: TuneServer, served: ServiceClient) -> None:
    before = served.get("gain")
    for origin in ("http://evil.test", f"http://localhost:{server.port + 1}", "null"):
        for path in POSTS:
            assert post(server, set_body(), path, Origin=origin).status == 403, (origin, path)
        answer = http_call(
            server.port, "GET", "/api/config", token=TOKEN, headers={"Origin": origin}
        )
        assert answer.status == 403, origin
    assert served.get("gain") == before
    own = f"http://127.0.0.1:{server.port}"
    assert post(server, set_body(value=5.0), Origin=own).ok
    assert served.get("gain") == [5.0]


def test_a_change_with_the_cookie_alone_needs_the_origin(
    server: TuneServer, served: ServiceClient
) -> None:
    cookie = {"Cookie": f"genparams-tune-{server.port}={TOKEN}"}
    assert (
        http_call(server.port, "POST", "/api/set", body=set_body(value=6.0), headers=cookie).status
        == 403
    )
    origin = {**cookie, "Origin": f"http://127.0.0.1:{server.port}"}
    assert http_call(server.port, "POST", "/api/set", body=set_body(value=6.0), headers=origin).ok
    assert served.get("gain") == [6.0]


def test_a_set_is_json_or_nothing(server: TuneServer, served: ServiceClient) -> None:
    before = served.get("gain")
    for kind in (
        "text/plain",
        "application/x-www-form-urlencoded",
        "multipart/form-data; boundary=x",
        "application/jsonx",
        "",
    ):
        for path in POSTS:
            answer = post(server, set_body(value=7.0), path, **{"Content-Type": kind})
            assert answer.status == 415, (kind, path)
    assert served.get("gain") == before
    assert post(
        server, set_body(value=7.0), **{"Content-Type": "application/json; charset=utf-8"}
    ).ok
    assert served.get("gain") == [7.0]


def test_bodies_are_limited_while_read(server: TuneServer) -> None:
    big = b'{"node": "' + b"a" * (2 << 20) + b'"}'
    assert post(server, big).status == 413
    # Chunked, with no length to trust: the limit is counted as the body arrives.
    connection = http.client.HTTPConnection("127.0.0.1", server.port, timeout=30)
    try:
        connection.request(
            "POST",
            "/api/set",
            body=iter([b"[" * 65536] * 40),
            headers={"Content-Type": "application/json", "X-Genparams-Token": TOKEN},
            encode_chunked=True,
        )
        assert connection.getresponse().status == 413
    finally:
        connection.close()


HOSTILE_BODIES = {
    "deep nesting": b"[" * 100_000 + b"]" * 100_000,
    "int past int64": json.dumps(
        {"node": SERVED, "params": [{"name": "retries", "type": "int", "value": 2**63}]}
    ).encode(),
    "10**400": set_body(value=10**400),
    "lone surrogate": json.dumps(
        {"node": SERVED, "params": [{"name": "frame", "type": "string", "value": "\ud800"}]}
    ).encode(),
    "surrogate name": json.dumps(
        {"node": SERVED, "params": [{"name": "\udfff", "type": "string", "value": "x"}]}
    ).encode(),
    "node bad name!": set_body(node="bad name!"),
    "node /{x}": set_body(node="/{x}"),
    "node as a list": set_body(node=[SERVED]),  # type: ignore[arg-type]
    "node as a number": set_body(node=7),  # type: ignore[arg-type]
    "not json": b"{'node': 1}",
    "not utf-8": b'{"node": "\xff"}',
    "a list": b"[]",
    "params not a list": json.dumps({"node": SERVED, "params": {"gain": 1}}).encode(),
    "param not an object": json.dumps({"node": SERVED, "params": [1]}).encode(),
    "unknown type": json.dumps(
        {"node": SERVED, "params": [{"name": "gain", "type": "float32", "value": 1}]}
    ).encode(),
    "value of another shape": set_body(value={"a": 1}),
    "atomic not a bool": json.dumps(
        {"node": SERVED, "params": [{"name": "gain", "type": "double", "value": 1}], "atomic": 2}
    ).encode(),
    "empty": b"",
}


@pytest.mark.parametrize("name", HOSTILE_BODIES)
def test_hostile_bodies_are_400(server: TuneServer, name: str) -> None:
    answer = post(server, HOSTILE_BODIES[name])
    assert answer.status == 400, answer.body
    assert answer.json()["error"]
    # A check answers a value the node cannot take with the node's verdict, and anything
    # else with a 400; never more.
    checked = post(server, HOSTILE_BODIES[name], "/api/check")
    if checked.status == 200:
        assert checked.json()["successful"] is False, checked.body
    else:
        assert checked.status == 400, checked.body
        assert checked.json()["error"]


@pytest.mark.parametrize(
    "query",
    [
        "/api/node?name=bad%20name!",
        "/api/node?name=/%7Bx%7D",
        "/api/node?name=",
        "/api/node",
        "/api/node?name=%ED%A0%80",
        "/api/node?name=%FF",
        "/api/params-file?node=bad%20name!",
        "/api/params-file",
    ],
)
def test_invalid_node_names_in_queries_are_400(server: TuneServer, query: str) -> None:
    assert http_call(server.port, "GET", query, token=TOKEN).status == 400


def test_named_nodes_restrict_reads_sets_and_events(
    server: TuneServer, other: ServiceClient, served: ServiceClient
) -> None:
    listed = http_call(server.port, "GET", "/api/nodes", token=TOKEN).json()["nodes"]
    assert [n["name"] for n in listed] == [SERVED]
    assert http_call(server.port, "GET", f"/api/node?name={OTHER}", token=TOKEN).status == 403
    assert (
        http_call(server.port, "GET", f"/api/params-file?node={OTHER}", token=TOKEN).status == 403
    )
    before = other.get("gain")
    assert post(server, set_body(node=OTHER, value=8.0)).status == 403
    assert post(server, set_body(node=OTHER, value=8.0), "/api/check").status == 403
    assert other.get("gain") == before
    # Events: a change of the other node never reaches the stream; one of ours does.
    connection = http.client.HTTPConnection("127.0.0.1", server.port, timeout=30)
    try:
        connection.request("GET", "/api/events", headers={"X-Genparams-Token": TOKEN})
        stream = connection.getresponse()
        assert stream.status == 200
        assert stream.readline() == b": connected\n"
        assert other.set(Parameter("gain", value=8.5))[0].successful
        assert served.set(Parameter("gain", value=9.0))[0].successful
        nodes = []
        while SERVED not in nodes:
            line = stream.readline()
            if line.startswith(b"data: "):
                nodes.append(json.loads(line[6:])["node"])
        assert OTHER not in nodes
    finally:
        connection.close()


def test_read_only_refuses_every_write(server: TuneServer, served: ServiceClient) -> None:
    viewer = TuneServer(read_only=True, graph=server.graph, token=TOKEN)
    viewer.start()
    try:
        before = served.get("gain")
        answer = http_call(viewer.port, "POST", "/api/set", body=set_body(value=1.5), token=TOKEN)
        assert answer.status == 403 and b"read-only" in answer.body
        assert served.get("gain") == before
        # A check sets nothing: a read-only page may still ask what the node would say.
        checked = http_call(viewer.port, "POST", "/api/check", body=set_body(), token=TOKEN)
        assert checked.ok and checked.json()["successful"], checked.body
        assert http_call(viewer.port, "GET", "/api/config", token=TOKEN).json()["read_only"]
    finally:
        viewer.stop()


def test_every_answer_carries_the_security_headers(server: TuneServer) -> None:
    answers = [
        http_call(server.port, "GET", f"/?token={TOKEN}"),
        http_call(server.port, "GET", "/static/app.js"),
        http_call(server.port, "GET", "/api/config", token=TOKEN),
        http_call(server.port, "GET", "/api/config"),
        http_call(server.port, "GET", "/api/config", headers={"Host": "evil.test"}),
        post(server, b"[", **{"Content-Type": "text/plain"}),
        post(server, b"{}"),
    ]
    for answer in answers:
        policy = answer.headers["content-security-policy"]
        assert "default-src 'self'" in policy and "script-src 'self'" in policy
        assert "frame-ancestors 'none'" in policy
        assert answer.headers["x-frame-options"] == "DENY"
        assert answer.headers["x-content-type-options"] == "nosniff"
        assert answer.headers["referrer-policy"] == "no-referrer"
    assert "server" not in answers[2].headers


def test_event_streams_are_limited_in_number(server: TuneServer) -> None:
    streams = server.app.streams
    limit, streams.max_streams = streams.max_streams, streams.open + 1
    opened: list[http.client.HTTPConnection] = []
    try:
        first, status = open_stream(server.port, TOKEN)
        opened.append(first)
        assert status == 200
        second, status = open_stream(server.port, TOKEN)
        opened.append(second)
        assert status == 503
        first.close()  # its place is given back once the server sees it gone

        def reopened() -> bool:
            connection, status = open_stream(server.port, TOKEN)
            opened.append(connection)
            return status == 200

        eventually(reopened, timeout=30, interval=0.2)
    finally:
        streams.max_streams = limit
        for connection in opened:
            connection.close()


def test_a_reader_that_falls_behind_is_dropped(server: TuneServer) -> None:
    streams = server.app.streams
    depth, streams.max_queued = streams.max_queued, 10
    connection = http.client.HTTPConnection("127.0.0.1", server.port, timeout=30)
    try:
        connection.request("GET", "/api/events", headers={"X-Genparams-Token": TOKEN})
        stream = connection.getresponse()
        assert stream.readline() == b": connected\n"
        flood = {
            "kind": "parameters",
            "node": SERVED,
            "new": {},
            "changed": {"gain": 1.0},
            "deleted": [],
        }

        def send() -> None:
            for _ in range(50_000):
                server.graph.dispatch(flood)

        sender = threading.Thread(target=send)
        sender.start()
        sender.join()
        received = stream.read().count(b"data: ")  # returns: the server ended the stream
        assert received < 50_000
    finally:
        streams.max_queued = depth
        connection.close()


def test_port_out_of_range_is_a_usage_error(capsys: pytest.CaptureFixture[str]) -> None:
    for port in ("70000", "-1", "http"):
        with pytest.raises(SystemExit) as exit_:
            cli_main(["tune", "--port", port])
        assert exit_.value.code == 2
        assert "0 to 65535" in capsys.readouterr().err or port == "http"
    assert cli_main(["tune", "--token", "short"]) == 2
    assert "16 to 256" in capsys.readouterr().err


def clients(graph: Graph) -> int:
    return sum(1 for _ in graph.node.clients)


def test_clients_of_nodes_not_there_are_released(server: TuneServer) -> None:
    graph = server.graph
    before = clients(graph)
    everyone = TuneServer(graph=graph, token=TOKEN)
    everyone.start()
    try:
        for index in range(20):
            ghost = f"/{unique('ghost')}_{index}"
            answer = http_call(everyone.port, "GET", f"/api/node?name={ghost}", token=TOKEN)
            assert answer.status == 404
            answer = http_call(
                everyone.port, "POST", "/api/set", body=set_body(node=ghost), token=TOKEN
            )
            assert answer.status == 404
        assert clients(graph) == before
        leaving = unique("gate_leaving")
        with demo_nodes(f"{leaving}:plain"):
            eventually(lambda: f"/{leaving}" in graph.node_names(), timeout=30)
            answer = http_call(everyone.port, "GET", f"/api/node?name=/{leaving}", token=TOKEN)
            assert answer.status == 200
            assert clients(graph) > before
        eventually(lambda: clients(graph) == before, timeout=30)
    finally:
        everyone.stop()


def test_the_token_is_printed_once_and_never_logged(tmp_path: object) -> None:
    token = "printed-once-" + "x" * 20
    command = [sys.executable, "-m", "genparams", "tune", "--port", "0", "--token", token]
    process = subprocess.Popen(
        command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    try:
        assert process.stdout is not None
        line = process.stdout.readline()
        assert line.startswith("genparams tune: serving http://127.0.0.1:") and token in line
        port = int(line.split(":")[3].split("/")[0])
        assert http_call(port, "GET", f"/?token={token}").ok
        assert http_call(port, "GET", f"/api/config?token={token}").status == 403
        assert http_call(port, "GET", "/api/nodes", token=token).ok
    finally:
        process.terminate()
        try:
            out, err = process.communicate(timeout=STOP_S)
        except subprocess.TimeoutExpired:  # a loaded machine: stop it the hard way
            process.kill()
            out, err = process.communicate()
    assert token not in out + err


def test_refusals_are_logged_escaped_and_without_the_query(
    server: TuneServer, caplog: pytest.LogCaptureFixture
) -> None:
    with caplog.at_level(logging.WARNING, logger="genparams.tune"):
        host = {"Host": "evil\x1b[31m.test"}
        assert (
            http_call(server.port, "GET", f"/api/nodes?token={TOKEN}", headers=host).status == 403
        )
        origin = {"Origin": "http://evil\x1b]0;title\x07.test"}
        assert (
            http_call(server.port, "GET", "/api/nodes", token=TOKEN, headers=origin).status == 403
        )
    lines = [r.getMessage() for r in caplog.records if r.name == "genparams.tune"]
    assert len(lines) == 2
    assert all("\x1b" not in line and "\x07" not in line for line in lines)
    assert all(TOKEN not in line for line in lines)
    assert "\\x1b" in lines[0] and "'/api/nodes'" in lines[0]
