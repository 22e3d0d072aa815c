"""``python -m bench.targets``: the runtime's performance targets, each MET or MISSED.

Every target is a ratio against hand-written rclpy (or a plain attribute
chain) measured in this process, the two sides interleaved sample by sample,
judged on the minimum CPU time of many short samples: the least disturbed by
other work on a shared machine. The spread (minimum, median, 90th percentile)
is printed beside it. Whole processes and memory run one subprocess per
sample. ``make bench-targets`` runs it; ``make bench`` runs it too.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import threading
import time
import timeit
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rclpy.parameter import Parameter

from bench.build_scenarios import write_bytecode
from bench.measure import CPU_CLOCK, run_probe, time_process
from bench.node_scenarios import (
    GENPARAMS,
    PLAIN,
    Declared,
    Pair,
    RosSession,
    _alternating,
    _each_call,
    attribute_chain,
    interleaved,
)
from bench.workspace import Prepared, prepare

SET_LIMIT = 1.15
DECLARE_LIMIT = 1.15
MEMORY_LIMIT = 1.5
START_LIMIT = 1.05
READ_LIMIT = 1.05
SNAPSHOT_FLAT = 1.5  # snapshot() at the largest N / at the smallest


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
        return min(self.ours) / min(self.theirs)

    @property
    def met(self) -> bool:
        return self.ratio <= self.limit

    def line(self) -> str:
        verdict = "MET   " if self.met else "MISSED"
        return (
            f"{verdict} {self.target}: {self.ratio:.2f}x (limit {self.limit:g}x)  "
            f"genparams {_spread(self.ours, self.unit)} | other {_spread(self.theirs, self.unit)}"
            + (f"  [{self.note}]" if self.note else "")
        )


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
    probe = declared.schema.probe
    calls = {}
    for label, node in declared.nodes.items():
        values = _alternating(
            [Parameter(probe.name, value=probe.kind.other)],
            [Parameter(probe.name, value=probe.kind.default)],
        )
        calls[label] = _each_call(node.set_parameters, values)
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


def snapshot_never_torn(declared: Declared, seconds: float) -> tuple[bool, str]:
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
    return ok, (
        f"{len(kept):,} snapshots kept during {sets[0]:,} atomic sets of two groups: "
        f"{torn} torn, {changed} changed after being taken"
    )


def probe_both(
    prepared: Prepared, samples: int, measure: Callable[[list[str]], float]
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
            measured[label].append(measure([directory, module, class_name, "rss"]))
    return measured


def start_to_declared(prepared: Prepared, samples: int) -> Outcome:
    """Whole processes (CPU time): start Python, init rclpy, make a node, import, declare, exit."""
    timed = probe_both(
        prepared,
        samples,
        lambda args: time_process([sys.executable, "-m", "bench.memory_probe", *args])[0],
    )
    return Outcome(
        f"whole process, start to declared, N={prepared.schema.size:,}",
        timed[GENPARAMS],
        timed[PLAIN],
        "s",
        START_LIMIT,
        "CPU time",
    )


def memory(prepared: Prepared, samples: int) -> Outcome:
    grown = probe_both(
        prepared, samples, lambda args: float(run_probe("bench.memory_probe", args)["bytes"])
    )
    return Outcome(
        f"RSS growth, N={prepared.schema.size:,}",
        grown[GENPARAMS],
        grown[PLAIN],
        "B",
        MEMORY_LIMIT,
        "import and declare, from rclpy with one node",
    )


def parse(argv: Sequence[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="python -m bench.targets", description=__doc__)
    parser.add_argument("--samples", type=int, default=40, help="in-process samples per side")
    parser.add_argument("--processes", type=int, default=5, help="subprocess samples per side")
    parser.add_argument("--only", default="set,declare,read,snapshot,start,memory")
    return parser.parse_args(argv)


def main(argv: Sequence[str] | None = None) -> int:
    args = parse(argv)
    only = set(args.only.split(","))
    lines: list[str] = []

    def report(outcome: Outcome | str) -> None:
        line = outcome if isinstance(outcome, str) else outcome.line()
        lines.append(line)
        print(line, flush=True)

    session = RosSession()
    try:
        with tempfile.TemporaryDirectory(prefix="genparams-targets-") as scratch:
            prepared = {n: prepare(n, Path(scratch)) for n in (100, 1_000)}
            if only & {"set", "read", "snapshot"}:
                declared = {n: Declared(session, p) for n, p in prepared.items()}
                for n in prepared:
                    if "set" in only:
                        report(set_one(declared[n], args.samples))
                if "read" in only:
                    report(read(declared[1_000], args.samples // 4))
                if "snapshot" in only:
                    report(snapshot_flat(declared[100], declared[1_000], args.samples // 4))
                    ok, text = snapshot_never_torn(declared[100], 2.0)
                    report(f"{'MET   ' if ok else 'MISSED'} snapshot() never torn: {text}")
                for each in declared.values():
                    each.destroy(session)
            if "declare" in only:
                for p in prepared.values():
                    report(declare(session, p, max(5, args.samples // (p.schema.size // 50))))
            if "start" in only:
                for p in prepared.values():
                    report(start_to_declared(p, args.processes))
            if "memory" in only:
                report(memory(prepare(10_000, Path(scratch)), max(2, args.processes // 2)))
    finally:
        session.close()
    missed = [line for line in lines if line.startswith("MISSED")]
    print(f"\n{len(lines) - len(missed)} of {len(lines)} targets met", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
