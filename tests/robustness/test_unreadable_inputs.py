"""Every command reads its files through one bounded reader: a clear error naming the file.

A FIFO fed without end reports a size of 0 to ``stat()``; it must be refused
after the size limit is read, in bounded memory, with exit 2 (docs/cli.md: bad
input). A FIFO nobody writes to is refused after a wait, never blocks for ever;
devices such as ``/dev/zero`` are refused at once. Missing files, folders and
files that are not UTF-8 name the file too, whichever command reads them.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest

from genparams.schema import input_file
from genparams.schema.errors import SchemaError
from genparams.schema.input_file import read_input_file
from genparams.schema.loader import MAX_BYTES
from tests.golden import ROOT, run_cli
from tests.patience import run_patiently

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"
GOOD_PARAMS = "/**:\n  ros__parameters:\n    serial: ABCD1234\n"

# What each command reads, as (command line with FILE where the input goes, what it calls it).
COMMANDS = {
    "validate": (["validate", "FILE"], "schema"),
    "import-rclpy": (["import-rclpy", "FILE"], "rclpy source"),
    "generate": (["generate", "FILE"], "schema"),
    "import-gpl": (["import-gpl", "FILE"], "generate_parameter_library file"),
    "check-params": (["check-params", str(SCHEMA), "FILE"], "params file"),
    "check-params schema": (["check-params", "FILE", "GOOD"], "schema"),
    "explain --params-file": (
        ["explain", "/camera", "--schema", str(SCHEMA), "--params-file", "FILE"],
        "params file",
    ),
    "explain --manifest": (["explain", "/camera", "--manifest", "FILE"], "manifest"),
    "check-deployment --manifest": (["check-deployment", "GOOD", "--manifest", "FILE"], "manifest"),
    "audit --params-file": (["audit", "/camera", "--params-file", "FILE"], "params file"),
    "check-deployment params": (
        ["check-deployment", "FILE", "--map", f"/camera={SCHEMA}"],
        "params file",
    ),
}


def command_line(name: str, file: Path | str, good: Path) -> list[str]:
    argv, _ = COMMANDS[name]
    return [{"FILE": str(file), "GOOD": str(good)}.get(arg, arg) for arg in argv]


@pytest.fixture
def good(tmp_path: Path) -> Path:
    params = tmp_path / "good params.yaml"
    params.write_text(GOOD_PARAMS, encoding="utf-8")
    return params


def unreadable(folder: Path) -> Iterator[tuple[str, Path, str]]:
    """(case, file, what the error says after the file's name and what it is)."""
    missing = folder / "missing.yaml"
    yield "missing", missing, ":1:1: cannot read "
    directory = folder / "a folder.yaml"
    directory.mkdir()
    yield "folder", directory, ":1:1: cannot read "
    latin1 = folder / "latin1.yaml"
    latin1.write_bytes(b"genparams: 1\nname: caf\xe9\n")
    yield "not UTF-8", latin1, ":2:10: cannot read "
    big = folder / "big.yaml"
    big.write_bytes(b"#" * (MAX_BYTES + 1))
    yield "over the limit", big, ":1:1: cannot read "


@pytest.mark.parametrize("command", COMMANDS)
def test_each_command_names_a_file_it_cannot_read(command: str, tmp_path: Path, good: Path) -> None:
    _, what = COMMANDS[command]
    for case, file, says in unreadable(tmp_path):
        code, stderr = run_cli(*command_line(command, file, good))
        assert code == 2, (case, stderr)
        assert stderr.startswith(f"{file}{says}{what}: "), (case, stderr)
        assert len(stderr.splitlines()) == 1, (case, stderr)


def test_the_reader_says_why(tmp_path: Path) -> None:
    cases = {name: (file, says) for name, file, says in unreadable(tmp_path)}
    messages = {}
    for name, (file, _) in cases.items():
        with pytest.raises(Exception) as caught:
            read_input_file(file, "params file")
        messages[name] = str(caught.value)
    assert messages["over the limit"].endswith(f"file is larger than {MAX_BYTES} bytes")
    assert messages["not UTF-8"].endswith("not UTF-8 text (byte 0xe9 at offset 22)")
    assert all(str(cases[name][0]) in message for name, message in messages.items())


def test_an_undecodable_manifest_is_named(tmp_path: Path) -> None:
    manifest = tmp_path / "deploy.yaml"
    manifest.write_bytes(b"genparams_deployment: 1\nnodes:\n  /cam\xff: {}\n")
    code, stderr = run_cli("explain", "/cam", "--manifest", str(manifest))
    assert (code, stderr) == (
        2,
        f"{manifest}:3:7: cannot read manifest: not UTF-8 text (byte 0xff at offset 37)\n",
    )


def test_a_file_of_exactly_the_limit_is_read(tmp_path: Path) -> None:
    file = tmp_path / "full.yaml"
    file.write_bytes(b"a: 1\n" + b"#" * (MAX_BYTES - 5))
    assert len(read_input_file(file, "params file")) == MAX_BYTES


def test_line_ends_are_read_as_text_files_read_them(tmp_path: Path) -> None:
    file = tmp_path / "crlf.yaml"
    file.write_bytes(b"a: 1\r\nb: 2\rc: 3\n")
    assert read_input_file(file, "params file") == "a: 1\nb: 2\nc: 3\n"


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads a file whatever its mode")
def test_a_file_without_read_permission_is_named(tmp_path: Path, good: Path) -> None:
    file = tmp_path / "secret.yaml"
    file.write_text(GOOD_PARAMS, encoding="utf-8")
    file.chmod(0)
    code, stderr = run_cli(*command_line("check-params", file, good))
    assert code == 2 and stderr.startswith(f"{file}:1:1: cannot read params file: ")


def test_a_fifo_holding_a_params_file_is_read(tmp_path: Path) -> None:
    """As ``check-params schema.yaml <(generate-params)`` gives it: a pipe, no size."""
    fifo = tmp_path / "params.fifo"
    os.mkfifo(fifo)
    writer = threading.Thread(target=fifo.write_text, args=(GOOD_PARAMS, "utf-8"), daemon=True)
    writer.start()
    assert run_cli("check-params", str(SCHEMA), str(fifo)) == (0, "")
    writer.join(timeout=10)


@pytest.mark.parametrize("command", COMMANDS)
def test_a_fifo_nobody_writes_to_is_refused_after_a_wait(
    command: str, tmp_path: Path, good: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Opening a FIFO blocks until a writer comes: the reader opens it without blocking."""
    monkeypatch.setattr(input_file, "PIPE_TIMEOUT_S", 0.2)
    fifo = tmp_path / "nobody writes.fifo"
    os.mkfifo(fifo)
    code, stderr = run_cli(*command_line(command, fifo, good))
    assert (code, stderr) == (
        2,
        f"{fifo}:1:1: cannot read {COMMANDS[command][1]}: "
        "the pipe was not written whole within 0.2 s\n",
    )


def test_a_fifo_whose_writer_stalls_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(input_file, "PIPE_TIMEOUT_S", 0.5)
    fifo = tmp_path / "stalled.fifo"
    os.mkfifo(fifo)
    writer_ready = threading.Event()
    release = threading.Event()

    def stall() -> None:
        with open(fifo, "wb", buffering=0) as pipe:  # opens once the reader has
            pipe.write(b"genparams: 1\n")
            writer_ready.set()
            release.wait(timeout=60)

    threading.Thread(target=stall, daemon=True).start()
    try:
        with pytest.raises(SchemaError, match=r"the pipe was not written whole within 0\.5 s"):
            read_input_file(fifo, "schema")
    finally:
        release.set()
    assert writer_ready.is_set()


@pytest.mark.skipif(not Path("/dev/null").exists(), reason="needs /dev/null")
def test_a_device_is_refused_at_once() -> None:
    with pytest.raises(SchemaError) as caught:
        read_input_file("/dev/null", "params file")
    assert str(caught.value) == (
        "/dev/null:1:1: cannot read params file: a character device, not a file or a pipe"
    )


# Run in a fresh interpreter: the peak (VmHWM) is the child's own, and an address-space
# limit keeps a reader that does not stop from taking the machine's memory with it.
ENDLESS = """
import contextlib, io, json, resource, sys, threading
resource.setrlimit(resource.RLIMIT_AS, (1 << 30, 1 << 30))
from genparams.cli import main

def feed(path):
    try:
        with open(path, "wb") as pipe:
            while True:
                pipe.write(b"a: 1\\n" * 8192)
    except OSError:
        pass

results = []
for name, argv, fifo in json.loads(sys.argv[1]):
    if fifo:
        threading.Thread(target=feed, args=(fifo,), daemon=True).start()
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        try:
            code = main(argv)
        except MemoryError:
            code = "MemoryError"
    results.append({"name": name, "code": code, "stderr": err.getvalue()})
with open("/proc/self/status", encoding="ascii") as status:
    peak_kb = next(int(line.split()[1]) for line in status if line.startswith("VmHWM:"))
print(json.dumps({"results": results, "peak_mb": peak_kb / 1024}))
"""


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="needs /dev/zero")
def test_endless_inputs_are_refused_in_bounded_memory(tmp_path: Path, good: Path) -> None:
    cases: list[tuple[str, list[str], str | None]] = []
    for command in COMMANDS:
        cases.append((f"{command} /dev/zero", command_line(command, "/dev/zero", good), None))
        fifo_path = tmp_path / f"{command.replace(' ', '_')}.fifo"
        os.mkfifo(fifo_path)
        cases.append((f"{command} FIFO", command_line(command, fifo_path, good), str(fifo_path)))
    result = run_patiently(
        [sys.executable, "-c", ENDLESS, json.dumps(cases)], budget_s=120, cwd=tmp_path
    )
    assert result.returncode == 0, result.stderr
    outcome = json.loads(result.stdout)
    for (name, _argv, fifo), got in zip(cases, outcome["results"], strict=True):
        what = COMMANDS[name.rsplit(" ", 1)[0]][1]
        why = (
            f"file is larger than {MAX_BYTES} bytes"
            if fifo
            else "a character device, not a file or a pipe"
        )
        assert got["code"] == 2, got
        assert got["stderr"] == f"{fifo or '/dev/zero'}:1:1: cannot read {what}: {why}\n", got
    assert outcome["peak_mb"] < 150, outcome["peak_mb"]


def test_the_child_measures_its_own_peak(tmp_path: Path) -> None:
    """The bound above can fail: a child that holds 300 MB reports it."""
    script = ENDLESS.replace("results = []", "ballast = b'x' * (300 << 20)\nresults = []")
    result = subprocess.run(
        [sys.executable, "-c", script, "[]"], capture_output=True, text=True, timeout=120
    )
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["peak_mb"] > 300
