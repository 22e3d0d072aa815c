"""Results and the two ways of timing: in this process, and whole subprocesses."""

from __future__ import annotations

import gc
import json
import os
import resource
import statistics
import subprocess
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent


@dataclass(frozen=True)
class Result:
    """Repeated measurements of one variant of one scenario at one size."""

    scenario: str
    variant: str
    size: int
    unit: str  # "s" (seconds per operation) or "B" (bytes)
    samples: tuple[float, ...]

    @property
    def min(self) -> float:
        return min(self.samples)

    @property
    def median(self) -> float:
        return statistics.median(self.samples)


# CPU time of the measuring thread: other processes on a shared machine delay a
# benchmark in wall-clock time, but barely change the CPU time it consumes.
CPU_CLOCK: Callable[[], float] = time.thread_time
WALL_CLOCK: Callable[[], float] = time.perf_counter


def time_calls(
    call: Callable[[], Any],
    repeats: int,
    number: int = 1,
    clock: Callable[[], float] = CPU_CLOCK,
    collect: bool = True,
) -> tuple[float, ...]:
    """Seconds per call: ``repeats`` samples, each the mean of ``number`` calls.

    With ``collect``, garbage from earlier samples is collected first; the
    cyclic collector stays on while timing, as it is in a real node.
    """
    samples = []
    for _ in range(repeats):
        if collect:
            gc.collect()
        start = clock()
        for _ in range(number):
            call()
        samples.append((clock() - start) / number)
    return tuple(samples)


def child_environment(**extra: str) -> dict[str, str]:
    """The environment of a benchmark subprocess: this one, with the repository importable."""
    env = dict(os.environ)
    paths = [str(ROOT), *filter(None, env.get("PYTHONPATH", "").split(os.pathsep))]
    env["PYTHONPATH"] = os.pathsep.join(paths)
    env.update(extra)
    return env


def time_process(
    arguments: Sequence[str], env: dict[str, str] | None = None
) -> tuple[float, float]:
    """Seconds of a whole process, from spawn to exit: (CPU time, wall-clock). It must succeed.

    CPU time (user + system) is what the process costs whatever else runs on
    the machine; wall-clock is what a user waits, and grows with that load.
    """
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    completed = subprocess.run(
        arguments, env=env or child_environment(), capture_output=True, text=True, check=False
    )
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if completed.returncode != 0:
        raise RuntimeError(
            f"{' '.join(arguments)} exited with {completed.returncode}:\n{completed.stderr}"
        )
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall


def run_probe(module: str, arguments: Sequence[str], env: dict[str, str] | None = None) -> Any:
    """Run ``python -m module arguments`` and return the JSON it prints on its last line."""
    completed = subprocess.run(
        [sys.executable, "-m", module, *arguments],
        env=env or child_environment(),
        capture_output=True,
        text=True,
        check=False,
    )
    if completed.returncode != 0:
        raise RuntimeError(f"{module} {' '.join(arguments)} failed:\n{completed.stderr}")
    return json.loads(completed.stdout.strip().splitlines()[-1])
