"""Excerpts of generated files shown in docs/ match the committed files they quote."""

from __future__ import annotations

import pytest

from tests.docs_site.pages import DOCS, blocks
from tests.support import ROOT

pytestmark = pytest.mark.docs

MODULE = ROOT / "examples/camera_node/camera_node/camera_driver_params.py"


def test_generated_module_excerpt_is_current() -> None:
    page = (DOCS / "generated-api.md").read_text(encoding="utf-8")
    excerpt = next(block for block in blocks(page) if "DO NOT EDIT" in block.body)
    module = MODULE.read_text(encoding="utf-8").splitlines()
    stale = [line for line in excerpt.body.splitlines() if line.strip() and line not in module]
    assert not stale, f"lines not in {MODULE.name} (regenerated since?): {stale}"
