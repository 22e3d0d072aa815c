"""Nodes that come and go, for the soak test: ``python -m tests.tune.churn PREFIX BATCH``.

Starts BATCH self-describing nodes (the motion schema), prints their names on one
line, and waits for a line on stdin; then destroys them and starts the next
batch, with new names. An empty line or end of input stops it.
"""

from __future__ import annotations

import sys
import tempfile
import threading
from pathlib import Path

import rclpy
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node

from tests.tune.demo_nodes import params_class


def main(prefix: str, batch: int) -> int:
    rclpy.init()
    executor = MultiThreadedExecutor()
    spinner = threading.Thread(target=executor.spin, daemon=True)
    spinner.start()
    params = params_class("motion", Path(tempfile.mkdtemp(prefix="genparams-churn-")))
    round_ = 0
    while True:
        nodes = [Node(f"{prefix}_{round_}_{index}") for index in range(batch)]
        held = [params.declare(node) for node in nodes]
        for node in nodes:
            executor.add_node(node)
        print(" ".join(node.get_fully_qualified_name() for node in nodes), flush=True)
        command = sys.stdin.readline()
        for node in nodes:
            executor.remove_node(node)
            node.destroy_node()
        del held
        if not command.strip():
            break
        round_ += 1
    executor.shutdown()
    rclpy.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2])))
