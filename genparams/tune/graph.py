"""The live ROS graph as a tuning page and an audit see it: nodes, schemas, values, events.

One rclpy node of our own, spun by an executor in a background thread, does
everything ``ros2 param`` does: the parameter services of each node, the latched
``<node>/genparams/schema`` topics of self-describing nodes, and
``/parameter_events`` for changes made by anyone else. Calls return rclpy
Futures; :func:`wait_future` and the web app's bridge turn them into results.
"""

from __future__ import annotations

import json
import logging
import threading
import time
from collections.abc import Callable, Iterable, Sequence
from typing import Any

import rclpy
from rcl_interfaces.msg import ParameterEvent
from rclpy.client import Client
from rclpy.context import Context
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor, ShutdownException
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient
from rclpy.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_parameter_events,
)
from rclpy.subscription import Subscription
from std_msgs.msg import String

from genparams.runtime.schema_topic import SCHEMA_TOPIC_SUFFIX
from genparams.tune.reader import (
    TYPE_NAMES,
    ParameterReader,
    answers,
    python_value,
    read_all,
)

LOG = logging.getLogger("genparams.tune")
SWEEP_SECONDS = 1.0
SCHEMA_QOS = QoSProfile(
    depth=1,
    history=HistoryPolicy.KEEP_LAST,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)
ROS_TYPES = {name: ros_type for ros_type, name in TYPE_NAMES.items()}
EventListener = Callable[[dict[str, Any]], None]


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
        self.schema_subscriptions: dict[str, Subscription] = {}
        self.absent: set[str] = set()  # nodes the last sweep found gone (see sweep)
        self.quiet: set[str] = set()  # schema topics it found without a publisher
        self.readers: dict[str, ParameterReader] = {}
        self.setters: dict[str, AsyncParameterClient] = {}
        self.listeners: list[EventListener] = []
        self.node.create_subscription(
            ParameterEvent, "/parameter_events", self.on_event, qos_profile_parameter_events
        )
        self.node.create_timer(0.25, self.watch_schema_topics)
        self.node.create_timer(SWEEP_SECONDS, self.sweep)
        self.thread = threading.Thread(target=self.spin, name="genparams-graph", daemon=True)
        self.thread.start()

    def spin(self) -> None:
        """Spin until :meth:`close`; a callback's error is logged and spinning goes on.

        One bad message or a race inside rclpy must not end the thread that answers
        every page and audit.
        """
        while self.context.ok():
            try:
                self.executor.spin()
            except (ExternalShutdownException, ShutdownException):
                return
            except Exception:
                if not self.context.ok():
                    return  # shutdown while spinning ends the thread quietly
                LOG.exception("genparams tune: the ROS executor went on after an error")

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
            subscription = self.node.create_subscription(String, topic, self.on_schema, SCHEMA_QOS)
            with self.lock:
                self.schema_subscriptions[topic] = subscription

    def sweep(self) -> None:
        """Let go of what nodes that left the graph held: service clients, schemas, topics.

        A node or topic gone at two sweeps in a row is gone (one sweep could race a
        client made for a node discovered meanwhile). Without this, every node name
        ever asked for would keep its clients, and node churn would grow the server.
        """
        present = set(self.node_names())
        with self.lock:
            held = {*self.readers, *self.setters, *self.schemas}
            topics = list(self.schema_subscriptions)
        quiet = {t for t in topics if self.node.count_publishers(t) == 0}
        gone = {n for n in held if n not in present}
        gone_nodes, self.absent = gone & self.absent, gone
        gone_topics, self.quiet = quiet & self.quiet, quiet
        for topic in gone_topics:
            with self.lock:
                subscription = self.schema_subscriptions.pop(topic)
                self.subscribed.discard(topic)
            self.node.destroy_subscription(subscription)
        for name in gone_nodes:
            self.forget(name)
            with self.lock:
                self.schemas.pop(name, None)
                self.schema_times.pop(name, None)

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

    def setter(self, node_name: str) -> AsyncParameterClient:
        with self.lock:
            found = self.setters.get(node_name)
            if found is None:
                found = self.setters[node_name] = AsyncParameterClient(self.node, node_name)
            return found

    def reader(self, node_name: str) -> ParameterReader:
        with self.lock:
            found = self.readers.get(node_name)
            if found is None:
                found = self.readers[node_name] = ParameterReader(self.node, node_name)
            return found

    def forget(self, node_name: str) -> None:
        """Destroy the service clients of ``node_name``.

        Every client is an entity the executor waits on at each wake-up and DDS
        matches against every new endpoint: an audit of many nodes reads a few at
        a time and lets their clients go.
        """
        with self.lock:
            reader = self.readers.pop(node_name, None)
            setter = self.setters.pop(node_name, None)
        if reader is not None:
            reader.destroy()
        if setter is not None:
            for attribute in vars(setter).values():
                if isinstance(attribute, Client):
                    self.node.destroy_client(attribute)

    def services_ready(self, node_name: str, timeout: float) -> bool:
        return self.reader(node_name).wait_ready(timeout)

    def read_node(self, node_name: str, timeout: float = 5.0) -> list[dict[str, Any]]:
        """Every parameter of a node: name, type, value and descriptor, as JSON-ready dicts."""
        return self.read_nodes([node_name], timeout)[node_name]

    def read_nodes(
        self, node_names: Sequence[str], timeout: float = 5.0
    ) -> dict[str, list[dict[str, Any]]]:
        return read_all([self.reader(name) for name in node_names], timeout)

    def set_parameters(
        self, node_name: str, parameters: list[Parameter], atomic: bool, timeout: float = 5.0
    ) -> list[dict[str, Any]]:
        """Set through the node's services; one result per parameter (atomic: the same one)."""
        client = self.setter(node_name)
        if not client.services_are_ready():
            deadline = time.monotonic() + timeout
            while not client.services_are_ready():  # rclpy's own wait sleeps 0.25 s steps
                if time.monotonic() > deadline:
                    raise TimeoutError(f"{node_name}: parameter services did not appear")
                time.sleep(0.005)
        if atomic:
            sent = answers([lambda: client.set_parameters_atomically(parameters)], timeout)
            results = [sent[0].result] * len(parameters)
        else:
            results = answers([lambda: client.set_parameters(parameters)], timeout)[0].results
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
