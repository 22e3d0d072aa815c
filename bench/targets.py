"""``python -m bench.targets``: the runtime's performance targets, each MET or MISSED.

Every target is a ratio against hand-written rclpy (or a plain attribute
chain) measured in this process, the two sides interleaved sample by sample,
judged on the minimum CPU time of many short samples: the least disturbed by
other work on a shared machine. The spread (minimum, median, 90th percentile)
is printed beside it. Whole processes and memory run one subprocess per
sample. ``make bench-targets`` prints them; ``make bench`` also writes them
into docs/benchmarks.md (``measure`` below, called by ``python -m bench``).

| target | limit |
|---|---|
| one in-process ``node.set_parameters``, N = 100 and 1,000 | 1.15x |
| declare on a fresh node, the class declared before (steady state) | 0.9x |
| RSS growth at 10,000 parameters (import and declare) | 2.0x |
| the same, declared with ``publish_schema=False`` | 1.5x |
| whole process, start to declared, N = 100 and 1,000 (CPU time) | 1.05x |
| a read against a plain attribute chain | 1.05x |
| ``snapshot()`` O(1) (N = 1,000 against N = 100) and never torn | 1.5x; 0 torn |
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import tempfile
import threading
import time
import timeit
from collections.abc import Callable, Collection, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rclpy.parameter import Parameter

from bench.build_scenarios import write_bytecode
from bench.measure import CPU_CLOCK, child_environment, run_probe, time_process
from bench.node_scenarios import (
    GENPARAMS,
    PLAIN,
    Declared,
    Pair,
    RosSession,
    attribute_chain,
    interleaved,
    set_calls,
)
from bench.workspace import Prepared, prepare

SET_LIMIT = 1.15
DECLARE_LIMIT = 0.9
MEMORY_LIMIT = 2.0  # with the schema topic (its message is built when a subscriber asks)
BARE_MEMORY_LIMIT = 1.5  # publish_schema=False
START_LIMIT = 1.05
READ_LIMIT = 1.05
SNAPSHOT_FLAT = 1.5  # snapshot() at the largest N / at the smallest
ONLY = ("set", "declare", "read", "snapshot", "start", "memory")


@dataclass(frozen=True)
class Outcome:
    target: str
    ours: Sequence[float]
    theirs: Sequence[float]
    unit: str
    limit: float
    note: str = ""

    @property
    def ratio(self) -> float:
        ours, theirs = min(self.ours), min(self.theirs)
        if theirs <= 0:  # RSS at small N can grow by no page at all
            return 1.0 if ours <= 0 else math.inf
        return ours / theirs

    @property
    def met(self) -> bool:
        return self.ratio <= self.limit

    @property
    def limit_text(self) -> str:
        return f"≤ {self.limit:g}x"

    @property
    def measured(self) -> str:
        return (
            f"{self.ratio:.2f}x; genparams {_spread(self.ours, self.unit)} | "
            f"other {_spread(self.theirs, self.unit)}" + (f" [{self.note}]" if self.note else "")
        )

    def line(self) -> str:
        verdict = "MET   " if self.met else "MISSED"
        return (
            f"{verdict} {self.target}: {self.ratio:.2f}x (limit {self.limit:g}x)  "
            f"genparams {_spread(self.ours, self.unit)} | other {_spread(self.theirs, self.unit)}"
            + (f"  [{self.note}]" if self.note else "")
        )


@dataclass(frozen=True)
class Verdict:
    """A target judged by a count rather than a ratio (snapshots never torn)."""

    target: str
    limit_text: str
    measured: str
    met: bool

    def line(self) -> str:
        return f"{'MET   ' if self.met else 'MISSED'} {self.target}: {self.measured}"


Judged = Outcome | Verdict


def _spread(samples: Sequence[float], unit: str) -> str:
    ordered = sorted(samples)
    p90 = ordered[min(len(ordered) - 1, int(len(ordered) * 0.9))]
    values = (ordered[0], statistics.median(ordered), p90)
    return "min/med/p90 " + "/".join(_format(v, unit) for v in values) + f" (n={len(ordered)})"


def _format(value: float, unit: str) -> str:
    if unit == "B":
        return f"{value / 2**20:.2f}MiB"
    for scale, name in ((1.0, "s"), (1e-3, "ms"), (1e-6, "µs")):
        if value >= scale:
            return f"{value / scale:.3g}{name}"
    return f"{value / 1e-9:.3g}ns"


def set_one(declared: Declared, samples: int) -> Outcome:
    calls = set_calls(declared)
    timed = interleaved(calls, samples, 20)
    return Outcome(
        f"one node.set_parameters, N={declared.schema.size:,}",
        timed[GENPARAMS],
        timed[PLAIN],
        "s",
        SET_LIMIT,
    )


def declare(session: RosSession, prepared: Prepared, samples: int) -> Outcome:
    """A fresh node each sample; the class was declared once before (its spec compiled)."""
    pair = Pair(prepared)
    warm = session.node()
    pair.params_cls.declare(warm)
    session.destroy(warm)
    sides: dict[str, Callable[[Any], Any]] = {
        GENPARAMS: pair.params_cls.declare,
        PLAIN: pair.plain.declare,
    }
    timed: dict[str, list[float]] = {GENPARAMS: [], PLAIN: []}
    for round_ in range(samples):
        order = list(sides) if round_ % 2 == 0 else list(sides)[::-1]
        for label in order:
            node = session.node()
            start = CPU_CLOCK()
            sides[label](node)
            timed[label].append(CPU_CLOCK() - start)
            session.destroy(node)
    return Outcome(
        f"declare on a fresh node, N={prepared.schema.size:,}",
        timed[GENPARAMS],
        timed[PLAIN],
        "s",
        DECLARE_LIMIT,
    )


def read(declared: Declared, samples: int, number: int = 100_000) -> Outcome:
    path = declared.schema.probe.name
    namespace = {"cfg": declared.cfg, "plain": attribute_chain(declared.schema.values())}
    timers = {
        GENPARAMS: timeit.Timer(f"cfg.{path}", timer=CPU_CLOCK, globals=namespace),
        PLAIN: timeit.Timer(f"plain.{path}", timer=CPU_CLOCK, globals=namespace),
    }
    timed: dict[str, list[float]] = {GENPARAMS: [], PLAIN: []}
    for _ in range(samples):
        for label, timer in timers.items():
            timed[label].append(timer.timeit(number) / number)
    return Outcome(
        f"read cfg.{path} vs a plain attribute chain, N={declared.schema.size:,}",
        timed[GENPARAMS],
        timed[PLAIN],
        "s",
        READ_LIMIT,
        "both include timeit's loop",
    )


def snapshot_flat(small: Declared, large: Declared, samples: int) -> Outcome:
    timers = [
        timeit.Timer("cfg.snapshot()", timer=CPU_CLOCK, globals={"cfg": d.cfg})
        for d in (large, small)
    ]
    timed: list[list[float]] = [[], []]
    for _ in range(samples):
        for index, timer in enumerate(timers):
            timed[index].append(timer.timeit(100_000) / 100_000)
    return Outcome(
        f"snapshot() O(1): N={large.schema.size:,} vs N={small.schema.size:,}",
        timed[0],
        timed[1],
        "s",
        SNAPSHOT_FLAT,
    )


def snapshot_never_torn(declared: Declared, seconds: float) -> Verdict:
    """One thread sets two parameters in different groups together, atomically; another
    takes snapshots. Each must show the two equal, and still show what it showed at first."""
    schema = declared.schema
    first, second = [p for p in schema.parameters if p.kind.name == "speed"][:2]
    node, cfg = declared.genparams_node, declared.cfg
    stop = threading.Event()
    sets = [0]

    def writer() -> None:
        while not stop.is_set():
            for value in (first.kind.other, first.kind.default):
                node.set_parameters_atomically(
                    [Parameter(first.name, value=value), Parameter(second.name, value=value)]
                )
                sets[0] += 1

    def pair(snapshot: Any) -> tuple[Any, Any]:
        return eval(f"s.{first.name}", {"s": snapshot}), eval(f"s.{second.name}", {"s": snapshot})

    thread = threading.Thread(target=writer)
    thread.start()
    torn = changed = 0
    kept: list[tuple[Any, tuple[Any, Any]]] = []
    deadline = time.monotonic() + seconds
    try:
        while time.monotonic() < deadline:
            snapshot = cfg.snapshot()
            values = pair(snapshot)
            torn += values[0] != values[1]
            if len(kept) < 10_000:
                kept.append((snapshot, values))
    finally:
        stop.set()
        thread.join()
    changed = sum(pair(snapshot) != values for snapshot, values in kept)
    ok = torn == 0 and changed == 0 and sets[0] > 0
    return Verdict(
        "snapshot() never torn",
        "0 torn, 0 changed",
        f"{len(kept):,} snapshots kept during {sets[0]:,} atomic sets of two groups: "
        f"{torn} torn, {changed} changed after being taken",
        ok,
    )


def probe_both(
    prepared: Prepared, samples: int, measure: Callable[[list[str]], float], mode: str = "rss"
) -> dict[str, list[float]]:
    """``measure`` of bench.memory_probe's arguments for each side, ``samples`` times, the
    sides in turn (which goes first alternates, so neither gains from the other's caches)."""
    schema = prepared.schema
    directory = str(prepared.module_path.parent)
    write_bytecode(prepared.module_path.parent, schema.module_name, schema.plain_module_name)
    sides = {
        GENPARAMS: (schema.module_name, schema.class_name),
        PLAIN: (schema.plain_module_name, "-"),
    }
    measured: dict[str, list[float]] = {GENPARAMS: [], PLAIN: []}
    for round_ in range(samples):
        order = list(sides) if round_ % 2 == 0 else list(sides)[::-1]
        for label in order:
            module, class_name = sides[label]
            measured[label].append(measure([directory, module, class_name, mode]))
    return measured


def start_to_declared(prepared: Prepared, samples: int) -> Outcome:
    """Whole processes (CPU time): start Python, init rclpy, make a node, import, declare, exit.

    Every module comes from its compiled bytecode, as from an installed package:
    the processes share a bytecode cache in a scratch folder (the source tree is
    not written), filled by one untimed process per side. Without it, a
    checkout run with ``PYTHONDONTWRITEBYTECODE`` would compile genparams (and any
    dependency installed without bytecode) from source in every sample.
    """
    with tempfile.TemporaryDirectory(prefix="genparams-bytecode-") as cache:
        env = child_environment(PYTHONPYCACHEPREFIX=cache)
        env.pop("PYTHONDONTWRITEBYTECODE", None)

        def run(args: list[str]) -> float:
            return time_process([sys.executable, "-m", "bench.memory_probe", *args], env)[0]

        probe_both(prepared, 1, run)  # untimed: writes the bytecode of both sides
        timed = probe_both(prepared, samples, run)
    return Outcome(
        f"whole process, start to declared, N={prepared.schema.size:,}",
        timed[GENPARAMS],
        timed[PLAIN],
        "s",
        START_LIMIT,
        "CPU time",
    )


def memory(prepared: Prepared, samples: int, bare: bool = False) -> Outcome:
    grown = probe_both(
        prepared,
        samples,
        lambda args: float(run_probe("bench.memory_probe", args)["bytes"]),
        "rss-bare" if bare else "rss",
    )
    return Outcome(
        f"RSS growth, N={prepared.schema.size:,}" + (", publish_schema=False" if bare else ""),
        grown[GENPARAMS],
        grown[PLAIN],
        "B",
        BARE_MEMORY_LIMIT if bare else MEMORY_LIMIT,
        "import and declare, from rclpy with one node"
        + ("" if bare else "; the schema topic on, no subscriber asked for its message"),
    )


def measure(
    samples: int = 40,
    processes: int = 5,
    only: Collection[str] = ONLY,
    sizes: tuple[int, int] = (100, 1_000),
    memory_size: int = 10_000,
    report: Callable[[Judged], None] = lambda judged: None,
) -> list[Judged]:
    """Every target in ``only``, at the two ``sizes`` (and RSS at ``memory_size``)."""
    judged: list[Judged] = []

    def add(outcome: Judged) -> None:
        judged.append(outcome)
        report(outcome)

    small, large = sizes
    session = RosSession()
    try:
        with tempfile.TemporaryDirectory(prefix="genparams-targets-") as scratch:
            prepared = {n: prepare(n, Path(scratch)) for n in sizes}
            if set(only) & {"set", "read", "snapshot"}:
                declared = {n: Declared(session, p) for n, p in prepared.items()}
                if "set" in only:
                    for n in sizes:
                        add(set_one(declared[n], samples))
                if "read" in only:
                    add(read(declared[large], max(2, samples // 4)))
                if "snapshot" in only:
                    add(snapshot_flat(declared[small], declared[large], max(2, samples // 4)))
                    add(snapshot_never_torn(declared[small], 2.0))
                for each in declared.values():
                    each.destroy(session)
            if "declare" in only:
                for p in prepared.values():
                    add(declare(session, p, max(5, samples // max(1, p.schema.size // 50))))
            if "start" in only:
                for p in prepared.values():
                    add(start_to_declared(p, processes))
            if "memory" in only:
                largest = prepare(memory_size, Path(scratch))
                add(memory(largest, max(2, processes // 2)))
                add(memory(largest, max(2, processes // 2), bare=True))
    finally:
        session.close()
    return judged


def parse(argv: Sequence[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="python -m bench.targets", description=__doc__)
    parser.add_argument("--samples", type=int, default=40, help="in-process samples per side")
    parser.add_argument("--processes", type=int, default=5, help="subprocess samples per side")
    parser.add_argument("--only", default=",".join(ONLY))
    return parser.parse_args(argv)


def main(argv: Sequence[str] | None = None) -> int:
    args = parse(argv)
    judged = measure(
        args.samples,
        args.processes,
        args.only.split(","),
        report=lambda outcome: print(outcome.line(), flush=True),
    )
    met = sum(outcome.met for outcome in judged)
    print(f"\n{met} of {len(judged)} targets met", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
