"""A node declaring a generated class, served from a context and thread of its own, as
``genparams tune`` and ``genparams audit`` find the nodes of other processes."""

from __future__ import annotations

import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node

from genparams.tune.graph import Graph
from tests.support import unique_name


@contextmanager
def served(params_cls: Any, args: list[str]) -> Iterator[str]:
    """The node's fully qualified name while the block runs."""
    context = Context()
    rclpy.init(context=context)
    name = unique_name("served")
    node = Node(name, context=context, cli_args=["--ros-args", *args])
    params_cls.declare(node)
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(node)
    thread = threading.Thread(target=executor.spin, daemon=True)
    thread.start()
    try:
        yield f"/{name}"
    finally:
        executor.shutdown()
        thread.join(timeout=10)
        node.destroy_node()
        rclpy.shutdown(context=context)


def first_read(graph: Graph, node: str, timeout: float = 30.0) -> list[dict[str, Any]]:
    """A service can be ready before its reply path to this client is matched, and a
    request sent then goes unanswered: ask again until one is answered."""
    deadline = time.monotonic() + timeout
    while True:
        try:
            return graph.read_node(node, timeout=2.0)
        except TimeoutError:
            if time.monotonic() > deadline:
                raise
