"""The README is short, starts with the two commands, and reaches every page of docs/."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.docs_site.pages import DOCS, README, anchors, blocks, links, pages, repository_paths

pytestmark = pytest.mark.docs


def test_readme_is_short() -> None:
    lines = README.read_text(encoding="utf-8").splitlines()
    assert len(lines) <= 300, len(lines)


def test_readme_starts_with_demo_and_test() -> None:
    first = blocks(README.read_text(encoding="utf-8"))[0]
    commands = [line.split("#")[0].strip() for line in first.body.splitlines()]
    assert commands == ["make demo", "make test"]


def test_readme_links_every_docs_page() -> None:
    linked = {target.split("#")[0] for target in links(README.read_text(encoding="utf-8"))}
    missing = {f"docs/{page.name}" for page in DOCS.glob("*.md")} - linked - {"docs/index.md"}
    assert not missing, f"docs pages the README does not reach: {sorted(missing)}"


@pytest.mark.parametrize("page", pages(), ids=lambda page: page.name)
def test_relative_links_resolve(page: Path) -> None:
    """Links to files and sections exist (Sphinx checks docs/ too; this covers the README)."""
    problems = []
    for target in links(page.read_text(encoding="utf-8")):
        path, _, anchor = target.partition("#")
        file = (page.parent / path).resolve() if path else page
        if not file.exists():
            problems.append(f"{target}: no such file")
        elif anchor and anchor not in anchors(file.read_text(encoding="utf-8")):
            problems.append(f"{target}: no such section")
    assert not problems, problems


@pytest.mark.parametrize("page", pages(), ids=lambda page: page.name)
def test_named_repository_files_exist(page: Path) -> None:
    """Files the page names as code text (`tests/runtime/test_mapped.py`) were not moved away."""
    root = README.parent
    named = repository_paths(page.read_text(encoding="utf-8"))
    # Paths written as patterns (`tests/bad_schemas/NAME.yaml`) name no one file.
    missing = {path for path in named if not (root / path).exists() and "NAME" not in path}
    assert not missing, sorted(missing)
