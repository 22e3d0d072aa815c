"""Memory of a node with N declared parameters: genparams and plain rclpy, one process each."""

from __future__ import annotations

from bench.build_scenarios import write_bytecode
from bench.measure import Result, run_probe
from bench.workspace import Prepared

RSS_GENPARAMS = "genparams: RSS growth"
RSS_PLAIN = "plain rclpy: RSS growth"
TRACED_GENPARAMS = "genparams: Python heap (tracemalloc)"
TRACED_PLAIN = "plain rclpy: Python heap (tracemalloc)"


def memory(prepared: Prepared, repeats: int) -> list[Result]:
    schema = prepared.schema
    directory = str(prepared.module_path.parent)
    sides = (
        (schema.module_name, schema.class_name, RSS_GENPARAMS, TRACED_GENPARAMS),
        (schema.plain_module_name, "-", RSS_PLAIN, TRACED_PLAIN),
    )
    # Without a .pyc, compiling the module would dominate (over 100 MiB at 10,000 parameters).
    write_bytecode(prepared.module_path.parent, schema.module_name, schema.plain_module_name)
    samples: dict[str, list[float]] = {}
    for _ in range(repeats):
        for module, class_name, rss_label, traced_label in sides:
            for mode, label in (("rss", rss_label), ("traced", traced_label)):
                outcome = run_probe("bench.memory_probe", [directory, module, class_name, mode])
                if outcome["parameters"] != schema.size:
                    raise RuntimeError(f"{label}: {outcome['parameters']} parameters declared")
                samples.setdefault(label, []).append(float(outcome["bytes"]))
    return [
        Result("memory", label, schema.size, "B", tuple(values))
        for label, values in samples.items()
    ]
