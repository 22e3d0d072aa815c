"""Where the time of a declare and of one set goes, genparams next to plain rclpy.

Runs the benchmark schemas on real nodes in one process and prints, per size,
the CPU time per call of both sides and, for genparams, the share of each step
(measured with cProfile, whose own overhead inflates every share alike):

    make bench-profile            # sizes 100 and 1,000
    .venv/bin/python -m bench.profile --sizes 10,100,1000,10000
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from rclpy.parameter import Parameter

from bench.measure import time_calls
from bench.node_scenarios import Pair, RosSession
from bench.workspace import Prepared, prepare

# Functions whose cumulative time makes up one step, by (file suffix, function name).
SET_STEPS: dict[str, tuple[tuple[str, str], ...]] = {
    "genparams: serializing lock and set frames": (("consistency.py", "set_serialized"),),
    "genparams: pre-set rewrites (empty arrays)": (("rewrites.py", "pre_set"),),
    "genparams: on-set validation (types, validators, rules)": (("consistency.py", "check"),),
    "genparams: commit to cfg (before post-set callbacks)": (
        ("consistency.py", "commit_then_post_set"),
    ),
    "rclpy: range and type checks (_apply_descriptors)": (("node.py", "_apply_descriptors"),),
    "rclpy: parameter event publish": (("publisher.py", "publish"),),
    "rclpy: whole set_parameters": (("node.py", "set_parameters"),),
}
DECLARE_STEPS: dict[str, tuple[tuple[str, str], ...]] = {
    "genparams: compile the class spec (first declare only)": (("spec.py", "compile_schema"),),
    "genparams: read and check overrides, resolve values": (("entries.py", "resolve_all"),),
    "genparams: build descriptors and rclpy Parameters": (
        ("binding.py", "<listcomp>"),
        ("declaring.py", "descriptor_for"),
    ),
    "genparams: build the typed tree": (("tree.py", "build_tree"),),
    # plain rclpy declares through _declare_parameter_common, one round per parameter;
    # genparams through the same set path, one round per DECLARE_ROUND parameters.
    "rclpy: declare rounds (_set_parameters_atomically_common)": (
        ("node.py", "_set_parameters_atomically_common"),
    ),
    "rclpy: parameter event publish": (("publisher.py", "publish"),),
    "genparams: whole declare": (("binding.py", "declare"),),
}


def parse(argv: Sequence[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="100,1000", help="comma-separated sizes")
    parser.add_argument("--sets", type=int, default=2000, help="sets timed per side")
    return parser.parse_args(argv)


def main(argv: Sequence[str] | None = None) -> int:
    args = parse(argv)
    session = RosSession()
    try:
        with tempfile.TemporaryDirectory() as folder:
            for size in (int(s) for s in args.sizes.split(",")):
                prepared = prepare(size, Path(folder))
                print(f"\n## N = {size:,}\n")
                profile_declare(session, prepared)
                profile_set(session, prepared, args.sets)
    finally:
        session.close()
    return 0


def profile_declare(session: RosSession, prepared: Prepared) -> None:
    timings: dict[str, list[float]] = {"genparams": [], "plain rclpy": []}
    for _ in range(5):
        pair = Pair(prepared)
        sides = (("genparams", pair.params_cls.declare), ("plain rclpy", pair.plain.declare))
        for label, declare_on in sides:
            node = session.node()
            timings[label].extend(time_calls(lambda: declare_on(node), 1))  # noqa: B023
            session.destroy(node)
    _print_ratio("declare", timings)
    pair = Pair(prepared)
    node = session.node()
    stats = _profiled(lambda: pair.params_cls.declare(node))
    session.destroy(node)
    _print_steps(stats, DECLARE_STEPS, calls=1)


def profile_set(session: RosSession, prepared: Prepared, sets: int) -> None:
    pair = Pair(prepared)
    probe = prepared.schema.probe
    values = [
        [Parameter(probe.name, value=probe.kind.other)],
        [Parameter(probe.name, value=probe.kind.default)],
    ]
    nodes = {"genparams": session.node(), "plain rclpy": session.node()}
    pair.params_cls.declare(nodes["genparams"])
    pair.plain.declare(nodes["plain rclpy"])

    def setter(label: str) -> Callable[[], None]:
        node = nodes[label]
        state = {"i": 0}

        def call() -> None:
            state["i"] += 1
            (result,) = node.set_parameters(values[state["i"] % 2])
            if not result.successful:
                raise RuntimeError(result.reason)

        return call

    timings = {
        label: [min(time_calls(setter(label), 1, 50)) for _ in range(sets // 50)] for label in nodes
    }
    _print_ratio("one set (node.set_parameters)", timings)
    call = setter("genparams")
    stats = _profiled(lambda: [call() for _ in range(sets)])
    _print_steps(stats, SET_STEPS, calls=sets)
    for node in nodes.values():
        session.destroy(node)


def _profiled(work: Callable[[], Any]) -> pstats.Stats:
    profiler = cProfile.Profile()
    profiler.enable()
    work()
    profiler.disable()
    return pstats.Stats(profiler)


def _print_ratio(what: str, timings: dict[str, list[float]]) -> None:
    ours, plain = min(timings["genparams"]), min(timings["plain rclpy"])
    print(
        f"{what}: genparams {ours * 1e6:,.1f} µs, plain rclpy {plain * 1e6:,.1f} µs, "
        f"ratio {ours / plain:.2f} (minimum CPU time per call)"
    )


def _print_steps(
    stats: pstats.Stats, steps: dict[str, tuple[tuple[str, str], ...]], calls: int
) -> None:
    table: dict[tuple[str, int, str], Any] = stats.stats  # type: ignore[attr-defined]
    whole_label = next(reversed(steps))
    cumulative = {
        label: sum(
            entry[3]
            for (file, _line, function), entry in table.items()
            for suffix, name in wanted
            if file.endswith(suffix) and function == name
        )
        for label, wanted in steps.items()
    }
    whole = cumulative[whole_label] or 1.0
    per_call = cumulative[whole_label] / calls * 1e6
    print(f"  under cProfile, per call ({whole_label}: {per_call:,.1f} µs):")
    for label, seconds in cumulative.items():
        if label != whole_label:
            print(f"  - {label}: {seconds / calls * 1e6:,.1f} µs ({seconds / whole:.0%})")


if __name__ == "__main__":
    raise SystemExit(main())
