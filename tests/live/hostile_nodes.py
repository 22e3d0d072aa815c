"""Nodes that misbehave on the parameter services and topics, in a process of their own.

``python -m tests.live.hostile_nodes NAME:KIND[:ARG] ...`` starts one node per argument
and prints "ready". The first four publish a schema message of no class, so the audit reads
them. Kinds:

- ``short_describe``: describe_parameters answers one descriptor for two names.
- ``type42``: get_parameters answers a value of type 42.
- ``huge``: list_parameters answers 100,001 names.
- ``deep``: list_parameters answers a name 100 segments deep.
- ``ghosts:N``: publishes schema topics of N nodes that do not exist.
- ``forger:TARGET``: publishes ``ParameterEvent(node=TARGET, gain=9.5)`` five times a second.
- ``slow:SECONDS:FILE``: declares ``counter`` (an int); its on-set callback takes SECONDS and
  writes how many times it ran to FILE.
- ``gated:DIR``: declares ``counter`` (an int); its on-set callback for the value V waits
  until the file DIR/release_V exists, writes how many times it ran to DIR/count, and
  refuses 13 (``13 is unlucky``); when DIR/leave_V appears first, the node leaves the graph
  without answering.
- ``gated_short:DIR``: declares ``counter``; its set_parameters service (not the atomic
  one) waits for DIR/release_V as ``gated`` does, then answers two results for one value.
- ``plain``: a plain node with ``gain`` (a double): for names of one's choosing (hidden ones).
- ``dotted``: a plain node declaring ``a``, ``a.b`` and ``a.b.c``.
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path
from typing import Any

import rclpy
from rcl_interfaces.msg import Parameter as ParameterMsg
from rcl_interfaces.msg import (
    ParameterDescriptor,
    ParameterEvent,
    ParameterType,
    ParameterValue,
    SetParametersResult,
)
from rcl_interfaces.srv import DescribeParameters, GetParameters, ListParameters, SetParameters
from rclpy.node import Node
from rclpy.parameter_service import ParameterService
from rclpy.qos import qos_profile_parameters
from std_msgs.msg import String

from genparams.live.schema_topics import SCHEMA_QOS
from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX
from tests.node_process import serve

FORGED_GAIN = 9.5


def lying_node(name: str, names: list[str], bad_get: bool, short_describe: bool) -> Node:
    """A node whose parameter services answer as told: names listed, values, descriptors."""
    node = Node(name, start_parameter_services=False)

    def listing(request: Any, response: Any) -> Any:
        response.result.names = names
        return response

    def getting(request: Any, response: Any) -> Any:
        kind = 42 if bad_get else ParameterType.PARAMETER_DOUBLE
        response.values = [ParameterValue(type=kind, double_value=1.0) for _ in request.names]
        return response

    def describing(request: Any, response: Any) -> Any:
        count = max(0, len(request.names) - 1) if short_describe else len(request.names)
        response.descriptors = [ParameterDescriptor(name=n) for n in request.names[:count]]
        return response

    node.create_service(ListParameters, "~/list_parameters", listing)
    node.create_service(GetParameters, "~/get_parameters", getting)
    node.create_service(DescribeParameters, "~/describe_parameters", describing)
    # A schema of no class, well formed: the audit reads every node that publishes one.
    schema = {"format": 1, "node": f"/{name}", "genparams": "1", "hash": "h", "classes": []}
    publisher = node.create_publisher(String, f"~{SCHEMA_TOPIC_SUFFIX}", SCHEMA_QOS)
    publisher.publish(String(data=json.dumps(schema)))
    return node


def ghosts(name: str, count: int) -> Node:
    node = Node(name)
    node.keep = [  # type: ignore[attr-defined]
        node.create_publisher(String, f"/{name}_ghost_{i}{SCHEMA_TOPIC_SUFFIX}", SCHEMA_QOS)
        for i in range(count)
    ]
    for publisher in node.keep:  # type: ignore[attr-defined]
        publisher.publish(String(data='{"format": 1}'))
    return node


def forger(name: str, target: str) -> Node:
    node = Node(name)
    publisher = node.create_publisher(ParameterEvent, "/parameter_events", 10)
    forged = ParameterMsg(
        name="gain",
        value=ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=FORGED_GAIN),
    )

    def publish() -> None:
        publisher.publish(ParameterEvent(node=target, changed_parameters=[forged]))

    node.create_timer(0.2, publish)
    return node


def slow(name: str, seconds: float, count_file: Path) -> Node:
    node = Node(name)
    node.declare_parameter("counter", 0)
    calls = [0]

    def on_set(parameters: list[Any]) -> SetParametersResult:
        calls[0] += 1
        count_file.write_text(str(calls[0]), encoding="utf-8")
        end = time.monotonic() + seconds
        while time.monotonic() < end and node.context.ok():  # a stop ends the wait
            time.sleep(0.05)
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(on_set)
    return node


def gated(name: str, workdir: Path) -> Node:
    """A node whose on-set callback takes as long as the test wants: until DIR/release_V."""
    node = Node(name)
    node.declare_parameter("counter", 0)
    calls = [0]

    def on_set(parameters: list[Any]) -> SetParametersResult:
        calls[0] += 1
        (workdir / "count").write_text(str(calls[0]), encoding="utf-8")
        values = [p.value for p in parameters]
        gates = [workdir / f"release_{value}" for value in values]
        leave = [workdir / f"leave_{value}" for value in values]
        left: list[bool] = []
        while not all(gate.exists() for gate in gates) and node.context.ok():  # a stop ends it
            if not left and any(gate.exists() for gate in leave):
                node.destroy_node()  # leaves the graph, never to answer (until the stop)
                left.append(True)
            time.sleep(0.05)
        if 13 in values:
            return SetParametersResult(successful=False, reason="13 is unlucky")
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(on_set)
    return node


def gated_short(name: str, workdir: Path) -> Node:
    """rclpy's parameter services, but a set answered late and unusably (two results for one)."""
    node = Node(name, start_parameter_services=False)
    node.declare_parameter("counter", 0)
    ParameterService(node)
    service = f"{name}/set_parameters"  # rclpy's own, named relative to the node
    node.destroy_service(next(s for s in node.services if s.srv_name == service))

    def setting(request: Any, response: Any) -> Any:
        gates = [workdir / f"release_{p.value.integer_value}" for p in request.parameters]
        while not all(gate.exists() for gate in gates) and node.context.ok():  # a stop ends it
            time.sleep(0.05)
        response.results = [SetParametersResult(successful=True)] * (len(gates) + 1)
        return response

    node.create_service(SetParameters, service, setting, qos_profile=qos_profile_parameters)
    return node


