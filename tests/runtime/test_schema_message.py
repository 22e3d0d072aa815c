"""The ~/genparams/schema message a node publishes: every field of every declared class,
its hashes, and how it is latched for late subscribers."""

from __future__ import annotations

import hashlib
import json
import time
import types
from pathlib import Path
from typing import Any

import pytest
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

from genparams import __version__
from genparams.runtime.core.spec import compile_schema
from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX, class_text
from tests.support import ROOT, RosHarness, load_generated

GRIPPER = """\
genparams: 1
name: gripper
parameters:
  serial: {type: string, description: Serial number., read_only: true}
  force:
    type: double
    default: 2.5
    unit: N
    description: Closing force.
    range: {min: 0.0, max: 10.0, step: 0.5}
    additional_constraints: Keep it low on glass.
  width: {type: int, default: 40, range: {min: 0, max: 80}}
  mode: {type: string, default: soft, choices: [soft, firm]}
  blob: {type: byte_array, default: [0, 255]}
  names:
    type: string_array
    default: [a, b]
    validators: [not_empty, {pattern: "^[a-z]"}]
  old_grip: {type: bool, default: false, deprecated: use mode, aliases: [grip]}
  fingers: {type: string_array, default: [left]}
  tips:
    for_each: fingers
    pad: {type: double, default: 1.0, validators: [{ge: 0.0}]}
    soft: {type: bool, default: true}
rules:
  - name: width_with_force
    check: force <= width
    description: Force grows with the opening.
"""

LATCHED = QoSProfile(
    depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL
)


