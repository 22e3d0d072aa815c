"""The real-world corpus: other projects' schemas and params files, read where they live.

They are public ROS 2 repositories' files, so this repository holds none of them. They sit
in ``shared/corpus`` beside the repository's root (``GENPARAMS_CORPUS`` names another
folder); each of its folders (``gpl``, ``paramsfile``, ``realworld``) has a SOURCES.md that
names every file's repository, commit, path and license.

Where the corpus is absent, as in a clone of one's own, every test that reads it skips
with the one reason below. In CI (``CI=true``) its absence is a failure instead.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import NoReturn

import pytest

ENV = "GENPARAMS_CORPUS"
DEFAULT = Path(__file__).resolve().parent.parent.parent / "shared" / "corpus"


def location() -> Path:
    """The corpus folder: ``$GENPARAMS_CORPUS``, else ``shared/corpus`` beside the repository."""
    named = os.environ.get(ENV)
    return Path(named).expanduser().resolve() if named else DEFAULT


def absent_reason(missing: Path | None = None) -> str:
    return (
        f"the real-world corpus is absent: no {missing or location()} (the shared/corpus folder "
        f"beside the repository, or ${ENV}); see docs/development.md, 'The real-world corpus'"
    )


def folder(name: str) -> Path:
    """``<corpus>/<name>`` with its SOURCES.md; else the test or module skips (fails in CI).

    Called at a test module's top it skips the whole module; inside a test, that test.
    """
    path = location() / name
    if not (path / "SOURCES.md").is_file():
        _absent(path / "SOURCES.md" if location().is_dir() else location())
    return path


def _absent(missing: Path) -> NoReturn:
    reason = absent_reason(missing)
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(reason, pytrace=False)
    pytest.skip(reason, allow_module_level=True)
