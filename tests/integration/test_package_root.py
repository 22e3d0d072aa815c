"""The package root is the lazy facade of the API, at the top of every layer.

Nothing inside genparams imports it: the version lives in genparams/_version.py, which
imports nothing. So no import runs back up the layers, and pyproject's import-linter
contracts need no exception for the root.
"""

from __future__ import annotations

import re
import tomllib

import grimp

import genparams
from genparams._version import __version__
from tests.support import ROOT


def test_no_module_of_the_package_imports_the_root() -> None:
    graph = grimp.build_graph("genparams", exclude_type_checking_imports=False, cache_dir=None)
    assert len(graph.modules) > 50
    assert sorted(graph.find_modules_that_directly_import("genparams")) == []


def test_no_contract_makes_an_exception_for_the_root() -> None:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["importlinter"]
    ignored = [i for c in config["contracts"] for i in c.get("ignore_imports", [])]
    assert [i for i in ignored if i.split("->")[0].strip() == "genparams"] == []


def test_the_root_reports_the_version_of_its_one_source() -> None:
    assert genparams.__version__ == __version__
    hatch = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["hatch"]["version"]
    assert hatch == {"path": "genparams/_version.py"}


def test_the_changelog_names_this_version_as_the_newest_release() -> None:
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    releases = re.findall(r"^## \[(\d+\.\d+\.\d+)\] - \d{4}-\d{2}-\d{2}$", changelog, re.MULTILINE)
    assert releases[0] == __version__
    assert "## [Unreleased]" in changelog.split(f"## [{__version__}]")[0]
