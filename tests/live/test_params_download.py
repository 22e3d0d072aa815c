"""The params download (``/api/params-file``) of real nodes.

- A node with open groups: the file holds every name the node declared from its schema,
  placed by the runtime's own place mapping (open groups and groups in entries), and no other.
- A plain node declaring ``a``, ``a.b`` and ``a.b.c``: the file is written (no 500), and
  genparams' params reader reads back the same three names and values.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
import yaml

from genparams.paramsfile.params_reader import read_params_file
from genparams.tune.server import TuneServer
from tests.live.support import hostile_nodes
from tests.runtime.test_open_groups import PARAMS
from tests.tune.support import api_call, demo_nodes, eventually, unique

OPEN, DOTTED = f"/{unique('dump_open')}", f"/{unique('dump_dotted')}"
RCLPY_OWN = {"use_sim_time", "start_type_description_service"}  # every rclpy node has them


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[TuneServer]:
    params = tmp_path_factory.mktemp("dump") / "open.yaml"
    params.write_text(PARAMS, encoding="utf-8")
    with (
        demo_nodes(f"{OPEN[1:]}:open", ros_args=("--params-file", str(params))),
        hostile_nodes(f"{DOTTED[1:]}:dotted"),
    ):
        tune = TuneServer()
        tune.start()
        try:
            eventually(lambda: tune.graph.schema(OPEN))
            eventually(lambda: DOTTED in tune.graph.node_names())  # a plain node: no schema
            yield tune
        finally:
            tune.stop()


def dumped(server: TuneServer, node: str, tmp_path: Path) -> dict[str, object]:
    answer = api_call(server, f"/api/params-file?node={node}")
    assert answer.ok, (answer.status, answer.body)
    text = answer.body.decode("utf-8")
    document = read_params_file(text, str(tmp_path / "dump.yaml"))
    assert not document.problems, document.problems
    return {entry.name: entry.value for s in document.sections for entry in s.entries}


def test_open_groups_dump_every_declared_name_and_no_other(
    server: TuneServer, tmp_path: Path
) -> None:
    declared = {
        p["name"]
        for p in api_call(server, f"/api/node?name={OPEN}").json()["parameters"]
        if p["type"] != "unset" and p["name"] not in RCLPY_OWN
    }
    assert "controllers.arm.gains.left.p" in declared  # a group inside an open group's entry
    assert set(dumped(server, OPEN, tmp_path)) == declared


def test_a_name_below_another_value_is_written_and_read_back(
    server: TuneServer, tmp_path: Path
) -> None:
    values = dumped(server, DOTTED, tmp_path)
    assert {k: v for k, v in values.items() if k not in RCLPY_OWN} == {
        "a": 1.0,
        "a.b": 2.0,
        "a.b.c": "three",
    }
    text = api_call(server, f"/api/params-file?node={DOTTED}").body.decode("utf-8")
    assert yaml.safe_load(text)[DOTTED]["ros__parameters"]["a.b"] == 2.0
