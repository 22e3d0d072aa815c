"""``python -m bench``: run every scenario at every size and write the report.

``--quick`` (or GENPARAMS_BENCH_QUICK=1) stops at 1,000 parameters with
three repeats and writes to build/bench-quick instead of docs/, so a quick
run never replaces the published numbers.

The runtime's targets (``bench.targets``) are measured first and head the
report, each met or missed with its numbers.
"""

from __future__ import annotations

import argparse
import compileall
import datetime
import importlib.metadata
import os
import platform
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path

from bench import build_scenarios, memory_scenarios, node_scenarios, targets
from bench.measure import ROOT, Result
from bench.report import csv_text, markdown
from bench.workspace import Prepared, prepare

FULL_SIZES = (10, 100, 1_000, 10_000)
QUICK_SIZES = (10, 100, 1_000)
SCENARIOS = ("codegen", "import", "declare", "read", "set", "memory")


def parse(argv: Sequence[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="python -m bench", description=__doc__)
    parser.add_argument("--quick", action="store_true", default=_env_quick())
    parser.add_argument("--sizes", type=_sizes, help="comma-separated N, e.g. 10,100")
    parser.add_argument("--repeats", type=int, help="samples per measurement (5; quick: 3)")
    parser.add_argument("--only", type=_scenarios, help=f"comma-separated: {','.join(SCENARIOS)}")
    parser.add_argument("--output-dir", type=Path, help="where benchmarks.md and .csv go")
    parser.add_argument(
        "--targets",
        type=_targets,
        default=None,
        help="the targets' two sizes and the memory size, e.g. 100,1000,10000 (the default); "
        "'none' skips them",
    )
    parser.add_argument("--target-samples", type=int, help="in-process samples (40; quick: 20)")
    parser.add_argument("--target-processes", type=int, help="process samples (5; quick: 3)")
    args = parser.parse_args(argv)
    args.targets = (100, 1_000, 10_000) if args.targets is None else args.targets
    args.target_samples = args.target_samples or (20 if args.quick else 40)
    args.target_processes = args.target_processes or (3 if args.quick else 5)
    args.sizes = args.sizes or (QUICK_SIZES if args.quick else FULL_SIZES)
    args.repeats = args.repeats or (3 if args.quick else 5)
    args.only = args.only or SCENARIOS
    args.output_dir = args.output_dir or (
        ROOT / "build" / "bench-quick" if args.quick else ROOT / "docs"
    )
    return args


def _env_quick() -> bool:
    return os.environ.get("GENPARAMS_BENCH_QUICK", "") not in ("", "0")


def _sizes(text: str) -> tuple[int, ...]:
    return tuple(sorted(int(part) for part in text.split(",")))


def _targets(text: str) -> tuple[int, int, int] | tuple[()]:
    if text == "none":
        return ()
    sizes = tuple(int(part) for part in text.split(","))
    if len(sizes) != 3:
        raise argparse.ArgumentTypeError("three sizes: the two compared, then the memory size")
    return sizes[0], sizes[1], sizes[2]


def _scenarios(text: str) -> tuple[str, ...]:
    chosen = tuple(part.strip() for part in text.split(","))
    unknown = set(chosen) - set(SCENARIOS)
    if unknown:
        raise argparse.ArgumentTypeError(f"unknown scenarios: {', '.join(sorted(unknown))}")
    return chosen


def main(argv: Sequence[str] | None = None) -> int:
    args = parse(argv)
    # As an installed package has: otherwise every generator process would compile it first.
    for package in ("genparams", "bench"):
        compileall.compile_dir(str(ROOT / package), quiet=1)
    started = time.monotonic()
    load_before = _load_average()
    judged: list[targets.Judged] = []
    if args.targets:
        small, large, memory_size = args.targets
        judged = targets.measure(
            args.target_samples,
            args.target_processes,
            sizes=(small, large),
            memory_size=memory_size,
            report=lambda outcome: print(outcome.line(), file=sys.stderr, flush=True),
        )
    results: list[Result] = []
    session = node_scenarios.RosSession()
    try:
        with tempfile.TemporaryDirectory(prefix="genparams-bench-") as scratch:
            for size in args.sizes:
                prepared = prepare(size, Path(scratch))
                results.extend(run_size(prepared, session, args.only, args.repeats))
    finally:
        session.close()
    machine = machine_info(args, load_before, time.monotonic() - started)
    command = "make bench-quick" if args.quick else "make bench"
    args.output_dir.mkdir(parents=True, exist_ok=True)
    (args.output_dir / "benchmarks.md").write_text(
        markdown(results, machine, command, judged), encoding="utf-8"
    )
    (args.output_dir / "benchmarks.csv").write_text(csv_text(results), encoding="utf-8")
    print(f"wrote {args.output_dir / 'benchmarks.md'} and benchmarks.csv", file=sys.stderr)
    return 0


def run_size(
    prepared: Prepared, session: node_scenarios.RosSession, only: Sequence[str], repeats: int
) -> list[Result]:
    results: list[Result] = []

    def step(name: str, scenario: Callable[[], list[Result]]) -> None:
        start = time.monotonic()
        results.extend(scenario())
        print(
            f"N={prepared.schema.size:>6,} {name:<16} {time.monotonic() - start:6.1f} s",
            file=sys.stderr,
            flush=True,
        )

    if "codegen" in only:
        step("codegen", lambda: build_scenarios.codegen(prepared, repeats))
        step("codegen stages", lambda: build_scenarios.codegen_stages(prepared, repeats))
    if "import" in only:
        step("import", lambda: build_scenarios.import_time(prepared, repeats))
    if "declare" in only:
        step("declare", lambda: node_scenarios.declare(session, prepared, repeats))
    if "read" in only or "set" in only:
        declared = node_scenarios.Declared(session, prepared)
        try:
            if "read" in only:
                step("read", lambda: node_scenarios.read(declared, repeats))
            if "set" in only:
                step("set one", lambda: node_scenarios.set_one(declared, repeats))
                step(
                    "set one service",
                    lambda: node_scenarios.set_one_service(session, declared, repeats),
                )
                step("set all", lambda: node_scenarios.set_all(declared, repeats))
        finally:
            declared.destroy(session)
    if "memory" in only:
        step("memory", lambda: memory_scenarios.memory(prepared, min(repeats, 3)))
    return results


def machine_info(args: argparse.Namespace, load_before: str, elapsed: float) -> dict[str, str]:
    from rclpy.utilities import get_rmw_implementation_identifier

    return {
        "date (UTC)": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M"),
        "genparams": f"{_version('genparams')} ({_git_revision()})",
        "rclpy": _version("ros-jazzy-rclpy"),
        "RMW": get_rmw_implementation_identifier(),
        "Python": f"{platform.python_implementation()} {platform.python_version()}",
        "OS": platform.platform(),
        "CPU": f"{_cpu_model()}, {os.cpu_count()} logical cores",
        "load average (1 min) before / after": f"{load_before} / {_load_average()}",
        "sizes, repeats": f"{', '.join(f'{n:,}' for n in args.sizes)}; {args.repeats}",
        "targets: sizes; samples in process / processes": (
            f"{', '.join(f'{n:,}' for n in args.targets)}; "
            f"{args.target_samples} / {args.target_processes}"
            if args.targets
            else "not measured"
        ),
        "duration": f"{elapsed / 60:.1f} min",
    }


def _version(distribution: str) -> str:
    try:
        return importlib.metadata.version(distribution)
    except importlib.metadata.PackageNotFoundError:
        return "unknown"


def _git_revision() -> str:
    try:
        revision = subprocess.run(
            ["git", "describe", "--always", "--dirty"],
            cwd=ROOT,
            capture_output=True,
            text=True,
            check=True,
        ).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "no git"
    return f"git {revision}"


def _cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def _load_average() -> str:
    try:
        return f"{os.getloadavg()[0]:.2f}"
    except OSError:
        return "unknown"