def plain(name: str) -> Node:
    node = Node(name)
    node.declare_parameter("gain", 1.5)
    return node


def dotted(name: str) -> Node:
    """A plain node declaring ``a`` and ``a.b``: a name below another's value."""
    node = Node(name)
    node.declare_parameter("a", 1.0)
    node.declare_parameter("a.b", 2.0)
    node.declare_parameter("a.b.c", "three")
    return node


def make(spec: str) -> Node:
    name, _, rest = spec.partition(":")
    kind, _, arg = rest.partition(":")
    if kind == "short_describe":
        return lying_node(name, ["a", "b"], bad_get=False, short_describe=True)
    if kind == "type42":
        return lying_node(name, ["a", "b"], bad_get=True, short_describe=False)
    if kind == "huge":
        return lying_node(name, [f"p{i}" for i in range(100_001)], False, False)
    if kind == "deep":
        return lying_node(name, [".".join(["d"] * 100)], bad_get=False, short_describe=False)
    if kind == "ghosts":
        return ghosts(name, int(arg))
    if kind == "forger":
        return forger(name, arg)
    if kind == "slow":
        seconds, _, path = arg.partition(":")
        return slow(name, float(seconds), Path(path))
    if kind == "gated":
        return gated(name, Path(arg))
    if kind == "gated_short":
        return gated_short(name, Path(arg))
    if kind == "plain":
        return plain(name)
    if kind == "dotted":
        return dotted(name)
    raise SystemExit(f"unknown kind {kind!r}")


def main(argv: list[str]) -> int:
    rclpy.init()
    return serve([make(spec) for spec in argv])


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