@pytest.fixture
def gripper(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "gripper.yaml"
    schema.write_text(GRIPPER)
    return load_generated(schema, tmp_path)


class Listener:
    """A late subscriber, as a tool is: it gets the latched message without asking."""

    def __init__(self, ros: RosHarness, node: Node) -> None:
        self.ros = ros
        self.texts: list[str] = []
        topic = node.get_fully_qualified_name() + SCHEMA_TOPIC_SUFFIX
        self.subscription = ros.client_node.create_subscription(
            String, topic, self._received, LATCHED
        )

    def _received(self, message: String) -> None:
        self.texts.append(message.data)

    def wait_for(self, count: int, timeout: float = 10.0) -> list[str]:
        deadline = time.monotonic() + timeout
        while len(self.texts) < count:
            if time.monotonic() > deadline:
                raise TimeoutError(f"{len(self.texts)} of {count} messages")
            self.ros.executor.spin_once(timeout_sec=0.05)
        return self.texts

    def close(self) -> None:
        self.ros.client_node.destroy_subscription(self.subscription)


@pytest.fixture
def listen(ros: RosHarness) -> Any:
    listeners: list[Listener] = []

    def make(node: Node) -> Listener:
        listeners.append(Listener(ros, node))
        return listeners[-1]

    yield make
    for listener in listeners:
        listener.close()


def digest(body: Any) -> str:
    text = json.dumps(body, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


def param(name: str, type_: str, **fields: Any) -> dict[str, Any]:
    described = {
        "name": name,
        "type": type_,
        "required": False,
        "default": None,
        "description": "",
        "unit": "",
        "read_only": False,
        "range": None,
        "choices": None,
        "validators": [],
        "constraints": [],
        "additional_constraints": "",
        "deprecated": "",
        "aliases": [],
    }
    described.update(fields)
    return described


EXPECTED_PARAMETERS = [
    param(
        "hand.serial",
        "string",
        required=True,
        description="Serial number.",
        read_only=True,
    ),
    param(
        "hand.force",
        "double",
        default=2.5,
        unit="N",
        description="Closing force.",
        range={"min": 0.0, "max": 10.0, "step": 0.5},
        constraints=["within [0.0, 10.0] in steps of 0.5"],
        additional_constraints="Keep it low on glass.",
        ros_range=True,
    ),
    param(
        "hand.width",
        "int",
        default=40,
        range={"min": 0, "max": 80, "step": 0},
        constraints=["within [0, 80]"],
        ros_range=True,
    ),
    param(
        "hand.mode",
        "string",
        default="soft",
        choices=["soft", "firm"],
        constraints=["one of 'soft', 'firm'"],
    ),
    param("hand.blob", "byte_array", default=[0, 255]),
    param(
        "hand.names",
        "string_array",
        default=["a", "b"],
        validators=[["not_empty", None], ["pattern", "^[a-z]"]],
        constraints=["not empty", "matches '^[a-z]'"],
    ),
    param("hand.old_grip", "bool", default=False, deprecated="use mode", aliases=["grip"]),
    param(
        "hand.fingers",
        "string_array",
        default=["left"],
        constraints=[
            "each item names an entry of tips: any text but '.', '*', spaces and control "
            "characters; no repeats"
        ],
    ),
]


def test_every_field_of_a_class_is_published(
    ros: RosHarness, gripper: types.ModuleType, listen: Any
) -> None:
    node = ros.node(args=["-p", "hand.serial:=G1"])
    gripper.GripperParams.declare(node, prefix="hand")
    (text,) = listen(node).wait_for(1)
    message = json.loads(text)
    assert text == json.dumps(message, sort_keys=True)
    (described,) = message["classes"]
    assert sorted(described) == ["class", "hash", "maps", "parameters", "prefix", "rules"]
    assert (described["class"], described["prefix"]) == ("gripper", "hand")
    assert described["parameters"] == sorted(EXPECTED_PARAMETERS, key=lambda p: p["name"])
    assert described["maps"] == [
        {
            "path": "hand.tips",
            "for_each": "hand.fingers",
            "fields": [
                param(
                    "pad",
                    "double",
                    default=1.0,
                    validators=[["ge", 0.0]],
                    constraints=["must be >= 0.0"],
                ),
                param("soft", "bool", default=True),
            ],
        }
    ]
    assert described["rules"] == [
        {
            "name": "width_with_force",
            "check": "force <= width",
            "description": "Force grows with the opening.",
            "parameters": ["hand.force", "hand.width"],
        }
    ]
    body = {key: value for key, value in described.items() if key != "hash"}
    assert described["hash"] == digest(body)
    assert sorted(message) == ["classes", "format", "genparams", "hash", "node"]
    assert message["format"] == 1
    assert message["genparams"] == __version__
    assert message["node"] == node.get_fully_qualified_name()
    assert message["hash"] == digest({"classes": [described["hash"]]})


def test_equal_classes_hash_equal_and_a_prefix_changes_the_hash(
    ros: RosHarness, gripper: types.ModuleType, listen: Any
) -> None:
    nodes = [ros.node(args=["-p", f"{p}.serial:=G1"]) for p in ("hand", "hand", "left")]
    for node, prefix in zip(nodes, ("hand", "hand", "left"), strict=True):
        gripper.GripperParams.declare(node, prefix=prefix)
    messages = [json.loads(listen(node).wait_for(1)[0]) for node in nodes]
    first, same, other = (m["classes"][0]["hash"] for m in messages)
    assert first == same != other
    assert messages[0]["hash"] == messages[1]["hash"] != messages[2]["hash"]


def test_classes_declared_on_one_node_merge_in_one_latched_message(
    ros: RosHarness, gripper: types.ModuleType, listen: Any
) -> None:
    node = ros.node(args=["-p", "right.serial:=G2", "-p", "left.serial:=G1", "-p", "serial:=G0"])
    gripper.GripperParams.declare(node, prefix="right")
    gripper.GripperParams.declare(node, prefix="left")
    listener = listen(node)
    # Only the newest message is kept for a late subscriber.
    (latched,) = listener.wait_for(1)
    gripper.GripperParams.declare(node)
    _, newest = listener.wait_for(2)
    classes = json.loads(latched)["classes"]
    assert [c["prefix"] for c in classes] == ["left", "right"]
    assert [p["name"] for p in classes[0]["parameters"]][:2] == ["left.blob", "left.fingers"]
    merged = json.loads(newest)
    assert [c["prefix"] for c in merged["classes"]] == ["", "left", "right"]
    assert merged["classes"][1:] == classes
    assert merged["hash"] == digest({"classes": [c["hash"] for c in merged["classes"]]})
    assert newest == json.dumps(merged, sort_keys=True)


def test_a_class_description_is_built_once_per_prefix(
    gripper: types.ModuleType, tmp_path: Path
) -> None:
    arm = load_generated(ROOT / "examples" / "arm" / "arm.yaml", tmp_path)
    hand = compile_schema(gripper.GripperParams._SPEC)
    first = class_text(hand, "")
    assert json.loads(first.text)["hash"] == first.hash
    class_text(compile_schema(arm.ArmParams._SPEC), "")  # another class, the same prefix
    assert class_text(hand, "") is first  # every node declaring it shares this text
    prefixed = class_text(hand, "hand")
    assert prefixed is not first and prefixed.hash != first.hash
    assert class_text(hand, "hand") is prefixed
