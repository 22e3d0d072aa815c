"""Values on the page as the node holds them: int64 past 2^53 exact, doubles as doubles,
and the rules that read a parameter next to it."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from playwright.sync_api import Page, expect
from rclpy.parameter import Parameter

from genparams.tune.server import TuneServer
from tests.support import RosHarness
from tests.tune.support import demo_nodes, eventually, open_node, service_client, unique

NODE = f"/{unique('tune_values')}"
BIG = 9007199254740993  # 2^53 + 1: a JavaScript number rounds it to ...992


@pytest.fixture(scope="module")
def server() -> Iterator[TuneServer]:
    with demo_nodes(f"{NODE[1:]}:values"):
        tune = TuneServer(nodes=(NODE,))
        tune.start()
        try:
            yield tune
        finally:
            tune.stop()


def box(page: Page, name: str):  # type: ignore[no-untyped-def]
    """The text or number box of a parameter (a ranged one's box beside its slider)."""
    form = page.locator(f'form[data-node="{NODE}"]')
    ranged = form.locator(f'[data-param-box="{name}"]')
    return ranged if ranged.count() else form.locator(f'[data-param="{name}"]')


def items(page: Page, name: str):  # type: ignore[no-untyped-def]
    return page.locator(f'form[data-node="{NODE}"] [data-param="{name}"] input')


def test_integers_past_2_53_keep_every_digit(
    page: Page, server: TuneServer, ros_harness: RosHarness
) -> None:
    open_node(page, server, NODE)
    expect(box(page, "big")).to_have_value(str(BIG))
    expect(items(page, "ids").nth(0)).to_have_value(str(BIG))
    expect(items(page, "ids").nth(1)).to_have_value("-9223372036854775808")
    remote = service_client(ros_harness, NODE)
    # From the page to the node, then from the node (an event) to the page.
    box(page, "big").fill(str(BIG + 2))
    box(page, "big").dispatch_event("change")
    eventually(lambda: remote.get("big") == [BIG + 2])
    assert remote.set(Parameter("big", value=BIG + 4))[0].successful
    expect(box(page, "big")).to_have_value(str(BIG + 4))


def test_doubles_show_as_doubles(page: Page, server: TuneServer, ros_harness: RosHarness) -> None:
    open_node(page, server, NODE)
    expect(box(page, "ratio")).to_have_value("30.0")
    expect(box(page, "ranged")).to_have_value("2.0")
    expect(items(page, "weights").nth(0)).to_have_value("1.0")
    expect(items(page, "weights").nth(1)).to_have_value("2.5")
    assert service_client(ros_harness, NODE).set(Parameter("ratio", value=31.0))[0].successful
    expect(box(page, "ratio")).to_have_value("31.0")
    expect(page.locator('[data-diff="ratio"] td').nth(1)).to_have_text("30.0")
    expect(page.locator('[data-diff="ratio"] td').nth(2)).to_have_text("31.0")


def test_rules_show_next_to_the_parameters_they_read(page: Page, server: TuneServer) -> None:
    open_node(page, server, NODE)
    text = "rule low_below_ranged: low <= ranged (low stays at or below ranged.)"
    for name in ("low", "ranged"):
        rule = page.locator(f'[data-param-rules="{name}"] [data-rule="low_below_ranged"]')
        expect(rule).to_have_text(text)
    expect(page.locator('[data-param-rules="ratio"]')).to_have_count(0)
