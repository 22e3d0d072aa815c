"""Other web pages against the tuning server, in Chromium, with the victim's cookie in the jar.

The victim has opened the tuning page (so the browser holds its token cookie).
A page from another origin, served by a second local server, then tries what a
browser lets any page do without asking: a text/plain form POST, a no-cors
fetch, a beacon. A name resolved to 127.0.0.1 plays DNS rebinding. The node's
value is read back through its parameter services after every attempt.
"""

from __future__ import annotations

import json
import logging
import threading
from collections.abc import Iterator
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import pytest
from playwright.sync_api import Browser, BrowserContext, expect, sync_playwright

from genparams.tune.server import TuneServer
from tests.support import RosHarness, ServiceClient
from tests.tune.demo_nodes import HOSTILE_TEXT
from tests.tune.support import CHROMIUM, CHROMIUM_ARGS, demo_nodes, eventually, unique

VICTIM = f"/{unique('attacked')}"
RESOLVER = "--host-resolver-rules=MAP attacker.test 127.0.0.1, MAP rebind.test 127.0.0.1"
EVIL = 9.5  # the attacker's value for `gain` (the node starts at 2.0; 0 to 10 in steps of 0.5)


class AttackerSite:
    """A second web server on this machine: serves ``pages[path]`` as HTML, nothing more."""

    def __init__(self) -> None:
        self.pages: dict[str, str] = {}
        pages = self.pages

        class Handler(BaseHTTPRequestHandler):
            def do_GET(self) -> None:
                body = pages.get(self.path.split("?")[0], "").encode()
                self.send_response(200 if body else 404)
                self.send_header("Content-Type", "text/html; charset=utf-8")
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)

            def log_message(self, format: str, *args: object) -> None:
                pass

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.port = self.server.server_address[1]
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)
        self.thread.start()

    def close(self) -> None:
        self.server.shutdown()
        self.server.server_close()


@pytest.fixture(scope="module")
def victim(ros_harness: RosHarness) -> Iterator[ServiceClient]:
    with demo_nodes(f"{VICTIM[1:]}:plain"):
        yield ServiceClient(ros_harness, VICTIM)


@pytest.fixture(scope="module")
def server(victim: ServiceClient) -> Iterator[TuneServer]:
    tune = TuneServer()
    tune.start()
    eventually(lambda: VICTIM in tune.graph.node_names(), timeout=30)
    try:
        yield tune
    finally:
        tune.stop()


@pytest.fixture(scope="module")
def attacker() -> Iterator[AttackerSite]:
    site = AttackerSite()
    try:
        yield site
    finally:
        site.close()


@pytest.fixture(scope="module")
def browser() -> Iterator[Browser]:
    with sync_playwright() as playwright:
        launched = playwright.chromium.launch(
            executable_path=CHROMIUM, args=[*CHROMIUM_ARGS, RESOLVER]
        )
        yield launched
        launched.close()


@pytest.fixture
def context(browser: Browser, server: TuneServer) -> Iterator[BrowserContext]:
    """A browser whose user has the tuning page open: its cookie is in the jar."""
    opened = browser.new_context()
    page = opened.new_page()
    page.goto(server.url + f"#{VICTIM}")
    expect(page.locator(f'form[data-node="{VICTIM}"]')).to_be_visible()
    assert any(c["name"] == f"genparams-tune-{server.port}" for c in opened.cookies())
    yield opened
    opened.close()


def attack_script(target: str) -> str:
    """Every request a page may send to another origin without a CORS preflight, and one with."""
    body = json.dumps(
        {"node": VICTIM, "params": [{"name": "gain", "type": "double", "value": EVIL}]}
    )
    return f"""
const target = {json.dumps(target)};
const body = {json.dumps(body)};
const attempts = [
  fetch(target, {{method: "POST", mode: "no-cors", credentials: "include", body}}),
  fetch(target, {{method: "POST", mode: "no-cors", credentials: "include", body,
                  headers: {{"content-type": "application/json"}}}}),
  fetch(target, {{method: "POST", credentials: "include", body,
                  headers: {{"content-type": "application/json"}}}}),
];
try {{ navigator.sendBeacon(target, body); }} catch (e) {{}}
const blob = new Blob([body], {{type: "application/json"}});
try {{ navigator.sendBeacon(target, blob); }} catch (e) {{}}
Promise.allSettled(attempts).then(() => {{ document.title = "done"; }});
"""


def form_page(target: str) -> str:
    """The classic: a form whose one field's name is the JSON, posted as text/plain."""
    head, tail = json.dumps(
        {"node": VICTIM, "params": [{"name": "gain", "type": "double", "value": EVIL}], "x": "="}
    ).split("=")
    return f"""<!doctype html><html><body>
<form method="POST" enctype="text/plain" action="{target}">
  <input type="hidden" name='{head}' value='{tail}'>
</form>
<script>document.forms[0].submit();</script>
</body></html>"""


