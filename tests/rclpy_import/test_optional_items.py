"""Per-item parameters declared by type only (``for goal in goals:
self.declare_parameter(goal, Parameter.Type.DOUBLE_ARRAY)``) import as optional entries:
the generated class declares on a real node what the node's own code declares."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml

from genparams.cli import main
from genparams.runtime.core.naming import class_name
from tests.rclpy_import.declared import declared, without_item_rule
from tests.support import RosHarness, import_file, load_generated

NODE = """\
import rclpy
from rclpy.node import Node


class GoalPublisher(Node):
    def __init__(self, **kwargs):
        super().__init__("goal_publisher", **kwargs)
        self.declare_parameter("goals", ["home", "dock"])
        self.declare_parameter("arms", ["left"])
        for goal in self.get_parameter("goals").value:
            self.declare_parameter(goal, rclpy.Parameter.Type.DOUBLE_ARRAY)
        for arm in self.get_parameter("arms").value:
            self.declare_parameter(f"gains.{arm}.p", rclpy.Parameter.Type.DOUBLE)
            self.declare_parameter(f"gains.{arm}.i", 0.5)
"""


def imported(tmp_path: Path, text: str, capsys: pytest.CaptureFixture[str]) -> tuple[Path, str]:
    source = tmp_path / "goal_publisher.py"
    source.write_text(text, encoding="utf-8")
    schema = tmp_path / "goal_publisher.yaml"
    code = main(["import-rclpy", str(source), "-o", str(schema)])
    err = capsys.readouterr().err
    assert code in (0, 1), err
    return schema, err


def test_items_declared_by_type_only_import_as_optional_entries(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    schema, err = imported(tmp_path, NODE, capsys)
    parameters = yaml.safe_load(schema.read_text("utf-8"))["parameters"]
    assert parameters["*"] == {"for_each": "goals", "type": "double_array", "optional": True}
    assert parameters["gains"]["p"] == {"type": "double", "optional": True}
    assert "imported 5 of 5 parameters" in err and "warning" not in err


@pytest.mark.parametrize("args", [[], ["-p", "dock:=[1.0, 2.0]", "-p", "gains.left.p:=3.0"]])
def test_the_generated_class_declares_what_the_node_declares(
    args: list[str], ros: RosHarness, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    schema, _ = imported(tmp_path, NODE, capsys)
    module = load_generated(schema, tmp_path)
    cli_args = ["--ros-args", *args] if args else None
    node_class: Any = import_file(tmp_path / "goal_publisher.py").GoalPublisher
    hand = declared(ros.add_node(node_class(context=ros.context, cli_args=cli_args)))
    fresh = ros.node(args=args)
    getattr(module, class_name("goal_publisher")).declare(fresh)
    ours = {n: (without_item_rule(d), v) for n, (d, v) in declared(fresh).items()}
    assert (
        sorted(ours)
        == sorted(hand)
        == sorted(["goals", "arms", "home", "dock", "gains.left.p", "gains.left.i"])
    )
    for name in hand:
        assert ours[name] == hand[name], name


def test_items_naming_a_parameter_and_a_group_keep_the_group(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    text = NODE.replace(
        "            self.declare_parameter(goal, rclpy.Parameter.Type.DOUBLE_ARRAY)\n",
        "            self.declare_parameter(goal, rclpy.Parameter.Type.DOUBLE_ARRAY)\n"
        '            self.declare_parameter(f"{goal}.speed", 1.0)\n',
    )
    schema, err = imported(tmp_path, text, capsys)
    parameters = yaml.safe_load(schema.read_text("utf-8"))["parameters"]
    assert parameters["*"] == {"for_each": "goals", "speed": {"type": "double", "default": 1.0}}
    assert "{goal}: warning: its schema key '*' also holds a mapped group" in err
    assert "a schema key is a parameter or a group, not both: parameter left out" in err
