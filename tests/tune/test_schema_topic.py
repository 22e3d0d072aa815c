"""Self-describing nodes: the latched ~/genparams/schema message, merged per node."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

from genparams import __version__
from genparams.live.schema_topics import SCHEMA_QOS
from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX
from tests.patience import WAIT_S
from tests.support import ROOT, RosHarness, load_generated


def latest_schema(ros: RosHarness, node: Node) -> dict[str, Any]:
    """Subscribe late, as a tool would: the transient-local message still arrives."""
    received: list[str] = []
    topic = node.get_fully_qualified_name() + SCHEMA_TOPIC_SUFFIX

    def keep(message: String) -> None:
        received.append(message.data)

    subscription = ros.client_node.create_subscription(String, topic, keep, SCHEMA_QOS)
    try:
        deadline = time.monotonic() + 30.0  # by the clock: spin_once returns at any callback
        while not received and time.monotonic() < deadline:
            ros.executor.spin_once(timeout_sec=0.05)
        assert received, f"no message on {topic}"
        return dict(json.loads(received[-1]))
    finally:
        ros.client_node.destroy_subscription(subscription)


def test_a_declared_class_describes_itself(ros: RosHarness, tmp_path: Path) -> None:
    module = load_generated(ROOT / "examples/camera_node/camera_driver.yaml", tmp_path)
    node = ros.node(args=["-p", "serial:=CAM12345"])
    module.CameraDriverParams.declare(node)
    message = latest_schema(ros, node)
    assert message["genparams"] == __version__
    assert message["node"] == node.get_fully_qualified_name()
    (described,) = message["classes"]
    by_name = {p["name"]: p for p in described["parameters"]}
    fps = by_name["camera.fps"]
    assert fps["unit"] == "Hz"
    assert fps["range"] == {"min": 1.0, "max": 120.0, "step": 0.5}
    assert fps["constraints"] == ["within [1.0, 120.0] in steps of 0.5"]
    assert by_name["camera.encoding"]["choices"] == ["rgb8", "mono8", "bgr8"]
    assert by_name["robot_name"]["read_only"] is True
    assert by_name["serial"]["required"] is True
    assert by_name["topics"]["validators"] == [
        ["not_empty", None],
        ["unique", None],
        ["pattern", "^/"],
    ]
    assert len(described["hash"]) == 16


def test_mapped_groups_rules_and_a_second_class_merge(ros: RosHarness, tmp_path: Path) -> None:
    arm = load_generated(ROOT / "examples/arm/arm.yaml", tmp_path)
    motion = load_generated(ROOT / "examples/motion/motion.yaml", tmp_path)
    node = ros.node()
    arm.ArmParams.declare(node, prefix="left")
    first = latest_schema(ros, node)
    motion.MotionParams.declare(node, prefix="base")
    merged = latest_schema(ros, node)
    assert [c["prefix"] for c in merged["classes"]] == ["base", "left"]
    assert merged["hash"] != first["hash"]
    left = next(c for c in merged["classes"] if c["prefix"] == "left")
    assert left["maps"][0]["path"] == "left.gains"
    assert left["maps"][0]["for_each"] == "left.joints"
    assert [f["name"] for f in left["maps"][0]["fields"]] == ["i", "p"]
    base = next(c for c in merged["classes"] if c["prefix"] == "base")
    speed = next(r for r in base["rules"] if r["name"] == "speed_order")
    assert speed["check"] == "min_speed <= max_speed"
    assert speed["parameters"] == ["base.min_speed", "base.max_speed"]


def test_the_topic_can_be_turned_off(ros: RosHarness, tmp_path: Path) -> None:
    module = load_generated(ROOT / "examples/arm/arm.yaml", tmp_path)
    node = ros.node()
    module.ArmParams.declare(node, publish_schema=False)
    topics = [name for name, _ in node.get_publisher_names_and_types_by_node(node.get_name(), "/")]
    assert not any(name.endswith(SCHEMA_TOPIC_SUFFIX) for name in topics)


def test_the_assembled_text_is_the_sorted_json_of_the_message(
    ros: RosHarness, tmp_path: Path
) -> None:
    from genparams.runtime.node.schema_topic import SchemaPublisher

    arm = load_generated(ROOT / "examples/arm/arm.yaml", tmp_path)
    node = ros.node()
    arm.ArmParams.declare(node)
    arm.ArmParams.declare(node, prefix="right")
    text = SchemaPublisher.of(node).message_text()
    assert json.dumps(json.loads(text), sort_keys=True) == text


def test_a_destroyed_node_is_not_kept_alive(ros: RosHarness, tmp_path: Path) -> None:
    import gc
    import weakref

    arm = load_generated(ROOT / "examples/arm/arm.yaml", tmp_path)
    node = ros.node()
    arm.ArmParams.declare(node)
    alive = weakref.ref(node)
    del node
    ros.destroy_test_nodes()
    gc.collect()
    assert alive() is None


def test_the_message_is_sent_when_a_subscriber_first_asks(ros: RosHarness, tmp_path: Path) -> None:
    """Nothing is published at declare: a volatile subscriber (which a message published
    before it matched would never reach) still gets the first message, sent on its match."""
    module = load_generated(ROOT / "examples/arm/arm.yaml", tmp_path)
    node = ros.node()
    module.ArmParams.declare(node)
    topic = node.get_fully_qualified_name() + SCHEMA_TOPIC_SUFFIX
    assert topic in dict(node.get_topic_names_and_types())  # discoverable at once
    received: list[String] = []
    volatile = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE)
    subscription = ros.client_node.create_subscription(String, topic, received.append, volatile)
    try:
        deadline = time.monotonic() + 30.0
        while not received and time.monotonic() < deadline:
            ros.executor.spin_once(timeout_sec=0.05)
    finally:
        ros.client_node.destroy_subscription(subscription)
    (message,) = received
    assert [c["class"] for c in json.loads(message.data)["classes"]] == ["arm"]


STRING_ALONE = """
import sys
import rclpy
from rclpy.context import Context
from rclpy.node import Node
from genparams.runtime.node.schema_topic import SchemaPublisher, string_message_type
context = Context()
rclpy.init(context=context)
node = Node("string_alone", context=context)
publisher = SchemaPublisher.of(node)
print("std_msgs.msg" in sys.modules)
from std_msgs.msg import String
print(String is publisher.message_type is string_message_type())
node.destroy_node()
rclpy.shutdown(context=context)
"""


def test_the_publisher_loads_std_msgs_string_alone_and_shares_it() -> None:
    """Only String's module is loaded for the topic; std_msgs.msg, imported later, hands
    out the same class (a fresh process: this one imported std_msgs.msg already)."""
    result = subprocess.run(
        [sys.executable, "-c", STRING_ALONE],
        capture_output=True,
        text=True,
        timeout=WAIT_S,
        env=dict(os.environ),
        check=False,
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ["False", "True"]
