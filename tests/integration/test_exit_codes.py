"""Every command keeps the exit codes docs/cli.md promises.

0 on success, 1 when a check finds a problem, 2 for bad input or usage. Each
command has a run of each kind it can give (audit and import-node only their bad
input here: their other codes need a running node, and
tests/tune/test_audit.py and tests/import_node/test_import_node.py prove them),
and every code-2 run says why on stderr, through `genparams.cli.main`, never with
a traceback. `genparams tune` serves until interrupted, then exits 0.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import secrets
import signal
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

from genparams.cli import build_parser, main
from genparams.errors import CommandError
from tests.support import ROOT

EXAMPLE = ROOT / "examples" / "camera_node" / "camera_driver.yaml"
CHECKS = ROOT / "tests" / "cases" / "camera_driver" / "check_params"
VALID = CHECKS / "valid_minimal" / "params.yaml"
OUT_OF_RANGE = CHECKS / "out_of_range" / "params.yaml"
GPL = ROOT / "tests" / "gpl" / "sources" / "conveyor_controller_parameters.yaml"
RCLPY_NODES = ROOT / "tests" / "rclpy_import" / "nodes"
NODE = "/camera/camera_driver"
LAUNCH = ROOT / "tests" / "launch" / "corpus" / "camera_driver" / "launch" / "camera.launch.yaml"


@dataclass(frozen=True)
class Run:
    command: str
    code: int
    what: str
    args: tuple[str, ...]  # "@NAME" stands for the file NAME of inputs(), "@TMP" a fresh folder


def inputs(tmp: Path) -> dict[str, str]:
    """What the runs read: the repository's files, and a few written for them in ``tmp``."""
    gpl_warning = tmp / "gpl.yaml"
    gpl_warning.write_text(
        "ctrl:\n  rate: {type: double, default_value: 1.0, unit: Hz}\n", encoding="utf-8"
    )
    manifest = tmp / "deploy.yaml"
    schema = json.dumps(str(EXAMPLE))
    manifest.write_text(
        f"genparams_deployment: 1\nnodes:\n  {NODE}:\n    schemas: [{schema}]\n", encoding="utf-8"
    )
    deployed_valid = tmp / "bringup.yaml"
    section = f"{NODE}:\n  ros__parameters:\n    serial: ABCD1234\n"
    deployed_valid.write_text(section, encoding="utf-8")
    deployed_bad = tmp / "bringup_bad.yaml"
    deployed_bad.write_text(section + "    camera: {fps: 500.0}\n", encoding="utf-8")
    bad_schema = tmp / "bad.yaml"
    bad_schema.write_text("name: 3\n", encoding="utf-8")
    files = {
        "@SCHEMA": EXAMPLE,
        "@BAD_SCHEMA": bad_schema,
        "@VALID": VALID,
        "@OUT_OF_RANGE": OUT_OF_RANGE,
        "@MANIFEST": manifest,
        "@DEPLOYED_VALID": deployed_valid,
        "@DEPLOYED_BAD": deployed_bad,
        "@GPL_WARNING": gpl_warning,
        "@GPL": GPL,
        "@RCLPY_EXACT": RCLPY_NODES / "key_teleop.py",
        "@RCLPY_LOSSY": RCLPY_NODES / "legacy_bridge.py",
        "@MISSING": tmp / "no such file.yaml",
        "@TMP": tmp,
    }
    return {name: str(path) for name, path in files.items()}


def argv(run: Run, tmp: Path) -> list[str]:
    files = inputs(tmp)
    expanded = []
    for arg in run.args:
        for name in sorted(files, key=len, reverse=True):
            arg = arg.replace(name, files[name])
        expanded.append(arg)
    return [run.command, *expanded]


def _run(command: str, code: int, what: str, *args: str) -> Run:
    return Run(command, code, what, args)


