"""import-rclpy on ``else`` branches, ``!=`` and ``not in``: each becomes a negated ``when``
(``{not: ...}``), and the class generated from the schema declares, on a real node, exactly
what the node's own code declares on another, whatever the node starts with."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml

from genparams.cli import main
from genparams.runtime.core.naming import class_name
from tests.rclpy_import.cases import NODES
from tests.rclpy_import.declared import declared
from tests.support import RosHarness, import_file, load_generated

NODE = NODES / "lease_client.py"


def imported(source: Path, schema: Path, capsys: pytest.CaptureFixture[str]) -> str:
    code = main(["import-rclpy", str(source), "-o", str(schema)])
    err = capsys.readouterr().err
    assert code == 0, err
    return err


@pytest.mark.parametrize(
    "args",
    [
        [],
        ["-p", "leasing_mode:=proxied", "-p", "link:=sim", "-p", "retries:=0"],
        ["-p", "link:=udp", "-p", "simulated:=true", "-p", "retries:=1"],
        ["-p", "lease_rate:=5.0", "-p", "baud_rate:=9600", "-p", "backoff:=3.0"],
        ["-p", "leasing_mode:=proxied", "-p", "proxy_host:=relay", "-p", "lease_rate:=5.0"],
    ],
)
def test_the_generated_class_declares_what_the_node_declares(
    args: list[str], ros: RosHarness, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    schema = tmp_path / "lease_client.yaml"
    err = imported(NODE, schema, capsys)
    assert "warning" not in err and err.endswith("imported 13 of 13 parameters\n"), err
    node_class: Any = import_file(NODE).LeaseClient
    cli_args = ["--ros-args", *args] if args else None
    hand = declared(ros.add_node(node_class(context=ros.context, cli_args=cli_args)))
    fresh = ros.node(args=args)
    getattr(load_generated(schema, tmp_path), class_name("lease_client")).declare(fresh)
    assert declared(fresh) == hand


def test_each_branch_gets_its_condition(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    schema = tmp_path / "lease_client.yaml"
    imported(NODE, schema, capsys)
    when = {
        name: leaf.get("when")
        for name, leaf in yaml.safe_load(schema.read_text("utf-8"))["parameters"].items()
    }
    assert when == {
        "leasing_mode": None,
        "link": None,
        "simulated": None,
        "retries": None,
        "proxy_host": {"leasing_mode": "proxied"},
        "lease_rate": {"leasing_mode": {"not": "proxied"}},  # else
        "device": {"link": {"not": "sim"}},  # !=
        "baud_rate": {"link": {"not": ["sim", "udp"]}},  # not in
        "world": {"simulated": True},
        "calibration_file": {"simulated": False},  # the else of a truth test
        "fail_fast": {"retries": 0},
        "retry_delay": {"retries": 1},  # elif: not 0, and 1
        "backoff": {"retries": {"not": [0, 1]}},  # else of if ... elif ...
    }


BODY = """\
from rclpy.node import Node


class Valve(Node):
    def __init__(self):
        super().__init__("valve")
        mode = self.declare_parameter("mode", "auto").value
        if not mode == "manual":
            self.declare_parameter("setpoint", 1.0)
        if mode != "auto":
            if mode != "manual":
                self.declare_parameter("schedule", "daily")
            else:
                self.declare_parameter("handle", "left")
"""


def test_not_and_nested_tests_on_one_parameter_combine(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "valve.py"
    source.write_text(BODY, encoding="utf-8")
    schema = tmp_path / "valve.yaml"
    imported(source, schema, capsys)
    parameters = yaml.safe_load(schema.read_text("utf-8"))["parameters"]
    assert parameters["setpoint"]["when"] == {"mode": {"not": "manual"}}
    assert parameters["schedule"]["when"] == {"mode": {"not": ["auto", "manual"]}}
    assert parameters["handle"]["when"] == {"mode": "manual"}
