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


def _values(count: int, width: int) -> str:
    return "[" + ", ".join(f"{chr(97 + i) * width}" for i in range(count)) + "]"


NEGATED = f"""genparams: 1
name: negated
parameters:
  a_rather_long_mode_name_for_layout: {{type: string, default: x}}
  fits: {{type: int, default: 1, when: {{a_rather_long_mode_name_for_layout: {{not: y}}}}}}
  one_line_of_arguments:
    type: int
    default: 1
    when: {{a_rather_long_mode_name_for_layout: {{not: {_values(4, 14)}}}}}
  one_argument_a_line:
    type: int
    default: 1
    when: {{a_rather_long_mode_name_for_layout: {{not: {_values(6, 16)}}}}}
  one_long_argument:
    type: int
    default: 1
    when: {{a_rather_long_mode_name_for_layout: {{not: {"z" * 90}}}}}
"""


def test_negated_conditions_of_every_length_are_ruff_formatted(tmp_path: Path) -> None:
    module = tmp_path / "negated_params.py"
    text = genparams.generate("negated.yaml", NEGATED)
    module.write_text(text, encoding="utf-8")
    assert text.count("_NoneOf(\n") == 3  # each too long for its line: split as ruff splits
    for argv in (["format", "--check", "--diff"], ["check"]):
        result = subprocess.run(
            [sys.executable, "-m", "ruff", *argv, "--no-cache", str(module)],
            cwd=ROOT,
            capture_output=True,
            text=True,
            timeout=120,
        )
        assert result.returncode == 0, result.stdout + result.stderr