RUNS = [
    _run("generate", 0, "writes the module", "@SCHEMA", "-o", "@TMP/m.py"),
    _run("generate", 1, "--check of a missing output", "@SCHEMA", "-o", "@TMP/m.py", "--check"),
    _run("generate", 2, "a missing schema", "@MISSING"),
    _run("generate", 2, "-o with two schemas", "@SCHEMA", "@SCHEMA", "-o", "@TMP/m.py"),
    _run("validate", 0, "a valid schema", "@SCHEMA"),
    _run("validate", 2, "a schema with an error", "@BAD_SCHEMA"),
    _run("validate", 2, "no schema"),
    _run("docs", 0, "a page", "@SCHEMA", "-o", "@TMP/d.md"),
    _run("docs", 2, "an unknown format", "@SCHEMA", "--format", "pdf"),
    _run("defaults", 0, "a params file", "@SCHEMA", "-o", "@TMP/p.yaml"),
    _run("defaults", 2, "an invalid node name", "@SCHEMA", "--node", "/a//b"),
    _run("json-schema", 0, "a JSON Schema", "@SCHEMA", "-o", "@TMP/j.json"),
    _run("json-schema", 2, "a missing schema", "@MISSING"),
    _run("check-params", 0, "a valid file", "@SCHEMA", "@VALID"),
    _run("check-params", 1, "a value out of range", "@SCHEMA", "@OUT_OF_RANGE"),
    _run("check-params", 2, "a missing params file", "@SCHEMA", "@MISSING"),
    _run("check-params", 2, "an invalid --node", "@SCHEMA", "@VALID", "--node", "a b"),
    _run("check-deployment", 0, "a valid file", "@DEPLOYED_VALID", "--manifest", "@MANIFEST"),
    _run("check-deployment", 1, "out of range", "@DEPLOYED_BAD", "--manifest", "@MANIFEST"),
    _run("check-deployment", 2, "no manifest and no --map", "@VALID"),
    _run("explain", 0, "a valid file", NODE, "--schema", "@SCHEMA", "--params-file", "@VALID"),
    _run(
        "explain", 1, "out of range", NODE, "--schema", "@SCHEMA", "--params-file", "@OUT_OF_RANGE"
    ),
    _run("explain", 2, "an invalid node name", "a b", "--schema", "@SCHEMA"),
    _run("launch-nodes", 0, "a launch file", str(LAUNCH)),
    _run("launch-nodes", 2, "a missing launch file", "@MISSING"),
    _run("launch-nodes", 2, "an --arg without :=", str(LAUNCH), "--arg", "fps"),
    _run("tune", 2, "an invalid node name", "a b"),
    _run("tune", 2, "a port that is not a number", "--port", "http"),
    _run("audit", 2, "an invalid node name", "a b"),
    _run("audit", 2, "a missing params file", "--params-file", "@MISSING"),
    _run("import-gpl", 0, "an exact import", "@GPL", "-o", "@TMP/s.yaml"),
    _run("import-gpl", 1, "a key left out", "@GPL_WARNING", "-o", "@TMP/s.yaml"),
    _run("import-gpl", 2, "a missing file", "@MISSING"),
    _run("import-node", 2, "an invalid node name", "a b"),
    _run("import-rclpy", 0, "an exact import", "@RCLPY_EXACT", "-o", "@TMP/s.yaml"),
    _run("import-rclpy", 1, "parameters left out", "@RCLPY_LOSSY", "-o", "@TMP/s.yaml"),
    _run("import-rclpy", 2, "a missing file", "@MISSING"),
    _run("cmake-dir", 0, "the folder"),
    _run("cmake-dir", 2, "an unknown argument", "extra"),
]


def command_names() -> set[str]:
    parser = build_parser()
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return set(action.choices)


def run(argv: list[str]) -> tuple[int, str, str]:
    """Exit code, stdout and stderr of one in-process run, as the installed command gives them."""
    stdout, stderr = io.StringIO(), io.StringIO()
    with contextlib.redirect_stderr(stderr), contextlib.redirect_stdout(stdout):
        try:
            code = main(argv)
        except SystemExit as exc:  # argparse's usage errors
            code = exc.code if isinstance(exc.code, int) else 2
    return code, stdout.getvalue(), stderr.getvalue()


def test_every_command_has_a_success_and_a_bad_input() -> None:
    covered = {(r.command, r.code) for r in RUNS}
    graph_only = {"audit", "import-node"}  # their runs that succeed need a live node
    covered.add(("tune", 0))  # test_tune_exits_0_once_interrupted
    for name in command_names():
        assert (name, 2) in covered, name
        assert name in graph_only or (name, 0) in covered, name


@pytest.mark.parametrize("case", RUNS, ids=[f"{r.command}-{r.code}-{r.what}" for r in RUNS])
def test_exit_code(case: Run, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, stdout, stderr = run(argv(case, tmp_path))
    assert code == case.code, stderr
    assert "Traceback" not in stderr
    if case.code == 1:
        assert (stdout + stderr).strip(), "a run that exits 1 shows what it found"
    if case.code == 2:
        assert stderr.strip(), "a run that exits 2 says why"


def test_a_command_error_is_printed_once_with_its_code(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    def failing(args: argparse.Namespace) -> int:
        raise CommandError("gain\u200b: wrong", "second line", exit_code=1)

    parser = build_parser()
    monkeypatch.setattr("genparams.cli.build_parser", lambda: parser)
    parser.set_defaults(run=failing)
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    action.choices["cmake-dir"].set_defaults(run=failing)
    assert main(["cmake-dir"]) == 1
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err == "gain\\u200b: wrong\nsecond line\n"


def test_tune_exits_0_once_interrupted(tmp_path: Path) -> None:
    token = secrets.token_urlsafe(32)  # may start with "-": one argument with its option
    command = [sys.executable, "-m", "genparams", "tune", "--port", "0", f"--token={token}"]
    server = subprocess.Popen(
        command, cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    try:
        assert server.stdout is not None
        first = server.stdout.readline()  # once serving; empty if the command ended instead
        if not first.startswith("genparams tune: serving http://127.0.0.1:"):
            server.kill()
            _, stderr = server.communicate()
            raise AssertionError(f"not serving: {first!r}, exit {server.returncode}\n{stderr}")
        server.send_signal(signal.SIGINT)
        _, stderr = server.communicate(timeout=120)
    finally:
        if server.poll() is None:
            server.kill()
            server.communicate()
    assert server.returncode == 0, stderr
    assert "Traceback" not in stderr
