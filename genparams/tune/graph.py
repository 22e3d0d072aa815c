"""The live ROS graph as a tuning page and an audit see it: nodes, schemas, values, events.

One rclpy node of our own, spun by an executor in a background thread, does
everything ``ros2 param`` does: the parameter services of each node, the latched
``<node>/genparams/schema`` topics of self-describing nodes, and
``/parameter_events`` for changes made by anyone else. Calls return rclpy
Futures; :func:`wait_future` and the web app's bridge turn them into results.

A schema message is trusted only when it is well formed (read by
:mod:`~genparams.runtime.core.schema_message`) and every node that published on the
topic is the node the topic belongs to; otherwise the node gets a problem in
place of its schema, and the rest of the graph is unaffected.
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
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

from genparams.runtime.core.schema_message import SchemaProblem, read_schema_message
from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX
from genparams.tune.reader import (
    ParameterReader,
    answers,
    python_value,
    read_all,
    read_named,
)

LOG = logging.getLogger("genparams.tune")
SWEEP_SECONDS = 1.0
# A node asked for before discovery has told of it keeps its clients this long: a node
# started a moment ago may take seconds to appear on a loaded machine.
UNSEEN_GRACE_SECONDS = 60.0
SCHEMA_QOS = QoSProfile(
    depth=1,
    history=HistoryPolicy.KEEP_LAST,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)
EventListener = Callable[[dict[str, Any]], None]


NOT_IDENTIFIED = "published by a node not identified yet"  # DDS knows it, ROS not its name


@dataclass(frozen=True)
class Received:
    """The last message on a node's schema topic and who published on the topic then."""

    message: dict[str, Any] | SchemaProblem
    writers: tuple[tuple[bytes, str | None], ...]  # (endpoint gid, node name if known)


def publisher_node(info: Any) -> str | None:
    """The full name of a publisher's node, or None while discovery has not told it."""
    name, namespace = info.node_name, info.node_namespace
    if name.startswith("_NODE_NAME_UNKNOWN") or namespace.startswith("_NODE_NAMESPACE_UNKNOWN"):
        return None
    return f"{namespace.rstrip('/')}/{name}"


