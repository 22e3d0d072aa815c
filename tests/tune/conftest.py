"""The browser and page the tuning tests drive (Debian's Chromium through Playwright)."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from playwright.sync_api import Browser, Page, expect, sync_playwright

from tests.patience import WAIT_S
from tests.tune.support import CHROMIUM, CHROMIUM_ARGS

# What the page shows follows the nodes and the server: a loaded machine delays it, and a
# wait ends as soon as the page shows it.
expect.set_options(timeout=WAIT_S * 1000)


@pytest.fixture(scope="module")
def browser() -> Iterator[Browser]:
    with sync_playwright() as playwright:
        launched = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield launched
        launched.close()


@pytest.fixture
def page(browser: Browser) -> Iterator[Page]:
    opened = browser.new_page(viewport={"width": 1200, "height": 1000})
    opened.set_default_timeout(WAIT_S * 1000)
    yield opened
    opened.close()
