"""The graph lets go of nodes that left, and only of those.

A node started a moment ago can take seconds to be discovered on a loaded
machine. Its service clients, made as soon as a command asks for it, must live
until it appears: destroying them under a waiting reader made ``import-node``
fail with rclpy's "destruction was requested".
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from genparams.tune.graph import UNSEEN_GRACE_SECONDS, Graph
from tests.tune.support import demo_nodes, eventually, unique


@pytest.fixture
def graph() -> Iterator[Graph]:
    made = Graph(unique("sweep_test"))
    try:
        yield made
    finally:
        made.close()


def test_a_node_not_discovered_yet_keeps_its_clients(graph: Graph) -> None:
    late = unique("sweep_late")
    reader = graph.reader(f"/{late}")
    for _ in range(3):
        graph.sweep()
    assert graph.readers.get(f"/{late}") is reader
    assert reader.wait_ready(0.05) is False  # its clients still work: not ready, no error
    with demo_nodes(f"{late}:plain"):
        assert reader.wait_ready(60.0)
        assert [p["name"] for p in graph.read_node(f"/{late}", timeout=30.0)]


def test_a_node_that_left_is_let_go_after_two_sweeps(graph: Graph) -> None:
    leaving = unique("sweep_leaving")
    with demo_nodes(f"{leaving}:plain"):
        eventually(lambda: f"/{leaving}" in graph.node_names(), timeout=60)
        assert graph.reader(f"/{leaving}").wait_ready(60.0)
        graph.sweep()
    eventually(lambda: f"/{leaving}" not in graph.node_names(), timeout=60)
    graph.sweep()
    graph.sweep()
    assert f"/{leaving}" not in graph.readers


def test_a_node_never_seen_is_let_go_after_the_grace(graph: Graph) -> None:
    ghost = f"/{unique('sweep_ghost')}"
    graph.reader(ghost)
    graph.sweep()
    graph.sweep()
    assert ghost in graph.readers
    graph.asked[ghost] -= UNSEEN_GRACE_SECONDS + 1
    graph.sweep()
    graph.sweep()
    assert ghost not in graph.readers
