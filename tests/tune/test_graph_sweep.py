"""The graph lets go of nodes that left, and only of those.

A node started a moment ago can take seconds to be discovered on a loaded
machine. Its service clients, made as soon as a command asks for it, must live
until it appears: destroying them under a waiting reader made ``import-node``
fail with rclpy's "destruction was requested". The sweeps here are the graph's
own, run by its timer in its executor, as in a running server.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from genparams.live.graph import UNSEEN_GRACE_SECONDS, Graph
from tests.patience import WAIT_S
from tests.tune.support import demo_nodes, eventually, unique


@pytest.fixture
def graph() -> Iterator[Graph]:
    made = Graph(unique("sweep_test"))
    try:
        yield made
    finally:
        made.close()


def wait_sweeps(graph: Graph, count: int) -> None:
    """Until the graph's timer has swept ``count`` more times."""
    start = graph.sweeps
    eventually(lambda: graph.sweeps >= start + count, timeout=WAIT_S)


def test_a_node_not_discovered_yet_keeps_its_clients(graph: Graph) -> None:
    late = unique("sweep_late")
    reader = graph.reader(f"/{late}")
    wait_sweeps(graph, 3)
    assert graph.readers.get(f"/{late}") is reader
    assert reader.wait_ready(0.05) is False  # its clients still work: not ready, no error
    with demo_nodes(f"{late}:plain"):
        assert reader.wait_ready(WAIT_S)
        assert [p["name"] for p in graph.read_node(f"/{late}", timeout=WAIT_S)]


def test_a_node_that_left_is_let_go(graph: Graph) -> None:
    leaving = unique("sweep_leaving")
    with demo_nodes(f"{leaving}:plain"):
        eventually(lambda: f"/{leaving}" in graph.node_names(), timeout=WAIT_S)
        assert graph.reader(f"/{leaving}").wait_ready(WAIT_S)
    eventually(lambda: f"/{leaving}" not in graph.readers, timeout=WAIT_S)


def test_a_node_never_seen_is_let_go_after_the_grace(graph: Graph) -> None:
    ghost = f"/{unique('sweep_ghost')}"
    graph.reader(ghost)
    wait_sweeps(graph, 3)
    assert ghost in graph.readers
    with graph.lock:
        graph.asked[ghost] -= UNSEEN_GRACE_SECONDS + 1
    eventually(lambda: ghost not in graph.readers, timeout=WAIT_S)
