"""Benchmarks of genparams tune and audit; appends its section to docs/benchmarks.md.

- the page for a node with 1,000 parameters: from navigation to a usable form;
- a set made elsewhere (through the services) until the page shows it;
- the check of an edit (``/api/check``) on that node: first (compiles its schema) and later;
- audit time against the number of nodes (one process per 10 nodes).

Run with ``python -m bench.tune`` (``make bench`` runs it after the main suite).
"""

from __future__ import annotations

import json
import os
import statistics
import sys
import time
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

os.environ.setdefault("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")

from playwright.sync_api import Page, sync_playwright

from genparams.audit.walk import audit
from genparams.tune.checking import json_parameter
from genparams.tune.server import TuneServer
from tests.tune.support import demo_nodes

ROOT = Path(__file__).resolve().parent.parent
REPORT = ROOT / "docs" / "benchmarks.md"
START, END = "<!-- tune-bench:start -->", "<!-- tune-bench:end -->"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run"]
REPEATS = 5


def open_page(page: Page, url: str, node: str) -> tuple[float, float]:
    """Seconds from navigation to a usable form (first paint), and to its last control."""
    page.goto(f"{url}#{node}")
    page.wait_for_selector(f'form[data-node="{node}"] [data-param="group_0.p_0"]')
    ready = page.wait_for_selector("body[data-ready]")
    complete = page.wait_for_selector(f'form[data-node="{node}"][data-complete]')
    assert ready is not None and complete is not None
    assert page.locator('[data-param="group_19.p_49"]').count() == 1
    usable = int(ready.get_attribute("data-ready") or 0) / 1000
    return usable, int(complete.get_attribute("data-complete") or 0) / 1000


def check_numbers(url: str, token: str, node: str) -> list[float]:
    """Seconds per ``/api/check`` of one edit; the first compiles the node's schema message."""
    body = {"node": node, "params": [{"name": "group_0.p_0", "type": "double", "value": 2.5}]}
    times = []
    for _ in range(REPEATS + 1):
        request = urllib.request.Request(
            url.split("?")[0] + "api/check",
            data=json.dumps(body).encode(),
            headers={"content-type": "application/json", "x-genparams-token": token},
        )
        started = time.perf_counter()
        with urllib.request.urlopen(request, timeout=30) as response:
            assert json.loads(response.read())["successful"]
        times.append(time.perf_counter() - started)
    return times


def page_numbers(node: str) -> tuple[list[tuple[float, float]], list[float], list[float]]:
    server = TuneServer(nodes=(node,))
    url = server.start()
    try:
        server.graph.services_ready(node, 10.0)
        server.graph.wait_for_schemas([node], 10.0)
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(
                executable_path="/usr/bin/chromium", args=CHROMIUM_ARGS
            )
            page = browser.new_page()
            open_page(page, url, node)  # warm: the first load compiles the scripts
            loads = [open_page(browser.new_page(), url, node) for _ in range(REPEATS)]
            updates = []
            for index in range(REPEATS):
                value = 2.0 + index * 0.5
                selector = '[data-param="group_0.p_0"]'
                started = time.perf_counter()
                server.graph.set_parameters(
                    node, [json_parameter("group_0.p_0", "double", value)], atomic=False
                )
                # Polled from here: the page's CSP forbids the eval that wait_for_function needs.
                shown = f"document.querySelector('{selector}').value"
                deadline = started + 10.0
                while page.evaluate(shown) != f"{value:g}":
                    if time.perf_counter() > deadline:
                        raise TimeoutError(f"the page never showed {value:g}")
                updates.append(time.perf_counter() - started)
            browser.close()
        checks = check_numbers(url, server.token, node)
    finally:
        server.stop()
    return loads, updates, checks


def audit_numbers(counts: tuple[int, ...]) -> list[tuple[int, float]]:
    rows = []
    for count in counts:
        names = [f"bench_audit_{os.getpid()}_{i}" for i in range(count)]
        chunks = [names[i : i + 10] for i in range(0, count, 10)]
        with _all(chunks):
            server = TuneServer()  # only for its graph
            try:
                wanted = [f"/{n}" for n in names]
                audit(server.graph, only=wanted, settle=0.3, timeout=20.0)  # discovery
                times = []
                for _ in range(3):
                    result = audit(server.graph, only=wanted, settle=0.3)
                    assert len(result.audited) == count, result.plain
                    times.append(result.seconds)
                rows.append((count, statistics.median(times)))
            finally:
                server.graph.close()
    return rows


@contextmanager
def _all(chunks: list[list[str]]) -> Iterator[None]:
    if not chunks:
        yield
        return
    with demo_nodes(*(f"{n}:camera" for n in chunks[0])), _all(chunks[1:]):
        yield


def section(
    loads: list[tuple[float, float]],
    updates: list[float],
    checks: list[float],
    audits: list[tuple[int, float]],
) -> str:
    usable = [first for first, _ in loads]
    complete = [last for _, last in loads]
    load = os.getloadavg()[0]
    ms = lambda seconds: f"{seconds * 1000:.0f} ms"  # noqa: E731
    lines = [
        START,
        "## Tuning page and audit",
        "",
        "`python -m bench.tune`: Chromium (headless) on this machine, nodes in other processes;",
        f"{os.cpu_count()} CPUs, load average {load:.1f} while measuring.",
        "",
        "| measure | median | worst | target |",
        "|---|---|---|---|",
        f"| page for a node with 1,000 parameters, navigation to usable form (first paint) | "
        f"{ms(statistics.median(usable))} | {ms(max(usable))} | < 1 s |",
        f"| same page, navigation to its last control built | "
        f"{ms(statistics.median(complete))} | {ms(max(complete))} | |",
        f"| set made elsewhere until the page shows it | "
        f"{ms(statistics.median(updates))} | {ms(max(updates))} | < 1 s |",
        f"| check of one edit on that node, first (compiles its schema message) | "
        f"{ms(checks[0])} | | |",
        f"| same check, later (reads the node, runs rclpy's and the schema's checks) | "
        f"{ms(statistics.median(checks[1:]))} | {ms(max(checks[1:]))} | < 150 ms |",
        "",
        "| nodes audited | audit time | per node |",
        "|---|---|---|",
        *(f"| {n} | {ms(t)} | {ms(t / n)} |" for n, t in audits),
        "",
        "Audit time excludes discovery (the first run waits for it); each node costs one",
        "latched message and three service calls (list, get, describe).",
        END,
    ]
    return "\n".join(lines) + "\n"


def write_section(text: str) -> None:
    current = REPORT.read_text(encoding="utf-8") if REPORT.exists() else ""
    if START in current and END in current:
        head, _, rest = current.partition(START)
        _, _, tail = rest.partition(END + "\n")
        current = head + tail
    REPORT.write_text(current.rstrip("\n") + "\n\n" + text, encoding="utf-8")


def main() -> int:
    node = f"bench_wide_{os.getpid()}"
    with demo_nodes(f"{node}:wide1000"):
        loads, updates, checks = page_numbers(f"/{node}")
    audits = audit_numbers((1, 10, 20, 40))
    text = section(loads, updates, checks, audits)
    write_section(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
