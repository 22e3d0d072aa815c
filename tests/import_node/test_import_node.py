"""`genparams import-node`: a schema read from a hand-written node in another process; the
generated class, declared on a fresh node, reproduces every descriptor and value."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
import yaml
from rclpy.parameter import parameter_value_to_python

from genparams.runtime.core.naming import NODE_PARAMETERS
from tests.node_process import node_process
from tests.patience import WAIT_S, run_patiently
from tests.support import ROOT, RosHarness, ServiceClient, load_generated
from tests.tune.support import unique

NODES = "tests.import_node.hand_written_nodes"
FIELDS = ("type", "description", "additional_constraints", "read_only", "dynamic_typing")


def import_node(node: str, *args: str) -> subprocess.CompletedProcess[str]:
    command = [sys.executable, "-m", "genparams", "import-node", node, "--timeout", f"{WAIT_S:g}"]
    return run_patiently([*command, *args], budget_s=2 * WAIT_S, cwd=ROOT)


def _ranges(descriptor: Any) -> list[tuple[Any, ...]]:
    return [
        (r.from_value, r.to_value, r.step)
        for r in (*descriptor.integer_range, *descriptor.floating_point_range)
    ]


def _values(values: list[Any]) -> list[Any]:
    return [list(v) if isinstance(v, (list, tuple)) or hasattr(v, "tolist") else v for v in values]


def _one_by_one(client: ServiceClient, names: list[str]) -> list[Any]:
    """Each value alone: rclpy answers a get naming a parameter not set with no values."""
    out = []
    for name in names:
        response = client.harness.wait(client.client.get_parameters([name]))
        out.append(_values([parameter_value_to_python(v) for v in response.values]))
    return out


@pytest.mark.parametrize(
    "kind, parameters",
    [("driver", 12), ("dynamic", 5), ("names", 5)],
)
def test_generated_class_reproduces_every_descriptor(
    kind: str, parameters: int, ros: RosHarness, tmp_path: Path
) -> None:
    node = f"/{unique(kind)}"
    with node_process(NODES, f"{node[1:]}:{kind}"):
        done = import_node(node, "-o", str(tmp_path / f"{kind}.yaml"))
        assert done.returncode == 0, done.stderr
        remote = ServiceClient(ros, node)
        names = sorted(n for n in _list(remote) if n not in NODE_PARAMETERS)
        theirs = remote.describe(*names)
        their_values = _one_by_one(remote, names)
    assert f"imported {parameters} of {parameters} parameters" in done.stderr
    assert len(names) == parameters
    module = load_generated(tmp_path / f"{kind}.yaml", tmp_path)
    fresh = ros.node()
    cls = next(v for k, v in vars(module).items() if k.endswith("Params") and hasattr(v, "_SPEC"))
    cls.declare(fresh)
    client = ros.client(fresh)
    ours = client.describe(*names)
    for name, mine, original_descriptor in zip(names, ours, theirs, strict=True):
        for field in FIELDS:
            assert getattr(mine, field) == getattr(original_descriptor, field), (name, field)
        assert _ranges(mine) == _ranges(original_descriptor), name
    assert _one_by_one(client, names) == their_values


def _list(client: Any) -> list[str]:
    response = client.harness.wait(client.client.list_parameters([], 0))
    return list(response.result.names)


def test_optional_and_dynamically_typed_parameters_import_as_such(tmp_path: Path) -> None:
    node = f"/{unique('dynamic')}"
    with node_process(NODES, f"{node[1:]}:dynamic"):
        done = import_node(node)
    assert done.returncode == 0, done.stderr
    assert "warning" not in done.stderr
    schema = yaml.safe_load(done.stdout)
    assert schema["parameters"] == {
        "gain": {"type": "double", "default": 2.0, "description": "Gain."},
        "anything": {"type": "any", "default": 1},
        "extra": {"type": "any", "optional": True, "description": "Free."},
        "robot_ip": {"type": "string", "optional": True},
        "frames": {
            "type": "string_array",
            "optional": True,
            "description": "Frames to watch.",
            "read_only": True,
        },
    }


def test_a_parameter_a_schema_cannot_state_is_left_out_with_a_warning_and_exit_1(
    tmp_path: Path,
) -> None:
    node = f"/{unique('lossy')}"
    output = tmp_path / "lossy.yaml"
    with node_process(NODES, f"{node[1:]}:lossy"):
        done = import_node(node, "-o", str(output))
    assert done.returncode == 1, done.stderr
    lines = done.stderr.splitlines()  # rclpy's own parameters first, as notes
    assert all(": note: declared by rclpy itself: left out" in line for line in lines[:-3])
    assert lines[-3:] == [
        f"{node}: limits.upper: warning: 'limits' is a parameter too, so it cannot be a "
        "namespace: left out",
        f"{node}: speed_max: warning: 'speed_max' and 'speed-max' of one namespace would "
        "share the Python attribute 'speed_max': left out",
        "imported 2 of 4 parameters; 2 left out (see warnings)",
    ]
    schema = yaml.safe_load(output.read_text(encoding="utf-8"))
    assert schema["parameters"] == {
        "limits": {"type": "double", "default": 1.0},
        "speed-max": {"type": "double", "default": 1.0},
    }


def test_a_node_that_is_not_there_exits_2() -> None:
    done = import_node(f"/{unique('nobody')}", "--timeout", "1")
    assert done.returncode == 2
    assert "parameter services did not appear" in done.stderr
    assert done.stdout == ""


@pytest.mark.parametrize("bad", ["bad name!", "/{x}"])
def test_an_invalid_node_name_exits_2(bad: str) -> None:
    done = import_node(bad)
    assert done.returncode == 2 and "invalid node" in done.stderr
