"""The latched ``<node>/genparams/schema`` topics: followed for nodes that exist, believed from
their own node only.

A schema message is trusted when it is well formed (read by
:mod:`~genparams.runtime.core.schema_message`, whose compile costs every pattern before
any engine compiles it), every node that published on the topic is the
node the topic belongs to, and no other node in the graph has that name: a second
node of the same name could publish in its place, so two nodes claiming one name
leave neither a schema. Otherwise the node gets a problem in place of its schema,
and the rest of the graph is unaffected.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from rclpy.node import Node
from rclpy.subscription import Subscription
from std_msgs.msg import String

from genparams.runtime.core.schema_message import SchemaProblem, read_schema_message
from genparams.runtime.node.schema_topic import SCHEMA_TOPIC_SUFFIX, schema_qos

SCHEMA_QOS = schema_qos()
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


class SchemaTopics:
    """The schema topics of the nodes in the graph, seen from ``node``."""

    def __init__(
        self,
        node: Node,
        lock: threading.Lock,
        node_names: Callable[[], list[str]],
        claimants: Callable[[str], int],
        arrived: Callable[[str], None],
    ) -> None:
        self.node = node
        self.lock = lock
        self.node_names = node_names
        self.claimants = claimants  # how many nodes in the graph have a name
        self.arrived = arrived
        self.schemas: dict[str, Received] = {}  # node name -> what its schema topic carried
        self.subscriptions: dict[str, Subscription] = {}  # topic -> its subscription
        self.quiet: set[str] = set()  # topics the last sweep found without a publisher

    def watch(self) -> None:
        """Subscribe to the schema topic of every node in the graph; the latched message follows.

        A topic whose node is not in the graph is not followed: a process could own
        any number of them.
        """
        present = set(self.node_names())
        for topic, types in self.node.get_topic_names_and_types():
            if not topic.endswith(SCHEMA_TOPIC_SUFFIX) or "std_msgs/msg/String" not in types:
                continue
            owner = topic[: -len(SCHEMA_TOPIC_SUFFIX)]
            with self.lock:
                if topic in self.subscriptions or owner not in present:
                    continue

            def received(message: String, owner: str = owner) -> None:
                self.on_schema(owner, message)

            subscription = self.node.create_subscription(String, topic, received, SCHEMA_QOS)
            with self.lock:
                self.subscriptions[topic] = subscription

    def sweep(self, gone_nodes: set[str]) -> None:
        """Let go of the topics without a publisher at two sweeps, and of nodes gone."""
        present = set(self.node_names())
        with self.lock:
            topics = list(self.subscriptions)
        quiet = {
            t
            for t in topics
            if self.node.count_publishers(t) == 0 or t[: -len(SCHEMA_TOPIC_SUFFIX)] not in present
        }
        gone, self.quiet = quiet & self.quiet, quiet
        gone |= self.outlived(topics)
        for topic in gone:
            with self.lock:
                subscription = self.subscriptions.pop(topic)
                self.schemas.pop(topic[: -len(SCHEMA_TOPIC_SUFFIX)], None)
            self.node.destroy_subscription(subscription)
        with self.lock:
            for name in gone_nodes:
                self.schemas.pop(name, None)

    def outlived(self, topics: list[str]) -> set[str]:
        """Topics whose message came while a publisher now gone was on them: which of the
        publishers sent it cannot be told, so it is read again from those left (latched)."""
        with self.lock:
            received = {t: self.schemas.get(t[: -len(SCHEMA_TOPIC_SUFFIX)]) for t in topics}
        again = set()
        for topic, message in received.items():
            if message is None or len(message.writers) < 2:
                continue
            current = self.writers(topic[: -len(SCHEMA_TOPIC_SUFFIX)])
            if current and not {gid for gid, _ in message.writers} <= set(current):
                again.add(topic)
        return again

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
        self.arrived(owner)

    def held(self) -> set[str]:
        with self.lock:
            return set(self.schemas)

    def state(self, node_name: str) -> tuple[dict[str, Any] | None, str | None]:
        """(the node's schema, None) when trusted; (None, the problem) when not; or neither."""
        claimants = self.claimants(node_name)
        if claimants > 1:
            return None, f"{claimants} nodes in the graph have the name {node_name}: none believed"
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
        if len({gid for gid, _ in received.writers} | set(current)) > 1:
            return None, f"more than one publisher on {node_name}'s schema topic"
        return received.message, None

    def wait(self, names: set[str], timeout: float) -> None:
        """Wait until each of ``names`` has published a schema its publishers can be told of.

        Each waits at most ``timeout``; a node whose publishers stay unidentified
        keeps that problem.
        """
        deadline = time.monotonic() + timeout
        pending = set(names)
        while pending and time.monotonic() < deadline:
            held = self.held()
            pending = {n for n in pending if n not in held or self.state(n)[1] == NOT_IDENTIFIED}
            if pending:
                time.sleep(0.02)
