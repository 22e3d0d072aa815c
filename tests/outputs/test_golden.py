"""Generated modules of tests/cases match their golden files and pass mypy --strict and ruff.

After an intended change of generated output: ``make golden`` and review the diff.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.golden import CASES, ROOT, case_dirs, render_case

CASE_DIRS = case_dirs()


def test_every_case_has_a_golden_module() -> None:
    assert len(CASE_DIRS) >= 6
    missing = [case.name for case in CASE_DIRS if not (case / "expected_params.py").is_file()]
    assert missing == [], "run `make golden`"


@pytest.mark.parametrize("case", CASE_DIRS, ids=lambda case: case.name)
def test_generated_module_matches_golden(case: Path) -> None:
    expected = (case / "expected_params.py").read_text(encoding="utf-8")
    assert render_case(case) == expected, "generated code changed: review, then `make golden`"


def run_tool(*argv: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", *argv], cwd=ROOT, capture_output=True, text=True, timeout=300
    )


def test_golden_modules_pass_mypy_strict(tmp_path: Path) -> None:
    # One mypy run over every case; modules are copied under distinct names.
    for case in CASE_DIRS:
        shutil.copy(case / "expected_params.py", tmp_path / f"{case.name}_params.py")
    result = run_tool(
        "mypy", "--strict", "--config-file", str(ROOT / "pyproject.toml"), str(tmp_path)
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert f"no issues found in {len(CASE_DIRS)} source files" in result.stdout


def test_golden_modules_pass_ruff_check_and_format() -> None:
    modules = [str(case / "expected_params.py") for case in CASE_DIRS]
    check = run_tool("ruff", "check", "--no-cache", *modules)
    assert check.returncode == 0, check.stdout + check.stderr
    formatted = run_tool("ruff", "format", "--check", "--no-cache", *modules)
    assert formatted.returncode == 0, formatted.stdout + formatted.stderr


def test_cases_folder_holds_only_case_folders() -> None:
    stray = [p.name for p in CASES.iterdir() if p.is_file() or not (p / "schema.yaml").exists()]
    assert [name for name in stray if name != "__pycache__"] == []
