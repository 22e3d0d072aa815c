"""Subprocess time limits that hold on a loaded machine and still catch a hang.

A fixed wall-clock timeout fails a test whose process merely waited for a CPU
(a 4 s demo took over 120 s with many jobs running). Here the budget is spent
in "idle-machine seconds": each second of wall time counts as the share of a
core a runnable process gets at the current load (cores / load average, at most
one). A hung process still runs out of budget; a slow machine gives it longer.
"""

from __future__ import annotations

import os
import signal
import subprocess
import time
from collections.abc import Sequence
from typing import Any

POLL_S = 1.0
# However loaded the machine, a process gets no more than this many times its budget.
MAX_STRETCH = 20.0
# How long a test waits for a condition another process or discovery brings about (a node
# appearing, a service answering, an event arriving). A wait ends as soon as the condition
# holds, so this costs nothing when it passes: it is only how long a real failure takes.
WAIT_S = 60.0


def cpu_share() -> float:
    """The share of one core a runnable process can expect now, in (0, 1]."""
    cores = os.cpu_count() or 1
    load = os.getloadavg()[0]
    return min(1.0, cores / load) if load > 0 else 1.0


class Budget:
    """Idle-machine seconds left of ``seconds``: :meth:`spent` says when they ran out."""

    def __init__(self, seconds: float) -> None:
        self.seconds = seconds
        self.start = self.tick = time.monotonic()
        self.used = 0.0

    def spent(self) -> bool:
        now = time.monotonic()
        self.used += (now - self.tick) * cpu_share()
        self.tick = now
        return self.used > self.seconds or self.wall() > self.seconds * MAX_STRETCH

    def wall(self) -> float:
        return time.monotonic() - self.start


def run_patiently(
    args: Sequence[str], *, budget_s: float, **popen_kwargs: Any
) -> subprocess.CompletedProcess[str]:
    """Run ``args`` to completion within ``budget_s`` idle-machine seconds, else kill it.

    The process gets a session of its own, so a kill also stops what it started.
    Raises TimeoutError (with the output so far) when the budget runs out.
    """
    process = subprocess.Popen(
        list(args),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
        **popen_kwargs,
    )
    budget = Budget(budget_s)
    try:
        while True:
            try:
                stdout, stderr = process.communicate(timeout=POLL_S)
                break
            except subprocess.TimeoutExpired:
                if budget.spent():
                    os.killpg(process.pid, signal.SIGKILL)
                    stdout, stderr = process.communicate()
                    raise TimeoutError(
                        f"{args[0]} ran out of its {budget_s:g} s budget "
                        f"({budget.wall():.0f} s wall, load {os.getloadavg()[0]:.1f});"
                        f" stderr:\n{stderr}"
                    ) from None
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    return subprocess.CompletedProcess(process.args, process.returncode, stdout, stderr)
