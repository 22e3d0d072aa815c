"""The docs/ site builds with Sphinx and MyST, warnings as errors, as `make docs` builds it."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tests.support import ROOT

pytestmark = pytest.mark.docs

DOCS = ROOT / "docs"


def build(out: Path) -> subprocess.CompletedProcess[str]:
    # -E: read every page again, so no cached environment hides a warning.
    command = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", "-b", "html"]
    command += ["-d", str(out / "doctrees"), str(DOCS), str(out / "html")]
    return subprocess.run(command, capture_output=True, text=True, timeout=120, check=False)


def test_docs_build_without_warnings(tmp_path: Path) -> None:
    result = build(tmp_path)
    assert result.returncode == 0, result.stderr
    assert "WARNING" not in result.stderr, result.stderr
    pages = sorted(page.stem for page in DOCS.glob("*.md"))
    built = sorted(page.stem for page in (tmp_path / "html").glob("*.html"))
    # Every page is built (a page outside every toctree would also have warned).
    assert set(pages) <= set(built), set(pages) - set(built)


def test_a_broken_link_fails_the_build(tmp_path: Path) -> None:
    """The build is strict: a link to a missing section of a page is an error."""
    docs = tmp_path / "docs"
    docs.mkdir()
    (docs / "conf.py").write_text((DOCS / "conf.py").read_text(encoding="utf-8"))
    (docs / "index.md").write_text(
        "# Index\n\n```{toctree}\nother\n```\n\nSee [the part](other.md#no-such-part).\n"
    )
    (docs / "other.md").write_text("# Other\n\n## A part\n")
    command = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html"]
    command += [str(docs), str(tmp_path / "html")]
    result = subprocess.run(command, capture_output=True, text=True, timeout=120, check=False)
    assert result.returncode != 0
    assert "no-such-part" in result.stderr
