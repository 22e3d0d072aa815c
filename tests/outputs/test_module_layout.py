"""Generated modules are laid out as ruff format lays them out, in columns, not characters."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import genparams
from tests.golden import ROOT

WIDE = "\U000214c0" * 40  # each takes two columns: the literal fits in characters, not columns
ACCENTS = "e\u0301" * 10  # a combining mark takes no column
SCHEMA = f"""genparams: 1
name: wide
parameters:
  mode:
    type: string
    default: b
    choices: ["{WIDE}", "b", "a"]
  tag:
    type: string
    default: "{WIDE[:20]}"
    description: "{ACCENTS}"
"""


def test_a_module_with_wide_characters_is_ruff_formatted(tmp_path: Path) -> None:
    module = tmp_path / "wide_params.py"
    module.write_text(genparams.generate("wide.yaml", SCHEMA), encoding="utf-8")
    result = subprocess.run(
        [sys.executable, "-m", "ruff", "format", "--check", "--diff", "--no-cache", str(module)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 0, result.stdout + result.stderr
