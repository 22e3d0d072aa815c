"""The tuning server's gate: what a request must show before any route sees it.

An ASGI middleware in front of the whole app, so no route can forget a rule:

- ``Host`` names this server (its bound address and port): a page on another
  name resolved to this address (DNS rebinding) is refused;
- ``Origin``, when sent, is this server's own; a request that changes state
  either sends this server's ``Origin`` or carries the token in its header;
- every route but the static assets needs the per-run token: in the
  ``X-Genparams-Token`` header, or in the HttpOnly, SameSite=Strict cookie that
  the page's URL (``/?token=...``) sets once;
- a request with a body sends ``Content-Type: application/json`` and at most
  ``MAX_BODY`` bytes, counted while reading;
- a read-only server refuses every write path;
- every response carries a CSP and headers against framing and sniffing.
"""

from __future__ import annotations

import functools
import hmac
import ipaddress
import logging
import re
import socket
from collections.abc import Iterable
from dataclasses import dataclass
from urllib.parse import parse_qs

from starlette.types import ASGIApp, Message, Receive, Scope, Send

from genparams.runtime.core.errors import GenparamsError
from genparams.runtime.core.json_codec import API_LIMITS, dumps

LOG = logging.getLogger("genparams.tune")
TOKEN_HEADER = "x-genparams-token"
TOKEN_TEXT = re.compile(r"[A-Za-z0-9_.~-]{16,256}")
TOKEN_RULE = "16 to 256 letters, digits or '_.~-'"
# 1 MiB, the codec's limit for an API body: a set of every parameter of a 20,000-parameter
# node fits. The gate counts it while the body arrives; the codec refuses longer text too.
MAX_BODY = API_LIMITS.max_chars
SAFE_METHODS = frozenset({"GET", "HEAD"})
PUBLIC_PREFIX = "/static/"  # the page's scripts and styles: the same in every wheel
WILDCARD_HOSTS = frozenset({"0.0.0.0", "::", ""})
LOOPBACK_NAMES = ("localhost", "127.0.0.1", "[::1]")
HEADERS = (
    (
        b"content-security-policy",
        b"default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
        b"connect-src 'self'; object-src 'none'; base-uri 'none'; form-action 'self'; "
        b"frame-ancestors 'none'",
    ),
    (b"x-frame-options", b"DENY"),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"no-referrer"),
    (b"cross-origin-resource-policy", b"same-origin"),
    (b"cross-origin-opener-policy", b"same-origin"),
)


def token_problem(token: str) -> str | None:
    """Why ``token`` cannot guard the page (it goes in a URL and a cookie), or None."""
    return None if TOKEN_TEXT.fullmatch(token) else f"a token must be {TOKEN_RULE}"


def is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def url_host(host: str) -> str:
    """``host`` as it appears in a URL and a ``Host`` header: IPv6 in brackets."""
    return f"[{host}]" if ":" in host and not host.startswith("[") else host


def is_ip_literal(name: str) -> bool:
    try:
        ipaddress.ip_address(name.strip("[]"))
    except ValueError:
        return False
    return True


@functools.cache
def host_names(bound: str) -> frozenset[str]:
    """The names a ``Host`` header may give for a server bound to ``bound``."""
    names = {url_host(bound).lower()}
    if is_loopback(bound):
        names.update(LOOPBACK_NAMES)
    else:
        names.update({socket.gethostname().lower(), socket.getfqdn().lower(), *LOOPBACK_NAMES})
    return frozenset(names)


class RefusedError(GenparamsError):
    def __init__(self, status: int, reason: str) -> None:
        super().__init__(reason)
        self.status = status
        self.reason = reason


def _port(text: str) -> int:
    """A ``Host`` port: one to five ASCII digits ('²' and '١' are digits to ``str.isdigit``)."""
    if not (text.isascii() and text.isdigit() and len(text) <= 5):
        raise RefusedError(400, f"Host port {text!r} is not a port number")
    return int(text)


def split_host(value: str) -> tuple[str, int | None]:
    """A ``Host`` header as (name, port): ``name:port`` or ``[v6]:port``; port None if absent.

    A port that is not a number is a :class:`RefusedError` (400).
    """
    value = value.strip().lower()
    if value.startswith("["):
        name, bracket, rest = value.partition("]")
        if rest.startswith(":"):
            return name + bracket, _port(rest[1:])
        return name + bracket, None
    name, colon, port = value.rpartition(":")
    if colon and ":" not in name:
        return name, _port(port)
    return value, None


@dataclass(frozen=True)
class Policy:
    """What the gate enforces for one server."""

    token: str
    bound_host: str = "127.0.0.1"
    read_only: bool = False
    writes: frozenset[str] = frozenset()  # paths that change state
    max_body: int = MAX_BODY

    def host_allowed(self, header: str, port: int | None) -> bool:
        name, given_port = split_host(header)
        if given_port is None:
            given_port = 80
        if port is not None and given_port != port:
            return False
        if name in host_names(self.bound_host):
            return True
        return self.bound_host in WILDCARD_HOSTS and is_ip_literal(name)

    def token_matches(self, given: str | None) -> bool:
        return given is not None and hmac.compare_digest(given.encode(), self.token.encode())


def cookie_name(port: int | None) -> str:
    """One cookie per port: browsers share a host's cookies across its ports."""
    return f"genparams-tune-{port or 80}"


