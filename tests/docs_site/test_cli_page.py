"""docs/cli.md's table lists every command the `genparams` parser has, and no other."""

from __future__ import annotations

import argparse
import re

import pytest

from genparams.cli import build_parser
from tests.docs_site.pages import DOCS

pytestmark = pytest.mark.docs

_TABLE_COMMAND = re.compile(r"^\| `genparams ([a-z][a-z-]*)", re.MULTILINE)


def parser_commands() -> set[str]:
    subparsers = [
        action
        for action in build_parser()._actions
        if isinstance(action, argparse._SubParsersAction)
    ]
    return set(subparsers[0].choices)


def test_the_table_lists_every_command() -> None:
    page = (DOCS / "cli.md").read_text(encoding="utf-8")
    # The first table of the page, before its first section.
    listed = _TABLE_COMMAND.findall(page.split("\n## ")[0])
    commands = parser_commands()
    assert {"check-deployment", "explain", "tune", "audit"} <= commands
    assert sorted(set(listed)) == sorted(commands)
    assert len(listed) == len(set(listed))
