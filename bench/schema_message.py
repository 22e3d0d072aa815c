"""How long a tool takes to read a node's schema message, for 100 to 5,000 parameters.

The mixed benchmark schema (bench/schemas.py: every type, ranges, choices,
validators) is described as a node publishes it; each row reads that text with
plain ``json.loads``, with the codec (limits, no NaN tokens, tags), and with
:func:`read_schema_message` (the codec, the shape check and every parameter
compiled with the runtime's validators), best of several runs.

Run with ``python -m bench.schema_message``.
"""

from __future__ import annotations

import json
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import genparams
from bench.schemas import bench_schema, write_schema
from genparams.runtime.core.json_codec import loads
from genparams.runtime.core.schema_message import SCHEMA_MESSAGE_LIMITS, read_schema_message
from genparams.runtime.core.spec import compile_schema
from genparams.runtime.node.schema_topic import class_text, node_message_text

SIZES = (100, 1000, 5000)
RUNS = 7


def message_text(size: int, directory: Path) -> str:
    schema_path = write_schema(bench_schema(size), directory)
    module_path = directory / f"bench_{size}_params.py"
    module_path.write_text(genparams.generate(schema_path), encoding="utf-8")
    namespace: dict[str, Any] = {}
    exec(compile(module_path.read_text(encoding="utf-8"), str(module_path), "exec"), namespace)
    spec = next(v._SPEC for v in namespace.values() if hasattr(v, "_SPEC"))
    return node_message_text("/bench", [class_text(compile_schema(spec), "")])


def best_ms(read: Callable[[str], object], text: str) -> float:
    times = []
    for _ in range(RUNS):
        started = time.perf_counter()
        read(text)
        times.append(time.perf_counter() - started)
    return min(times) * 1000


def codec(text: str) -> object:
    return loads(text, SCHEMA_MESSAGE_LIMITS)


def checked(text: str) -> object:
    return read_schema_message(text, "/bench")


def main() -> int:
    print("| parameters | message | json.loads | codec | read_schema_message |")
    print("|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as directory:
        for size in SIZES:
            text = message_text(size, Path(directory))
            assert isinstance(read_schema_message(text, "/bench"), dict)
            row = [best_ms(read, text) for read in (json.loads, codec, checked)]
            cells = " | ".join(f"{ms:.1f} ms" for ms in row)
            print(f"| {size:,} | {len(text) / 1024:.0f} KiB | {cells} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
