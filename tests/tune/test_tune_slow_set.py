"""A set the node is still working on shows as such in the page, then as what the node did.

The node's on-set callback waits until the test lets it go, so the server's wait for the
answer (SET_WAIT_SECONDS) ends first, whatever the machine's load: the server answers 202,
and the page keeps the edit as sent but not confirmed. Once the node answers, the outcome
and the node's value come by the event stream: applied, refused, an answer no one can use,
or no answer at all because the node left the graph.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from playwright.sync_api import Locator, Page, expect

from genparams.tune.server import TuneServer
from tests.live.support import hostile_nodes
from tests.support import RosHarness
from tests.tune.support import open_node, service_client, unique

GATED = f"/{unique('page_gated')}"
UNUSABLE = f"/{unique('page_gated_short')}"
LEAVING = f"/{unique('page_gated_leaving')}"


@pytest.fixture(scope="module")
def gate(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    workdir = tmp_path_factory.mktemp("gated")
    with hostile_nodes(f"{GATED[1:]}:gated:{workdir}", f"{UNUSABLE[1:]}:gated_short:{workdir}"):
        yield workdir


@pytest.fixture(scope="module")
def server(gate: Path) -> Iterator[TuneServer]:
    tune = TuneServer(nodes=(GATED, UNUSABLE, LEAVING))
    tune.start()
    try:
        yield tune
    finally:
        tune.stop()


def slow_apply(
    page: Page, server: TuneServer, value: int, node: str = GATED, *, live: bool = False
) -> None:
    """Set ``counter = value`` from the page (live: as typed, one value a set; else with the
    Apply button, atomically); return once the node has it, unanswered."""
    open_node(page, server, node)
    page.locator("#live").set_checked(live)
    box = counter_box(page, node)
    box.fill(str(value))
    with page.expect_response("**/api/set") as answered:
        box.dispatch_event("change")
        if not live:
            apply = page.locator("[data-apply]")
            expect(apply).to_contain_text("Apply 1 change(s)")
            apply.click()
    assert answered.value.status == 202
    expect(page.locator("#status")).to_contain_text("still working on the set")
    expect(row(page)).to_have_attribute("data-verdict", "working")
    expect(note(page)).to_have_text("sent, not yet confirmed by the node")
    if not live:
        expect(page.locator("[data-apply]")).to_be_disabled()  # sent once: not offered again


def counter_box(page: Page, node: str = GATED) -> Locator:
    return page.locator(f'form[data-node="{node}"] input[data-param="counter"]')


def row(page: Page) -> Locator:
    return page.locator('[data-row="counter"]')


def note(page: Page) -> Locator:
    return page.locator('[data-param-note="counter"]')


def calls(gate: Path) -> int:
    return int((gate / "count").read_text(encoding="utf-8"))


def test_a_slow_set_shows_as_still_working_then_as_applied(
    page: Page, server: TuneServer, gate: Path, ros_harness: RosHarness
) -> None:
    before = calls(gate) if (gate / "count").exists() else 0
    slow_apply(page, server, 7)
    assert calls(gate) == before + 1

    (gate / "release_7").touch()
    expect(page.locator("#status")).to_contain_text(f"{GATED} applied 1 change(s)")
    expect(row(page)).to_have_attribute("data-verdict", "ok")
    expect(note(page)).to_have_text("")
    expect(counter_box(page)).to_have_value("7")
    assert service_client(ros_harness, GATED).get("counter") == [7]
    assert calls(gate) == before + 1  # sent once


def test_a_slow_set_the_node_refuses_shows_its_reason_and_stays_to_apply(
    page: Page, server: TuneServer, gate: Path, ros_harness: RosHarness
) -> None:
    held = service_client(ros_harness, GATED).get("counter")
    slow_apply(page, server, 13)

    (gate / "release_13").touch()
    expect(page.locator("#status")).to_contain_text("the node rejected the change")
    expect(row(page)).to_have_attribute("data-verdict", "refused")
    expect(page.locator('[data-param-error="counter"]')).to_have_text("13 is unlucky")
    expect(page.locator("[data-apply]")).to_contain_text("Apply 1 change(s)")
    assert service_client(ros_harness, GATED).get("counter") == held


def test_a_slow_set_answered_unusably_shows_why(page: Page, server: TuneServer, gate: Path) -> None:
    slow_apply(page, server, 21, UNUSABLE, live=True)  # one value a set: a list of results

    (gate / "release_21").touch()
    expect(page.locator("#status")).to_contain_text(
        f"{UNUSABLE}: its set answer cannot be used: 2 results for 1 values"
    )
    expect(row(page)).to_have_attribute("data-verdict", "refused")
    expect(note(page)).to_have_text("")


def test_a_slow_set_whose_node_leaves_unanswering_ends_as_unknown(
    page: Page, server: TuneServer, tmp_path: Path
) -> None:
    with hostile_nodes(f"{LEAVING[1:]}:gated:{tmp_path}"):
        slow_apply(page, server, 5, LEAVING)
        (tmp_path / "leave_5").touch()
        expect(page.locator("#status")).to_contain_text(
            f"{LEAVING}: the node left the graph before answering the set", timeout=60_000
        )
        expect(row(page)).to_have_attribute("data-verdict", "unknown")
        expect(note(page)).to_have_text("outcome unknown: the node left before answering")
