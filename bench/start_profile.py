"""Where a whole process's time goes, from rclpy's node to the class declared, step by step.

Each sample is a fresh process (CPU time of its main thread per step; every
module from compiled bytecode, as ``bench.targets`` runs them), the two sides
alternating; the minimum over the samples is printed:

    .venv/bin/python -m bench.start_profile --sizes 100,1000 --samples 5
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from bench.measure import child_environment, run_probe
from bench.workspace import prepare

PLAIN = "plain"
GENPARAMS = "genparams"


def steps(directory: str, size: int, side: str) -> dict[str, float]:
    """In the child: time each step of making a node and declaring ``size`` parameters."""
    spent: dict[str, float] = {}

    def step(name: str, call: Callable[[], Any]) -> Any:
        start = time.thread_time()
        result = call()
        spent[name] = time.thread_time() - start
        return result

    def start_rclpy() -> Any:
        import rclpy
        from rclpy.context import Context
        from rclpy.node import Node

        context = Context()
        rclpy.init(context=context)
        return Node("start_profile", context=context)

    node = step("import rclpy, init, make a node", start_rclpy)
    sys.path.insert(0, directory)
    if side == PLAIN:
        module = step("import the module", lambda: importlib.import_module(f"bench_{size}_plain"))
        step("declare", lambda: module.declare(node))
        return spent
    step("import genparams.runtime", lambda: importlib.import_module("genparams.runtime"))
    module = step("import the module", lambda: importlib.import_module(f"bench_{size}_params"))
    step(
        "import the node layer (first declare)",
        lambda: importlib.import_module("genparams.runtime.node.binding"),
    )
    from genparams.runtime.core.spec import compile_schema

    # The schema message is built when a subscriber first asks: not on the way to declared.
    params = getattr(module, f"Bench{size}Params")
    step("compile the class spec (first declare)", lambda: compile_schema(params._SPEC))
    step("declare (the rest)", lambda: params.declare(node))
    return spent


def profile(sizes: Sequence[int], samples: int) -> None:
    with tempfile.TemporaryDirectory(prefix="genparams-start-") as scratch:
        env = child_environment(PYTHONPYCACHEPREFIX=str(Path(scratch, "bytecode")))
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        for size in sizes:
            directory = str(prepare(size, Path(scratch)).module_path.parent)
            best: dict[str, dict[str, float]] = {PLAIN: {}, GENPARAMS: {}}
            for round_ in range(samples + 1):  # the first round writes the bytecode, untimed
                for side in (PLAIN, GENPARAMS) if round_ % 2 else (GENPARAMS, PLAIN):
                    args = ["--child", directory, str(size), side]
                    spent: dict[str, float] = run_probe("bench.start_profile", args, env)
                    for name, seconds in spent.items():
                        if round_:
                            best[side][name] = min(seconds, best[side].get(name, seconds))
            print(f"N={size:,}: minimum of {samples} processes a side, CPU ms")
            for side, measured in best.items():
                for name, seconds in measured.items():
                    print(f"  {side:<10} {name:<48} {seconds * 1e3:8.1f}")
                total = sum(measured.values()) - measured["import rclpy, init, make a node"]
                print(f"  {side:<10} {'total after the node':<48} {total * 1e3:8.1f}")


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m bench.start_profile", description=__doc__)
    parser.add_argument("--sizes", default="100,1000")
    parser.add_argument("--samples", type=int, default=5)
    parser.add_argument("--child", nargs=3, metavar=("DIR", "SIZE", "SIDE"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child:
        directory, size, side = args.child
        print(json.dumps(steps(directory, int(size), side)))
        return 0
    profile([int(size) for size in args.sizes.split(",")], args.samples)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
