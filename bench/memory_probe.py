"""Memory of one node with N declared parameters, in a fresh process.

``python -m bench.memory_probe DIR MODULE CLASS MODE``: CLASS is the generated
class, or ``-`` for the hand-written module. MODE ``rss`` reports how much the
resident set grew from a baseline of rclpy initialised
with an empty node; ``rss-bare`` the same for a class declared with
``publish_schema=False``; ``traced`` reports the Python memory still allocated
afterwards (``tracemalloc``), which is exact but slows the run. All count
importing the module and declaring.
"""

from __future__ import annotations

import importlib
import json
import resource
import sys
import tracemalloc


def rss_bytes() -> int:
    """Resident set size now (Linux), else the peak so far."""
    try:
        with open("/proc/self/statm", encoding="ascii") as statm:
            return int(statm.read().split()[1]) * resource.getpagesize()
    except OSError:
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def main(directory: str, module_name: str, class_name: str, mode: str) -> None:
    import rclpy
    from rclpy.context import Context
    from rclpy.node import Node

    context = Context()
    rclpy.init(context=context)
    node = Node("bench_memory", context=context)
    sys.path.insert(0, directory)
    baseline_count = len(node.get_parameters_by_prefix(""))
    baseline = rss_bytes()
    if mode == "traced":
        tracemalloc.start()
    module = importlib.import_module(module_name)
    if class_name == "-":
        module.declare(node)
    else:
        getattr(module, class_name).declare(node, publish_schema=mode != "rss-bare")
    if mode == "traced":
        grown = tracemalloc.get_traced_memory()[0]
        tracemalloc.stop()
    else:
        grown = rss_bytes() - baseline
    declared = len(node.get_parameters_by_prefix(""))  # also counts rclpy's own, e.g. use_sim_time
    print(json.dumps({"bytes": grown, "parameters": declared - baseline_count}))
    node.destroy_node()
    rclpy.shutdown(context=context)


if __name__ == "__main__":
    main(*sys.argv[1:5])
