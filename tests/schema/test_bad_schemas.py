"""The bad-schema corpus: every file fails with its golden error, exit 2, nothing written.

After an intended change of a message: ``python -m tests.update_golden bad``.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from genparams.schema.loader import MAX_BYTES
from tests.golden import ROOT, bad_schemas, expected_stderr_path, relative, run_cli
from tests.patience import run_patiently

SCHEMAS = bad_schemas()
GOOD = ROOT / "tests" / "cases" / "all_types" / "schema.yaml"


def expected(schema: Path) -> str:
    return expected_stderr_path(schema).read_text(encoding="utf-8")


def test_corpus_is_large_and_complete() -> None:
    assert len(SCHEMAS) >= 40
    missing = [s.name for s in SCHEMAS if not expected_stderr_path(s).is_file()]
    assert missing == [], "run `python -m tests.update_golden bad`"
    stray = {p.stem for p in SCHEMAS[0].parent.glob("*.stderr")} - {s.stem for s in SCHEMAS}
    assert stray == set()


@pytest.mark.parametrize("schema", SCHEMAS, ids=lambda s: s.stem)
def test_validate_reports_golden_errors(schema: Path) -> None:
    code, stderr = run_cli("validate", str(schema))
    assert (code, stderr) == (2, expected(schema))
    for line in stderr.splitlines():  # FILE:LINE:COL: ...
        file, line_no, column, _rest = line.split(":", 3)
        assert file == relative(str(schema)) and int(line_no) >= 1 and int(column) >= 1


@pytest.mark.parametrize("schema", SCHEMAS, ids=lambda s: s.stem)
def test_generate_fails_the_same_way_and_touches_nothing(schema: Path, tmp_path: Path) -> None:
    kept = tmp_path / "kept_params.py"
    kept.write_text("# a previous, good output\n", encoding="utf-8")
    assert run_cli("generate", str(schema), "-o", str(kept)) == (2, expected(schema))
    assert kept.read_text(encoding="utf-8") == "# a previous, good output\n"
    fresh = tmp_path / "fresh_params.py"
    assert run_cli("generate", str(schema), "-o", str(fresh))[0] == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == ["kept_params.py"]


def test_one_bad_schema_among_good_ones_writes_nothing(tmp_path: Path) -> None:
    out = tmp_path / "out"
    bad = SCHEMAS[0]
    code, stderr = run_cli("generate", str(GOOD), str(bad), "--out-dir", str(out))
    assert (code, stderr) == (2, expected(bad))
    assert not out.exists()


def test_real_command_reports_every_file_at_once() -> None:
    result = subprocess.run(
        [sys.executable, "-m", "genparams", "validate", *(str(s) for s in SCHEMAS)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 2
    assert relative(result.stderr) == "".join(expected(s) for s in SCHEMAS)


def test_real_command_generate_exits_2_without_output(tmp_path: Path) -> None:
    target = tmp_path / "never_params.py"
    schema = SCHEMAS[-1]
    result = subprocess.run(
        [sys.executable, "-m", "genparams", "generate", str(schema), "-o", str(target)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert (result.returncode, relative(result.stderr)) == (2, expected(schema))
    assert not target.exists()


# The peak is read from /proc/self/status (VmHWM: this process's own high-water mark),
# not getrusage: Linux carries the parent's peak at fork into the child's ru_maxrss, so
# it would depend on what the test process ran before. Time is CPU time, so a loaded
# machine does not fail the bound while a blow-up still does.
MEASURE = """
import json, sys, time
from genparams.api import load_schema
from genparams.schema.errors import SchemaError
start = time.process_time()
try:
    load_schema(sys.argv[1])
    message = "accepted"
except SchemaError as exc:
    message = str(exc).splitlines()[0]
seconds = time.process_time() - start
with open("/proc/self/status", encoding="ascii") as status:
    peak_kb = next(int(line.split()[1]) for line in status if line.startswith("VmHWM:"))
print(json.dumps({"seconds": seconds, "max_rss_mb": peak_kb / 1024, "message": message}))
"""


def measure(schema: Path) -> dict[str, object]:
    result = run_patiently([sys.executable, "-c", MEASURE, str(schema)], budget_s=60, cwd=ROOT)
    assert result.returncode == 0, result.stderr
    outcome: dict[str, object] = json.loads(result.stdout)
    return outcome


HEAD = "genparams: 1\nname: big\nparameters:\n"


def hostile_inputs(folder: Path) -> dict[str, tuple[Path, str]]:
    """Name -> (file, expected start of the error), written at test time (too big to commit)."""
    files: dict[str, tuple[Path | str, str]] = {
        "alias bomb": (SCHEMAS[0].parent / "yaml_alias_bomb.yaml", "an alias bomb"),
        "flow nesting 100000 deep": (
            HEAD + "  x: " + "[" * 100_000 + "]" * 100_000 + "\n",
            "nested deeper than 64 levels",
        ),
        "file over the size limit": (
            HEAD + "  x: {type: string, default: " + "a" * MAX_BYTES + "}\n",
            f"file is larger than {MAX_BYTES} bytes",
        ),
        "description just under the size limit": (
            HEAD + "  x: {type: int, default: one, description: " + "a" * (MAX_BYTES - 99) + "}\n",
            "default does not match type",
        ),
        "60000 parameters, all named x": (
            HEAD + "  x: {type: int, default: 1}\n" * 60_000,
            "too large, or an alias bomb",
        ),
    }
    out = {}
    for name, (content, message) in files.items():
        if isinstance(content, Path):
            out[name] = (content, message)
            continue
        path = folder / (name.replace(" ", "_") + ".yaml")
        path.write_text(content, encoding="utf-8")
        out[name] = (path, message)
    return out


def test_hostile_inputs_fail_fast_with_bounded_memory(tmp_path: Path) -> None:
    """Each runs in a fresh interpreter: CPU time and peak RSS are its own."""
    for name, (path, message) in hostile_inputs(tmp_path).items():
        outcome = measure(path)
        assert message in str(outcome["message"]), (name, outcome)
        assert float(outcome["seconds"]) < 5.0, (name, outcome)  # type: ignore[arg-type]
        assert float(outcome["max_rss_mb"]) < 250, (name, outcome)  # type: ignore[arg-type]


def test_measured_peak_is_the_childs_own(tmp_path: Path) -> None:
    """A parent holding 300 MB must not show in the child's peak, whatever ran before."""
    ballast = b"x" * (300 * 1024 * 1024)
    schema = tmp_path / "small.yaml"
    schema.write_text(HEAD + "  x: {type: int, default: 1}\n", encoding="utf-8")
    outcome = measure(schema)
    assert len(ballast) and outcome["message"] == "accepted", outcome
    assert float(outcome["max_rss_mb"]) < 150, outcome  # type: ignore[arg-type]