def refusals(caplog: pytest.LogCaptureFixture, origin: str) -> list[str]:
    """What the server logged refusing requests to /api/set from ``origin``."""
    return [
        r.getMessage()
        for r in caplog.records
        if r.name == "genparams.tune" and f"'/api/set' (Origin '{origin}')" in r.getMessage()
    ]


@pytest.mark.parametrize("site", ["attacker.test", "127.0.0.1"])
def test_another_origin_cannot_set(
    context: BrowserContext,
    server: TuneServer,
    attacker: AttackerSite,
    victim: ServiceClient,
    site: str,
    caplog: pytest.LogCaptureFixture,
) -> None:
    # 127.0.0.1 on another port is the same site: the SameSite=Strict cookie goes along,
    # so only the Origin and Content-Type rules stand between that page and the node.
    before = victim.get("gain")
    assert before != [EVIL]
    target = f"http://127.0.0.1:{server.port}/api/set"
    attacker.pages["/script.html"] = f"<!doctype html><script>{attack_script(target)}</script>"
    attacker.pages["/form.html"] = form_page(target)
    page = context.new_page()
    origin = f"http://{site}:{attacker.port}"
    with caplog.at_level(logging.WARNING, logger="genparams.tune"):
        page.goto(f"{origin}/script.html")
        expect(page).to_have_title("done")
        with page.expect_navigation(url=target):
            page.goto(f"{origin}/form.html")
        # Every attempt reached the server and was refused there: two no-cors fetches, the
        # text beacon, the preflights of the JSON fetch and the JSON beacon, the form.
        eventually(lambda: len(refusals(caplog, origin)) >= 6, timeout=15)
    assert victim.get("gain") == before
    assert all("[403]" in line for line in refusals(caplog, origin))


def test_a_rebound_name_is_refused(
    context: BrowserContext, server: TuneServer, victim: ServiceClient
) -> None:
    before = victim.get("gain")
    page = context.new_page()
    rebound = f"http://rebind.test:{server.port}"
    answer = page.goto(f"{rebound}/?token={server.token}")
    assert answer is not None and answer.status == 403
    statuses = page.evaluate(
        """async ([node, value]) => {
          const body = JSON.stringify({node, params: [{name: "gain", type: "double", value}]});
          const set = await fetch("/api/set", {method: "POST", body,
                                              headers: {"content-type": "application/json"}});
          const read = await fetch(`/api/node?name=${encodeURIComponent(node)}`);
          return [set.status, read.status];
        }""",
        [VICTIM, EVIL],
    )
    assert statuses == [403, 403]
    assert victim.get("gain") == before


def test_the_page_works_under_its_policy_and_survives_a_bad_fragment(
    browser: Browser, server: TuneServer
) -> None:
    context = browser.new_context()
    page = context.new_page()
    violations: list[str] = []
    page.on(
        "console", lambda m: violations.append(m.text) if "Content Security" in m.text else None
    )
    try:
        page.goto(server.url + "#%E0%A4%A")
        expect(page.locator(f'[data-node-link="{VICTIM}"] a')).to_be_visible()
        expect(page.locator("#status")).to_contain_text("names no node")
        assert "token" not in page.url
        page.locator(f'[data-node-link="{VICTIM}"] a').click()
        expect(page.locator(f'form[data-node="{VICTIM}"]')).to_be_visible()
        page.reload()  # the cookie, not the address, carries the token now
        expect(page.locator(f'[data-node-link="{VICTIM}"] a')).to_be_visible()
        assert violations == []
        framed = context.new_page()
        with framed.expect_console_message(lambda m: "frame-ancestors" in m.text):
            framed.set_content(f'<iframe src="{server.url}"></iframe>')
        expect(framed.frame_locator("iframe").locator("#nodes")).to_have_count(0)
    finally:
        context.close()


def test_hostile_published_text_stays_text(context: BrowserContext, server: TuneServer) -> None:
    name = unique("hostile")
    with demo_nodes(f"{name}:hostile"):
        eventually(lambda: f"/{name}" in server.graph.node_names(), timeout=30)
        page = context.new_page()
        page.goto(f"{server.url}#/{name}")
        # The form the schema builds: until its message arrives the node shows as plain.
        form = page.locator(f'form.genparams[data-node="/{name}"]')
        expect(form).to_be_visible()
        expect(form.get_by_text(HOSTILE_TEXT).first).to_be_visible()
        assert form.locator("img, script").count() == 0
        options = form.locator('[data-param="mode"] option').all_text_contents()
        assert options == ["ok", HOSTILE_TEXT]
        assert page.evaluate("window.pwned") is None
