"""The tuning page in real Chromium on a node with open groups (``for_each: overrides``):
the entries the node declared from its params file are listed with their types and
checks, and sets work on them; a mapped group inside an open group's entry is listed
once per key. The node runs in another process (schema: tests/cases/open_groups)."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from playwright.sync_api import Page, expect

from genparams.tune.server import TuneServer
from tests.runtime.test_open_groups import PARAMS  # one params file for node and page
from tests.support import RosHarness, ServiceClient
from tests.tune.support import demo_nodes, eventually, open_node, unique

NODE = f"/{unique('tune_open')}"


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[TuneServer]:
    params = tmp_path_factory.mktemp("open groups") / "params file.yaml"
    params.write_text(PARAMS, encoding="utf-8")
    with demo_nodes(f"{NODE[1:]}:open", ros_args=("--params-file", str(params))):
        tune = TuneServer(nodes=(NODE,))
        tune.start()
        try:
            yield tune
        finally:
            tune.stop()


@pytest.fixture
def page(page: Page, server: TuneServer) -> Page:
    """The page (tests/tune/conftest.py) with the node open."""
    open_node(page, server, NODE)
    return page


@pytest.fixture(scope="module")
def remote(ros_harness: RosHarness) -> ServiceClient:
    return ServiceClient(ros_harness, NODE)


def control(page: Page, name: str):  # type: ignore[no-untyped-def]
    return page.locator(f'form[data-node="{NODE}"] [data-param="{name}"]')


def row(page: Page, name: str):  # type: ignore[no-untyped-def]
    return page.locator(f'[data-row="{name}"]')


def test_an_open_group_lists_the_entries_the_node_declared(page: Page) -> None:
    group = page.locator('[data-map="sensors"]')
    expect(group).to_contain_text("one entry per key given under sensors in the overrides")
    entries = group.locator("[data-entry]")
    expect(entries).to_have_count(2)
    assert [entries.nth(i).get_attribute("data-entry") for i in range(2)] == [
        "sensors.front",
        "sensors.rear",
    ]
    # Each entry's fields with their types and checks, values as the node holds them.
    expect(control(page, "sensors.front.rate")).to_have_attribute("type", "range")
    expect(control(page, "sensors.front.rate")).to_have_attribute("max", "200")
    expect(page.locator('[data-param-box="sensors.front.rate"]')).to_have_value("50.0")
    expect(page.locator('[data-param-box="sensors.rear.rate"]')).to_have_value("30.0")
    expect(row(page, "sensors.rear.rate")).to_contain_text("within [1.0, 200.0]")
    expect(control(page, "sensors.rear.enabled")).to_have_attribute("type", "checkbox")
    expect(control(page, "sensors.rear.topic")).to_have_value("/rear/scan")
    expect(row(page, "sensors.rear.topic")).to_contain_text("Topic the sensor publishes on.")
    expect(row(page, "sensors.rear.topic").locator(".required")).to_have_count(1)
    # Keys come from the overrides at startup: the page offers none to add or remove.
    expect(group.locator("[data-map-add], [data-map-remove]")).to_have_count(0)
    # No entry is left to the section of parameters outside the schema.
    expect(page.locator('[data-section^="other"] [data-row^="sensors."]')).to_have_count(0)


def test_a_map_inside_an_open_group_is_listed_per_key(page: Page) -> None:
    expect(page.locator('[data-map="controllers"]')).to_have_count(1)
    inner = page.locator('[data-map="controllers.arm.gains"]')
    expect(inner).to_contain_text("one entry per item of joints")
    expect(inner.locator("[data-entry]")).to_have_count(2)
    expect(control(page, "controllers.arm.gains.left.p")).to_have_value("2.0")
    expect(control(page, "controllers.arm.gains.right.p")).to_have_value("1.0")
    expect(page.locator('[data-row*="*"]')).to_have_count(0)  # no template is shown


def test_a_set_on_an_open_group_entry_reaches_the_node(page: Page, remote: ServiceClient) -> None:
    box = page.locator('[data-param-box="sensors.rear.rate"]')  # the slider moves by 0.199
    box.fill("60")
    box.dispatch_event("change")
    eventually(lambda: remote.get("sensors.rear.rate") == [60.0])
    topic = control(page, "sensors.front.topic")
    topic.fill("/front/points")
    topic.dispatch_event("change")
    eventually(lambda: remote.get("sensors.front.topic") == ["/front/points"])


def test_an_open_group_entry_is_checked_by_its_field(page: Page, remote: ServiceClient) -> None:
    box = page.locator('[data-param-box="sensors.front.rate"]')
    box.fill("500")
    box.dispatch_event("change")
    expect(page.locator('[data-param-error="sensors.front.rate"]')).to_contain_text(
        "sensors.front.rate: must be within"
    )
    assert remote.get("sensors.front.rate") == [50.0]


def test_keys_of_a_map_inside_an_open_group_follow_its_key_list(
    page: Page, remote: ServiceClient
) -> None:
    inner = page.locator('[data-map="controllers.arm.gains"]')
    inner.locator('[data-map-add="controllers.arm.gains"]').fill("wrist")
    inner.locator('[data-map-add-button="controllers.arm.gains"]').click()
    expect(control(page, "controllers.arm.gains.wrist.p")).to_be_visible(timeout=30_000)
    assert remote.get("joints") == [["left", "right", "wrist"]]
