"""Real nodes in a process of their own, as other programs' nodes are: both sides.

The process (a module run with ``python -m``) makes its nodes after ``rclpy.init()`` and
calls :func:`serve`, which prints "ready" and spins until the process is stopped. The test
starts it with :func:`node_process`, which returns once "ready" arrives and stops the
process when the block ends.
"""

from __future__ import annotations

import select
import subprocess
import sys
import tempfile
from collections.abc import Iterable, Iterator
from contextlib import contextmanager

from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node

from tests.patience import POLL_S, Budget
from tests.support import ROOT

READY = "ready"
# Idle-machine seconds to import rclpy, generate and declare (tests.patience.Budget).
START_BUDGET_S = 60.0
# A stopped process shuts rclpy and DDS down; on a loaded machine that takes a while.
STOP_S = 30.0
SPIN_WAIT_S = 0.25  # the longest a stopped node process waits before it sees the stop


def serve(nodes: Iterable[Node]) -> int:
    """Spin ``nodes`` (made after ``rclpy.init()``), say "ready", return once stopped."""
    executor = MultiThreadedExecutor()
    for node in nodes:
        executor.add_node(node)
    print(READY, flush=True)
    try:
        # rclpy's handler of SIGTERM shuts the context down and wakes the executor; its
        # wake-up can be lost (the process then waits in spin() for ever: 6 of 20 stops here),
        # so each wait is bounded and the context checked between them.
        while executor.context.ok():
            executor.spin_once(timeout_sec=SPIN_WAIT_S)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    return 0


@contextmanager
def node_process(module: str, *args: str) -> Iterator[subprocess.Popen[str]]:
    """``python -m MODULE ARGS...`` from its "ready" until the block ends.

    Its error output goes to a file (a pipe nobody reads would stall a node that logs), and
    is shown when it fails to start.
    """
    with tempfile.TemporaryFile("w+", encoding="utf-8") as errors:
        process = subprocess.Popen(
            [sys.executable, "-m", module, *args],
            cwd=ROOT,
            stdout=subprocess.PIPE,
            stderr=errors,
            text=True,
        )
        try:
            line = _first_line(process)
            if line.strip() != READY:
                process.kill()
                process.wait()
                errors.seek(0)
                raise RuntimeError(f"{module} did not start: {line!r}\n{errors.read()}")
            yield process
        finally:
            _stop(process)


def _first_line(process: subprocess.Popen[str]) -> str:
    """The first line the process writes, or "" when it ends or its budget runs out first."""
    assert process.stdout is not None
    budget = Budget(START_BUDGET_S)
    while not select.select([process.stdout], [], [], POLL_S)[0]:
        if process.poll() is not None or budget.spent():
            return ""
    return process.stdout.readline()


def _stop(process: subprocess.Popen[str]) -> None:
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(timeout=STOP_S)
        except subprocess.TimeoutExpired:  # stopping is not what the test checks
            process.kill()
            process.wait()
    if process.stdout is not None:
        process.stdout.close()
