"""What ``declare`` adds to a node: its parameters, one publisher (the schema message) and
one on-set callback; no pre-set callback, subscription, service, client or timer."""

from __future__ import annotations

import time
import types
from typing import Any

import pytest
from rclpy.node import Node

from genparams.runtime.node.schema_topic import SCHEMA_TOPIC
from tests.patience import WAIT_S
from tests.runtime.schemas import generate
from tests.support import RosHarness

SCHEMA = """\
genparams: 1
name: entities
parameters:
  rate: {type: double, default: 10.0, aliases: [hz]}
  joints: {type: string_array, default: [a]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0}
"""
OTHER = """\
genparams: 1
name: other
parameters:
  mode: {type: string, default: eco}
"""


def entities(node: Node) -> dict[str, Any]:
    return {
        "publishers": sorted(p.topic_name for p in node.publishers),
        "subscriptions": sorted(s.topic_name for s in node.subscriptions),
        "services": sorted(s.srv_name for s in node.services),
        "clients": sorted(c.srv_name for c in node.clients),
        "timers": len(list(node.timers)),
        "guards": len(list(node.guards)),
        "pre-set": len(node._pre_set_parameters_callbacks),
        "on-set": len(node._on_set_parameters_callbacks),
        "post-set": len(node._post_set_parameters_callbacks),
    }


def publishers_once_spun(ros: RosHarness, node: Node, count: int) -> list[str]:
    """The node's publishers, once it has ``count`` (a publisher may be made on first need)."""
    deadline = time.monotonic() + WAIT_S
    while len(list(node.publishers)) < count and time.monotonic() < deadline:
        ros.executor.spin_once(timeout_sec=0.1)
    return sorted(p.topic_name for p in node.publishers)


@pytest.fixture(scope="module")
def modules(tmp_path_factory: pytest.TempPathFactory) -> tuple[types.ModuleType, ...]:
    folder = tmp_path_factory.mktemp("entities")
    return generate(folder, SCHEMA, "entities"), generate(folder, OTHER, "other")


def test_declare_adds_one_publisher_and_one_on_set_callback(
    ros: RosHarness, modules: tuple[types.ModuleType, ...]
) -> None:
    entities_module, other_module = modules
    node = ros.node()
    before = entities(node)
    plain_parameters = set(node._parameters)
    entities_module.EntitiesParams.declare(node)
    other_module.OtherParams.declare(node, prefix="other")
    schema_topic = f"{node.get_fully_qualified_name()}/genparams/schema"
    assert SCHEMA_TOPIC == "~/genparams/schema"
    published = publishers_once_spun(ros, node, len(before["publishers"]) + 1)
    assert published == sorted([*before["publishers"], schema_topic])
    after = entities(node)
    after["publishers"] = published
    assert after == {**before, "publishers": published, "on-set": before["on-set"] + 1}
    added = set(node._parameters) - plain_parameters
    assert added == {"rate", "hz", "joints", "gains.a.p", "other.mode"}


def test_without_the_schema_message_no_publisher_is_added(
    ros: RosHarness, modules: tuple[types.ModuleType, ...]
) -> None:
    node = ros.node()
    before = entities(node)
    modules[0].EntitiesParams.declare(node, publish_schema=False)
    assert entities(node) == {**before, "on-set": before["on-set"] + 1}
