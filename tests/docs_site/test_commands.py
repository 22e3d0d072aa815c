"""Every `genparams` command shown in the README and docs/ runs, with the exit code shown.

And when a block of output follows the command's block, the command prints exactly that.

The commands run in a copy of the files they read, so a command that writes
(`genparams generate` in a package) never touches the repository; `/tmp/` in a
command is a temporary folder.
"""

from __future__ import annotations

import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from tests.docs_site.pages import Block, blocks, pages, shell_lines
from tests.support import ROOT

pytestmark = pytest.mark.docs

_GENPARAMS = re.compile(r"(?:\.\./)*\.venv/bin/genparams")
# A trailing comment that ends with the exit code the command is shown to give.
_SHOWN_EXIT = re.compile(r"#.*\bexit (\d)\s*$")


def expected_exit(command: str) -> int:
    shown = _SHOWN_EXIT.search(command)
    if shown:
        return int(shown[1])
    return 1 if " check-params " in command and "/valid" not in command else 0


def cases() -> list[Any]:
    found: list[Any] = []
    for page in pages():
        for number, block in enumerate(blocks(page.read_text(encoding="utf-8"))):
            if block.lang == "sh" and _GENPARAMS.search(block.body):
                found.append(pytest.param(block, id=f"{page.name}-{number}"))
    return found


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    shutil.copytree(ROOT / "examples", root / "examples", ignore=shutil.ignore_patterns("build"))
    for folder in ("cases", "bad_schemas", "gpl", "rclpy_import", "launch"):
        shutil.copytree(ROOT / "tests" / folder, root / "tests" / folder)
    (tmp_path / "out").mkdir()
    return root


@pytest.mark.parametrize("block", cases())
def test_shown_commands_run(block: Block, workspace: Path) -> None:
    out = workspace.parent / "out"
    genparams = f"{shlex.quote(sys.executable)} -m genparams"
    cwd = workspace
    for line in shell_lines(block.body):
        if line.startswith("cd "):
            # `cd DIR && command`, or `cd DIR` alone for the lines after it, as in a
            # shell; `(cd DIR && command)` runs in a subshell and is left to the shell.
            folder, _, line = line[3:].partition("&&")
            cwd = cwd / folder.strip()
        if not _GENPARAMS.search(line):
            continue
        # /tmp/ first, so a /tmp/ in the interpreter's own path stays as it is.
        command = line.replace("/tmp/", shlex.quote(f"{out}/"))
        command = _GENPARAMS.sub(lambda _: genparams, command)
        result = subprocess.run(
            command, shell=True, cwd=cwd, capture_output=True, text=True, timeout=60, check=False
        )
        assert result.returncode == expected_exit(line), (line, result.stdout, result.stderr)
        if block.followed_by is not None and not block.followed_by.lang:
            # The block right after shows what the command prints.
            assert result.stdout + result.stderr == block.followed_by.body, line