class Gate:
    """The ASGI middleware enforcing a :class:`Policy` before ``app`` sees a request."""

    def __init__(self, app: ASGIApp, policy: Policy) -> None:
        self.app = app
        self.policy = policy

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        send = with_headers(send, HEADERS)
        try:
            set_cookie = self.admit(scope)
            if scope["method"] not in SAFE_METHODS or has_body(scope):
                receive = await self.read_body(scope, receive)
        except RefusedError as refused:
            # The path only: the page's query string may hold the token. Quoted with
            # repr: what a client sends must not reach a terminal raw.
            origin = header_map(scope["headers"]).get("origin")
            LOG.warning(
                "refused %s %r (Origin %r): %s [%d]",
                scope["method"],
                scope["path"],
                origin,
                refused.reason,
                refused.status,
            )
            await refuse(send, refused)
            return
        if set_cookie is not None:
            send = with_headers(send, ((b"set-cookie", set_cookie.encode("latin-1")),))
        await self.app(scope, receive, send)

    def admit(self, scope: Scope) -> str | None:
        """Refuse what the policy forbids; a cookie to set when the URL carried the token."""
        headers = header_map(scope["headers"])
        port = server_port(scope)
        host = headers.get("host", "")
        if not self.policy.host_allowed(host, port):
            raise RefusedError(403, f"Host {host!r} is not this server's address")
        origin = headers.get("origin")
        if origin is not None and origin != f"http://{host}":
            raise RefusedError(403, f"requests from {origin!r} are refused")
        path: str = scope["path"]
        method: str = scope["method"]
        if path.startswith(PUBLIC_PREFIX) and method in SAFE_METHODS:
            return None
        from_header = self.policy.token_matches(headers.get(TOKEN_HEADER))
        cookie = cookies(headers.get("cookie", "")).get(cookie_name(port))
        set_cookie = None
        if not from_header and not self.policy.token_matches(cookie):
            given = parse_qs(scope.get("query_string", b"").decode("latin-1")).get("token", [])
            if (
                path == "/"
                and method in SAFE_METHODS
                and self.policy.token_matches(given[0] if given else None)
            ):
                set_cookie = (
                    f"{cookie_name(port)}={self.policy.token}; Path=/; HttpOnly; SameSite=Strict"
                )
            else:
                raise RefusedError(
                    403, "missing or wrong token: open the URL genparams tune printed"
                )
        if method not in SAFE_METHODS:
            if origin is None and not from_header:
                raise RefusedError(403, "a change needs this page's Origin or the token header")
            if self.policy.read_only and path in self.policy.writes:
                raise RefusedError(403, "this page is read-only")
        return set_cookie

    async def read_body(self, scope: Scope, receive: Receive) -> Receive:
        """The whole body, at most ``max_body`` bytes of JSON, replayed to the app."""
        headers = header_map(scope["headers"])
        media_type = headers.get("content-type", "").split(";")[0].strip().lower()
        if media_type != "application/json":
            raise RefusedError(415, "a request body must be Content-Type: application/json")
        limit = self.policy.max_body
        length = headers.get("content-length", "")
        if length.isdigit() and int(length) > limit:
            raise RefusedError(413, f"a request body may hold at most {limit} bytes")
        chunks: list[bytes] = []
        size = 0
        while True:
            message = await receive()
            if message["type"] == "http.disconnect":
                raise RefusedError(400, "the client left before sending the whole body")
            chunk: bytes = message.get("body", b"")
            size += len(chunk)
            if size > limit:
                raise RefusedError(413, f"a request body may hold at most {limit} bytes")
            chunks.append(chunk)
            if not message.get("more_body", False):
                break
        body = b"".join(chunks)
        sent = False

        async def replay() -> Message:
            nonlocal sent
            if sent:
                return await receive()
            sent = True
            return {"type": "http.request", "body": body, "more_body": False}

        return replay


def has_body(scope: Scope) -> bool:
    headers = header_map(scope["headers"])
    return headers.get("content-length", "0") not in ("", "0") or "transfer-encoding" in headers


def header_map(raw: Iterable[tuple[bytes, bytes]]) -> dict[str, str]:
    """Headers by lower-case name; the first of repeated names counts."""
    found: dict[str, str] = {}
    for name, value in raw:
        found.setdefault(name.decode("latin-1").lower(), value.decode("latin-1"))
    return found


def server_port(scope: Scope) -> int | None:
    server = scope.get("server")
    return int(server[1]) if server and server[1] is not None else None


def cookies(header: str) -> dict[str, str]:
    """A ``Cookie`` header's cookies, read item by item: one item no parser could read
    (``prefs={"a":1}``, ``session=a b``, a bare ``seen``) does not hide the others.
    The first of repeated names counts, as browsers send the most specific first."""
    jar: dict[str, str] = {}
    for item in header.split(";"):
        name, equals, value = item.partition("=")
        name, value = name.strip(), value.strip()
        if equals and name:
            if len(value) >= 2 and value[0] == value[-1] == '"':
                value = value[1:-1]
            jar.setdefault(name, value)
    return jar


def with_headers(send: Send, extra: Iterable[tuple[bytes, bytes]]) -> Send:
    added = list(extra)

    async def sender(message: Message) -> None:
        if message["type"] == "http.response.start":
            message = {**message, "headers": [*message.get("headers", []), *added]}
        await send(message)

    return sender


async def refuse(send: Send, refused: RefusedError) -> None:
    body = dumps({"error": refused.reason}).encode("ascii")
    await send(
        {
            "type": "http.response.start",
            "status": refused.status,
            "headers": [
                (b"content-type", b"application/json"),
                (b"content-length", str(len(body)).encode()),
                (b"cache-control", b"no-store"),
            ],
        }
    )
    await send({"type": "http.response.body", "body": body})
