"""What the page is told of a node is what the node holds, and a set reaches a node once.

- Another node publishes ``ParameterEvent(node=<plain>, gain=9.5)`` five times a second while
  the plain node holds 1.5: the graph's listeners get 1.5, never 9.5.
- A node whose on-set callback takes 1.6 s is set twice: its callback runs twice, once per
  set (a set resent while unanswered ran it again); a node still working past the server's
  wait is told as "still working" (202), not as failed.
"""

from __future__ import annotations

import json
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from genparams.live.graph import Graph
from genparams.tune.server import TuneServer
from tests.live.hostile_nodes import FORGED_GAIN
from tests.live.support import hostile_nodes
from tests.tune.support import api_call, eventually, unique

TARGET, FORGER = f"/{unique('events_target')}", f"/{unique('events_forger')}"
SLOW, SLOWER = f"/{unique('sets_slow')}", f"/{unique('sets_slower')}"


def test_forged_parameter_events_never_reach_the_listeners() -> None:
    graph = Graph(unique("events_test"))
    got: list[dict[str, Any]] = []
    seen = threading.Event()

    def listener(event: dict[str, Any]) -> None:
        if event.get("node") == TARGET and "gain" in event.get("changed", {}):
            got.append(event)
            if len(got) >= 3:
                seen.set()

    graph.subscribe(listener)
    try:
        with hostile_nodes(f"{TARGET[1:]}:plain", f"{FORGER[1:]}:forger:{TARGET}"):
            eventually(lambda: seen.is_set())
    finally:
        graph.close()
    values = [event["changed"]["gain"] for event in got]
    assert FORGED_GAIN not in values, got
    assert set(values) == {1.5}, got


def count(path: Path) -> int:
    return int(path.read_text(encoding="utf-8") or 0) if path.exists() else 0


@pytest.fixture(scope="module")
def slow_nodes(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[Path, Path]]:
    workdir = tmp_path_factory.mktemp("slow")
    slow, slower = workdir / "slow.count", workdir / "slower.count"
    with hostile_nodes(f"{SLOW[1:]}:slow:1.6:{slow}", f"{SLOWER[1:]}:slow:600:{slower}"):
        yield slow, slower


@pytest.fixture(scope="module")
def server(slow_nodes: tuple[Path, Path]) -> Iterator[TuneServer]:
    tune = TuneServer()  # it waits SET_WAIT_SECONDS for a set's answer
    tune.start()
    try:
        eventually(lambda: {SLOW, SLOWER} <= set(tune.graph.node_names()))
        yield tune
    finally:
        tune.stop()


def set_counter(server: TuneServer, node: str, value: int) -> Any:
    body = {"node": node, "params": [{"name": "counter", "type": "int", "value": value}]}
    return api_call(server, "/api/set", body)


def test_a_set_runs_the_on_set_callback_once(
    server: TuneServer, slow_nodes: tuple[Path, Path]
) -> None:
    for sets, value in enumerate((7, 8), start=1):
        answer = set_counter(server, SLOW, value)
        assert answer.ok, answer.body
        assert answer.json()["results"][0]["successful"]
        # Answered: the callback has run for this set, and for no set twice.
        assert count(slow_nodes[0]) == sets


def test_a_node_still_working_is_not_told_as_failed(
    server: TuneServer, slow_nodes: tuple[Path, Path]
) -> None:
    answer = set_counter(server, SLOWER, 7)
    assert answer.status == 202, (answer.status, answer.body)
    body = json.loads(answer.body)
    assert body["pending"] is True and "still working" in body["detail"]
    assert count(slow_nodes[1]) == 1
