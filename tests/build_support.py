"""Support for build tests: run real tools (colcon, cmake, pip, pre-commit) on copies in tmp."""

from __future__ import annotations

import os
import shlex
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path

from rclpy.parameter_client import AsyncParameterClient

from tests.support import ROOT, RosHarness, ServiceClient

EXAMPLES = ROOT / "examples"
# The venv running the tests holds genparams, colcon, ament_cmake and rclpy.
VENV_BIN = Path(sys.executable).parent


def tool_env(**extra: str) -> dict[str, str]:
    """The test environment with the venv's commands first on PATH, as in an activated venv."""
    env = dict(os.environ)
    env["PATH"] = f"{VENV_BIN}{os.pathsep}{env.get('PATH', '')}"
    env.pop("PYTHONPATH", None)
    env.update(extra)
    return env


def space_free_tools(tmp_path: Path) -> Path:
    """A folder for PATH whose `python`, `python3` and `colcon` run the venv by a path
    without spaces, for the builds that write it into a workspace.

    colcon writes the path of the interpreter that ran it into install/setup.sh and runs it
    there unquoted, so a venv in a clone whose path holds a space would break every
    workspace it builds; a user's colcon (a ROS 2 install's) has no such path.
    """
    venv = tmp_path / "venv"
    tools = tmp_path / "tools"
    if tools.is_dir():
        return tools
    venv.symlink_to(VENV_BIN.parent, target_is_directory=True)
    tools.mkdir()
    python = venv / "bin" / "python3"
    # The venv's interpreter reached through the link: it finds its pyvenv.cfg there.
    for name in ("python", "python3"):
        (tools / name).write_text(f'#!/bin/sh\nexec {shlex.quote(str(python))} "$@"\n')
        (tools / name).chmod(0o755)
    colcon = tools / "colcon"
    main = "import sys; from colcon_core.command import main; sys.exit(main())"
    colcon.write_text(f'#!/bin/sh\nexec {shlex.quote(str(python))} -c {shlex.quote(main)} "$@"\n')
    colcon.chmod(0o755)
    return tools


def run(
    command: Sequence[str | Path],
    cwd: Path,
    env: dict[str, str] | None = None,
    timeout: float = 300,
) -> subprocess.CompletedProcess[str]:
    """Run ``command``; on failure, fail with its whole output so the cause is visible."""
    completed = subprocess.run(
        [str(part) for part in command],
        cwd=cwd,
        env=env or tool_env(),
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )
    if completed.returncode != 0:
        raise AssertionError(
            f"{' '.join(map(str, command))} exited {completed.returncode} in {cwd}\n"
            f"--- stdout\n{completed.stdout}\n--- stderr\n{completed.stderr}"
        )
    return completed


def copy_example(relative: str, destination: Path) -> Path:
    """A fresh copy of ``examples/<relative>`` under ``destination``, without build leftovers."""
    target = destination / Path(relative).name
    shutil.copytree(
        EXAMPLES / relative,
        target,
        ignore=shutil.ignore_patterns("__pycache__", "build", "install", "log", "*.egg-info"),
    )
    return target


def tree_snapshot(folder: Path) -> dict[str, bytes]:
    """Every file under ``folder`` with its content: to prove a build left sources alone."""
    return {
        str(path.relative_to(folder)): path.read_bytes()
        for path in sorted(folder.rglob("*"))
        if path.is_file() and "__pycache__" not in path.parts
    }


@contextmanager
def node_process(
    workspace: Path, executable: str, *ros_args: str
) -> Iterator[subprocess.Popen[str]]:
    """Start ``executable`` after sourcing the workspace's setup.sh, as a ROS user would."""
    process = subprocess.Popen(
        ["sh", "-c", '. ./install/setup.sh && exec "$0" "$@"', executable, "--ros-args", *ros_args],
        cwd=workspace,
        env=tool_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    try:
        yield process
    finally:
        if process.poll() is None:
            process.send_signal(signal.SIGINT)
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
        if process.stdout is not None:
            process.stdout.close()


def wait_for_node(
    ros: RosHarness, process: subprocess.Popen[str], target: str, timeout: float = 30.0
) -> ServiceClient:
    """A parameter client of ``target`` once its services answer; fails early if it died."""
    probe = AsyncParameterClient(ros.client_node, target)
    deadline = time.monotonic() + timeout
    while not probe.services_are_ready():
        if process.poll() is not None:
            output = process.stdout.read() if process.stdout else ""
            raise AssertionError(f"{target} exited with {process.returncode}:\n{output}")
        if time.monotonic() > deadline:
            raise TimeoutError(f"parameter services of {target} did not appear in {timeout} s")
        ros.executor.spin_once(timeout_sec=0.1)
    return ServiceClient(ros, target)


def copy_repository(destination: Path) -> Path:
    """The repository's files as a user would get them (tracked or not ignored), in ``destination``.

    Builds of genparams itself run on this copy, so they never write into the checkout.
    """
    listed = subprocess.run(
        ["git", "ls-files", "--cached", "--others", "--exclude-standard", "-z"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    for name in filter(None, listed.split("\0")):
        source = ROOT / name
        if source.is_file():
            target = destination / name
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target)
    return destination


def build_wheel(source: Path, destination: Path, *, isolated: bool = True) -> Path:
    """Build genparams' wheel the way pip does for `pip install .` (isolated, with hatchling).

    ``isolated=False`` builds with the hatchling of the test environment (the lock's).
    """
    isolation = [] if isolated else ["--no-build-isolation"]
    pip_wheel = [sys.executable, "-m", "pip", "wheel", "--no-deps", *isolation, "--quiet"]
    run([*pip_wheel, "-w", destination, "."], source)
    (wheel,) = destination.glob("genparams-*.whl")
    return wheel
