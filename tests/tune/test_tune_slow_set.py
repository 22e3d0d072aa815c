"""A set the node is still working on shows as such in the page, then as what the node did.

The node's on-set callback waits until the test lets it go, so the server's wait for the
answer (SET_WAIT_SECONDS) ends first, whatever the machine's load: the server answers 202,
and the page keeps the edit as sent but not confirmed. Once the node answers, the outcome
and the node's value come by the event stream.
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


@pytest.fixture(scope="module")
def gate(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    workdir = tmp_path_factory.mktemp("gated")
    with hostile_nodes(f"{GATED[1:]}:gated:{workdir}"):
        yield workdir


@pytest.fixture(scope="module")
def server(gate: Path) -> Iterator[TuneServer]:
    tune = TuneServer(nodes=(GATED,))
    tune.start()
    try:
        yield tune
    finally:
        tune.stop()


def slow_apply(page: Page, server: TuneServer, value: int) -> None:
    """Apply ``counter = value`` from the page; return once the node has it, unanswered."""
    open_node(page, server, GATED)
    page.locator("#live").uncheck()
    box = counter_box(page)
    box.fill(str(value))
    box.dispatch_event("change")
    apply = page.locator("[data-apply]")
    expect(apply).to_contain_text("Apply 1 change(s)")
    with page.expect_response("**/api/set") as answered:
        apply.click()
    assert answered.value.status == 202
    expect(page.locator("#status")).to_contain_text("still working on the set")
    expect(row(page)).to_have_attribute("data-verdict", "working")
    expect(note(page)).to_have_text("sent, not yet confirmed by the node")
    expect(apply).to_be_disabled()  # sent once: not offered again


def counter_box(page: Page) -> Locator:
    return page.locator(f'form[data-node="{GATED}"] input[data-param="counter"]')


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