class Graph:
    """Our node in the ROS graph, spun in a background thread until :meth:`close`."""

    def __init__(self, node_name: str = "genparams_tune") -> None:
        self.context = Context()
        rclpy.init(context=self.context)
        self.node = Node(node_name, context=self.context, start_parameter_services=False)
        self.executor = MultiThreadedExecutor(num_threads=4, context=self.context)
        self.executor.add_node(self.node)
        self.lock = threading.Lock()
        self.closing = threading.Event()
        self.schemas: dict[str, Received] = {}  # node name -> what its schema topic carried
        self.subscribed: set[str] = set()
        self.schema_subscriptions: dict[str, Subscription] = {}
        self.absent: set[str] = set()  # nodes the last sweep found gone (see sweep)
        self.seen: set[str] = set()  # held nodes some sweep found in the graph
        self.asked: dict[str, float] = {}  # held node -> when its first client was made
        self.sweeps = 0  # sweeps done so far
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
        while self.context.ok() and not self.closing.is_set():
            try:
                self.executor.spin()
            except (ExternalShutdownException, ShutdownException):
                return
            except Exception:
                if not self.context.ok():
                    return  # shutdown while spinning ends the thread quietly
                LOG.exception("genparams tune: the ROS executor went on after an error")

    def close(self) -> None:
        """Stop spinning, then destroy: nothing is destroyed under the executor's wait."""
        self.closing.set()
        self.executor.shutdown(timeout_sec=1.0)
        self.thread.join(timeout=10.0)
        self.node.destroy_node()
        rclpy.shutdown(context=self.context)

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
            owner = topic[: -len(SCHEMA_TOPIC_SUFFIX)]

            def received(message: String, owner: str = owner) -> None:
                self.on_schema(owner, message)

            subscription = self.node.create_subscription(String, topic, received, SCHEMA_QOS)
            with self.lock:
                self.schema_subscriptions[topic] = subscription

    def sweep(self) -> None:
        """Let go of what nodes that left the graph held: service clients, schemas, topics.

        A node or topic gone at two sweeps in a row is gone (one sweep could race a
        client made for a node discovered meanwhile). A node not discovered yet is not
        gone: its clients stay until it has been seen (by a sweep, or when they were
        made), or for ``UNSEEN_GRACE_SECONDS``.
        Without this, every node name ever asked for would keep its clients, and node
        churn would grow the server.
        """
        present = set(self.node_names())
        now = time.monotonic()
        with self.lock:
            held = {*self.readers, *self.setters, *self.schemas}
            topics = list(self.schema_subscriptions)
            self.seen = (self.seen & held) | (present & held)
            seen, asked = set(self.seen), dict(self.asked)
        quiet = {t for t in topics if self.node.count_publishers(t) == 0}
        gone = {
            n
            for n in held
            if n not in present and (n in seen or now - asked.get(n, now) > UNSEEN_GRACE_SECONDS)
        }
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
                self.seen.discard(name)
                self.asked.pop(name, None)
        self.sweeps += 1

    def writers(self, node_name: str) -> dict[bytes, str | None]:
        """The publishers on a node's schema topic: endpoint gid -> node name (None: unknown)."""
        infos = self.node.get_publishers_info_by_topic(node_name + SCHEMA_TOPIC_SUFFIX)
        return {bytes(info.endpoint_gid): publisher_node(info) for info in infos}

    def on_schema(self, owner: str, message: String) -> None:
        """Keep the message of ``owner``'s topic, read but not yet trusted; never raises."""
        try:
            read = read_schema_message(message.data, owner)
            writers = tuple(self.writers(owner).items())
        except Exception as exc:  # a callback that raises would end the executor's thread
            read, writers = SchemaProblem(f"schema message cannot be read: {exc!r}"), ()
        with self.lock:
            self.schemas[owner] = Received(read, writers)
            self.asked.setdefault(owner, time.monotonic())
        self.dispatch({"kind": "schema", "node": owner})

    def schema_state(self, node_name: str) -> tuple[dict[str, Any] | None, str | None]:
        """(the node's schema, None) when trusted; (None, the problem) when not; or neither."""
        with self.lock:
            received = self.schemas.get(node_name)
        if received is None:
            return None, None
        if isinstance(received.message, SchemaProblem):
            return None, received.message.detail
        current = self.writers(node_name)
        for gid, known in (*received.writers, *current.items()):
            name = current.get(gid) or known
            if name is None and gid in current:
                return None, NOT_IDENTIFIED
            if name is None:
                return None, "published by a node that left before it was identified"
            if name != node_name:
                return None, f"{name}, not {node_name}, published on {node_name}'s schema topic"
        return received.message, None

    def schema(self, node_name: str) -> dict[str, Any] | None:
        """The node's schema message, when it is well formed and its own."""
        return self.schema_state(node_name)[0]

    def wait_for_schemas(self, names: Iterable[str], timeout: float) -> None:
        """Wait until each of ``names`` has published a schema its publishers can be told of.

        Each waits at most ``timeout``; a node whose publishers stay unidentified
        keeps that problem.
        """
        deadline = time.monotonic() + timeout
        pending = set(names)
        while pending and time.monotonic() < deadline:
            pending = {
                name
                for name in pending
                if name not in self.schemas or self.schema_state(name)[1] == NOT_IDENTIFIED
            }
            if pending:
                time.sleep(0.02)

    # Parameter services -------------------------------------------------------

    def setter(self, node_name: str) -> AsyncParameterClient:
        with self.lock:
            found = self.setters.get(node_name)
            if found is None:
                found = self.setters[node_name] = AsyncParameterClient(self.node, node_name)
                self.note_asked(node_name)
            return found

    def note_asked(self, node_name: str) -> None:
        """Remember when clients were first made for ``node_name``, and if it was there then."""
        self.asked.setdefault(node_name, time.monotonic())
        if node_name in self.node_names():
            self.seen.add(node_name)

    def reader(self, node_name: str) -> ParameterReader:
        with self.lock:
            found = self.readers.get(node_name)
            if found is None:
                found = self.readers[node_name] = ParameterReader(self.node, node_name)
                self.note_asked(node_name)
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

    def read_parameters(
        self, node_name: str, names: Sequence[str], timeout: float = 5.0
    ) -> tuple[list[str], list[dict[str, Any]]]:
        """Every name the node declares, and the parameters ``names`` in full."""
        return read_named(self.reader(node_name), names, timeout)

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
