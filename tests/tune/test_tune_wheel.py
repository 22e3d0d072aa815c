"""The tuning page's assets ship in the wheel: no CDN, no build step."""

from __future__ import annotations

import zipfile
from pathlib import Path

import pytest

from tests.build_support import build_wheel, copy_repository

ASSETS = ("index.html", "app.js", "api.js", "form.js", "json.js", "keep.js", "style.css")


@pytest.mark.slow
def test_wheel_ships_the_page(tmp_path: Path) -> None:
    source = copy_repository(tmp_path / "src")
    wheel = build_wheel(source, tmp_path / "dist")
    with zipfile.ZipFile(wheel) as archive:
        names = set(archive.namelist())
        page = archive.read("genparams/tune/static/index.html").decode()
    assert {f"genparams/tune/static/{asset}" for asset in ASSETS} <= names
    assert "http" not in page  # every script and style is served by genparams itself


def test_every_asset_is_local() -> None:
    static = Path(__file__).resolve().parents[2] / "genparams" / "tune" / "static"
    assert sorted(p.name for p in static.iterdir()) == sorted(ASSETS)
    for asset in ASSETS:
        text = (static / asset).read_text(encoding="utf-8")
        assert "https://" not in text and "http://" not in text, asset
