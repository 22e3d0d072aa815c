"""check-params against the number of keys in a params file: time per key stays flat.

Each size is a fresh ``genparams check-params`` process on the example camera
schema and a params file of N keys the schema does not own, each near one it
does (``gain123``), so every key is reported and given a "did you mean". A run
on an empty file measures start-up (imports, loading the schema), which is
subtracted before dividing by N. Times are the process's CPU time (user and
system), which a busy machine disturbs less than wall time; both are printed.

    .venv/bin/python -m bench.check_params_scale                 # 10k, 20k, 100k keys
    .venv/bin/python -m bench.check_params_scale --sizes 1000,5000 --repeats 3
"""

from __future__ import annotations

import argparse
import resource
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"


def params_text(keys: int) -> str:
    """A section for every node with ``keys`` unknown parameters (1.7 MB at 100,000)."""
    lines = ["/**:\n", "  ros__parameters:\n"]
    lines += [f"    gain{i}: {i % 10}\n" for i in range(keys)]
    return "".join(lines)


def check_params_seconds(params: Path, expected_code: int) -> tuple[float, float]:
    """CPU time and wall time of one check-params process on ``params``."""
    before = _children_cpu()
    start = time.perf_counter()
    result = subprocess.run(
        [sys.executable, "-m", "genparams", "check-params", str(SCHEMA), str(params)],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        cwd=ROOT,
        check=False,
    )
    elapsed = time.perf_counter() - start
    cpu = _children_cpu() - before
    if result.returncode != expected_code:
        raise SystemExit(
            f"check-params exited {result.returncode}, not {expected_code}:\n"
            + result.stderr.decode("utf-8", "replace")
        )
    return cpu, elapsed


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="10000,20000,100000", help="comma-separated key counts")
    parser.add_argument("--repeats", type=int, default=1, help="runs per size; the fastest counts")
    args = parser.parse_args(argv)
    sizes = [int(size) for size in args.sizes.split(",")]
    with tempfile.TemporaryDirectory(prefix="genparams bench ") as folder:
        empty = Path(folder) / "empty.yaml"
        empty.write_text("/**:\n  ros__parameters:\n    serial: ABCD1234\n", encoding="utf-8")
        startup = min(check_params_seconds(empty, 0) for _ in range(args.repeats))[0]
        print(f"check-params on {SCHEMA.name}: start-up {startup:.2f} s CPU (subtracted below)")
        print()
        print("| keys | CPU time | wall time | CPU per key | per key ÷ first row |")
        print("|---|---|---|---|---|")
        first = None
        for keys in sizes:
            params = Path(folder) / f"keys_{keys}.yaml"
            params.write_text(params_text(keys), encoding="utf-8")
            cpu, wall = min(check_params_seconds(params, 1) for _ in range(args.repeats))
            per_key = max(cpu - startup, 0.0) / keys
            first = first or per_key
            ratio = f"{per_key / first:.2f}" if first else "-"  # a first row within the noise
            print(
                f"| {keys:,} | {cpu:.2f} s | {wall:.2f} s | {per_key * 1e6:.0f} µs | {ratio} |",
                flush=True,
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
