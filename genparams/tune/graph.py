"""The live ROS graph as a tuning page and an audit see it: nodes, schemas, values, events.

One rclpy node of our own, spun by an executor in a background thread, does
everything ``ros2 param`` does: the parameter services of each node, the latched
``<node>/genparams/schema`` topics of self-describing nodes, and
``/parameter_events`` for changes made by anyone else. Calls return rclpy
Futures; :func:`wait_future` and the web app's bridge turn them into results.
"""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Callable, Iterable
from typing import Any

import rclpy
from rcl_interfaces.msg import ParameterEvent, ParameterType, ParameterValue
from rclpy.context import Context
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter, parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from rclpy.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_parameter_events,
)
from rclpy.task import Future
from std_msgs.msg import String

from genparams.runtime.schema_topic import SCHEMA_TOPIC_SUFFIX

SCHEMA_QOS = QoSProfile(
    depth=1,
    history=HistoryPolicy.KEEP_LAST,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)
TYPE_NAMES = {
    ParameterType.PARAMETER_BOOL: "bool",
    ParameterType.PARAMETER_INTEGER: "int",
    ParameterType.PARAMETER_DOUBLE: "double",
    ParameterType.PARAMETER_STRING: "string",
    ParameterType.PARAMETER_BYTE_ARRAY: "byte_array",
    ParameterType.PARAMETER_BOOL_ARRAY: "bool_array",
    ParameterType.PARAMETER_INTEGER_ARRAY: "int_array",
    ParameterType.PARAMETER_DOUBLE_ARRAY: "double_array",
    ParameterType.PARAMETER_STRING_ARRAY: "string_array",
}
ROS_TYPES = {name: ros_type for ros_type, name in TYPE_NAMES.items()}
EventListener = Callable[[dict[str, Any]], None]


def python_value(value: ParameterValue) -> Any:
    """A ParameterValue as JSON-ready Python: arrays as lists, bytes as ints."""
    plain = parameter_value_to_python(value)
    if value.type == ParameterType.PARAMETER_BYTE_ARRAY:
        return [b if isinstance(b, int) else ord(b) for b in plain]
    if isinstance(plain, Iterable) and not isinstance(plain, str):
        return list(plain)
    return plain


def ros_parameter(name: str, type_name: str, value: Any) -> Parameter:
    """A JSON value as an rclpy Parameter of the given schema type (never inferred)."""
    ros_type = Parameter.Type(ROS_TYPES[type_name])
    if type_name == "byte_array":
        value = [bytes((int(b),)) for b in value]
    elif type_name == "double":
        value = float(value)
    elif type_name == "double_array":
        value = [float(v) for v in value]
    return Parameter(name, ros_type, value)


def wait_future(future: Future, timeout: float) -> Any:
    """Block a thread other than the executor's until ``future`` is done."""
    done = threading.Event()
    future.add_done_callback(lambda _: done.set())
    if not done.wait(timeout):
        future.cancel()
        raise TimeoutError("no answer from the node's parameter services")
    return future.result()


