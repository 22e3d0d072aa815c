"""A node declaring a generated class, served from a context and thread of its own, as
``genparams tune`` and ``genparams audit`` find the nodes of other processes."""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node

from genparams.audit.walk import AuditResult, audit
from genparams.live.graph import Graph
from tests.patience import WAIT_S
from tests.support import unique_name


@contextmanager
def served(params_cls: Any, args: list[str]) -> Iterator[str]:
    """The node's fully qualified name while the block runs."""
    with served_node("served", lambda node: params_cls.declare(node), args) as name:
        yield name


@contextmanager
def served_node(stem: str, setup: Callable[[Node], object], args: list[str]) -> Iterator[str]:
    """A node named after ``stem``, ``setup`` run on it, spun until the block ends."""
    context = Context()
    rclpy.init(context=context)
    name = unique_name(stem)
    node = Node(name, context=context, cli_args=["--ros-args", *args])
    setup(node)
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


def first_read(graph: Graph, node: str) -> list[dict[str, Any]]:
    """Every parameter of ``node`` once its services appear (requests unanswered because the
    reply path to a new client was not matched yet are sent again)."""
    return graph.read_node(node, timeout=WAIT_S)


def audit_served(graph: Graph, node: str) -> AuditResult:
    """The audit of one node that publishes a schema: each wait ends when discovery does."""
    return audit(graph, only=[node], settle=WAIT_S, timeout=WAIT_S)