class Graph:
    """Our node in the ROS graph, spun in a background thread until :meth:`close`."""

    def __init__(self, node_name: str = "genparams_tune") -> None:
        self.context = Context()
        rclpy.init(context=self.context)
        self.node = Node(node_name, context=self.context, start_parameter_services=False)
        self.executor = MultiThreadedExecutor(num_threads=4, context=self.context)
        self.executor.add_node(self.node)
        self.lock = threading.Lock()
        self.schemas: dict[str, dict[str, Any]] = {}  # node name -> its schema message
        self.schema_times: dict[str, float] = {}
        self.subscribed: set[str] = set()
        self.clients: dict[str, AsyncParameterClient] = {}
        self.listeners: list[EventListener] = []
        self.node.create_subscription(
            ParameterEvent, "/parameter_events", self.on_event, qos_profile_parameter_events
        )
        self.node.create_timer(0.25, self.watch_schema_topics)
        self.thread = threading.Thread(target=self.spin, name="genparams-graph", daemon=True)
        self.thread.start()

    def spin(self) -> None:
        try:
            self.executor.spin()
        except Exception:  # shutdown while spinning ends the thread quietly
            pass

    def close(self) -> None:
        self.executor.shutdown(timeout_sec=1.0)
        self.node.destroy_node()
        rclpy.shutdown(context=self.context)
        self.thread.join(timeout=2.0)

    # The graph ---------------------------------------------------------------

    def node_names(self) -> list[str]:
        own = self.node.get_fully_qualified_name()
        found = {
            f"{namespace.rstrip('/')}/{name}"
            for name, namespace in self.node.get_node_names_and_namespaces()
        }
        return sorted(found - {own})

    def watch_schema_topics(self) -> None:
        """Subscribe to every schema topic that appeared; the latched message follows."""
        for topic, types in self.node.get_topic_names_and_types():
            if not topic.endswith(SCHEMA_TOPIC_SUFFIX) or "std_msgs/msg/String" not in types:
                continue
            with self.lock:
                if topic in self.subscribed:
                    continue
                self.subscribed.add(topic)
            self.node.create_subscription(String, topic, self.on_schema, SCHEMA_QOS)

    def on_schema(self, message: String) -> None:
        try:
            schema = json.loads(message.data)
            name = schema["node"]
        except (ValueError, KeyError, TypeError):
            return  # not ours: a stray publisher on a look-alike topic
        with self.lock:
            self.schemas[name] = schema
            self.schema_times[name] = time.monotonic()
        self.dispatch({"kind": "schema", "node": name})

    def schema(self, node_name: str) -> dict[str, Any] | None:
        with self.lock:
            return self.schemas.get(node_name)

    def wait_for_schemas(self, names: Iterable[str], timeout: float) -> None:
        """Wait until each of ``names`` has published its schema, or ``timeout`` passed."""
        deadline = time.monotonic() + timeout
        wanted = set(names)
        while time.monotonic() < deadline:
            with self.lock:
                if wanted <= self.schemas.keys():
                    return
            time.sleep(0.02)

    # Parameter services -------------------------------------------------------

    def client(self, node_name: str) -> AsyncParameterClient:
        with self.lock:
            found = self.clients.get(node_name)
            if found is None:
                found = self.clients[node_name] = AsyncParameterClient(self.node, node_name)
            return found

    def services_ready(self, node_name: str, timeout: float) -> bool:
        return bool(self.client(node_name).wait_for_services(timeout_sec=timeout))

    def read_node(self, node_name: str, timeout: float = 5.0) -> list[dict[str, Any]]:
        """Every parameter of a node: name, type, value and descriptor, as JSON-ready dicts."""
        client = self.client(node_name)
        if not client.wait_for_services(timeout_sec=timeout):
            raise TimeoutError(f"{node_name}: parameter services did not appear")
        listed = wait_future(client.list_parameters([], 0), timeout)
        names = sorted(listed.result.names)
        values = wait_future(client.get_parameters(names), timeout).values
        descriptors = wait_future(client.describe_parameters(names), timeout).descriptors
        return [
            {
                "name": name,
                "type": TYPE_NAMES.get(value.type, "unset"),
                "value": python_value(value),
                "read_only": descriptor.read_only,
                "description": descriptor.description,
                "constraints": descriptor.additional_constraints,
                "range": descriptor_range(descriptor),
            }
            for name, value, descriptor in zip(names, values, descriptors, strict=True)
        ]

    def set_parameters(
        self, node_name: str, parameters: list[Parameter], atomic: bool, timeout: float = 5.0
    ) -> list[dict[str, Any]]:
        """Set through the node's services; one result per parameter (atomic: the same one)."""
        client = self.client(node_name)
        if atomic:
            result = wait_future(client.set_parameters_atomically(parameters), timeout).result
            results = [result] * len(parameters)
        else:
            results = wait_future(client.set_parameters(parameters), timeout).results
        return [
            {"name": p.name, "successful": r.successful, "reason": r.reason}
            for p, r in zip(parameters, results, strict=True)
        ]

    # /parameter_events ---------------------------------------------------------

    def subscribe(self, listener: EventListener) -> Callable[[], None]:
        with self.lock:
            self.listeners.append(listener)

        def unsubscribe() -> None:
            with self.lock:
                if listener in self.listeners:
                    self.listeners.remove(listener)

        return unsubscribe

    def on_event(self, event: ParameterEvent) -> None:
        def values(parameters: Iterable[Any]) -> dict[str, Any]:
            return {p.name: python_value(p.value) for p in parameters}

        self.dispatch(
            {
                "kind": "parameters",
                "node": event.node,
                "new": values(event.new_parameters),
                "changed": values(event.changed_parameters),
                "deleted": [p.name for p in event.deleted_parameters],
            }
        )

    def dispatch(self, event: dict[str, Any]) -> None:
        with self.lock:
            listeners = tuple(self.listeners)
        for listener in listeners:
            listener(event)


def descriptor_range(descriptor: Any) -> dict[str, Any] | None:
    for ranges in (descriptor.integer_range, descriptor.floating_point_range):
        if ranges:
            first = ranges[0]
            return {"min": first.from_value, "max": first.to_value, "step": first.step}
    return None
