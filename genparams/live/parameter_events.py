"""``/parameter_events`` as a hint only: what listeners get is what the node holds.

Any node can publish ``ParameterEvent(node=/camera, gain=9.5)``, and a message does
not tell who sent it. So an event is taken as "these names of that node changed":
the names are read from the node over its ``get_parameters`` service, and listeners
get the values the node answered. Reads go out from the executor without blocking
it, one at a time per node; a flood of events queues at most ``MAX_QUEUED_READS``
reads of at most ``MAX_EVENT_NAMES`` names per node, and only for nodes in the graph.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any

from rcl_interfaces.msg import ParameterEvent
from rclpy.node import Node
from rclpy.qos import qos_profile_parameter_events
from rclpy.task import Future

from genparams.live.answers import NOT_SET, NodeAnswerError, checked_values, python_value
from genparams.live.services import ParameterReader

EventListener = Callable[[dict[str, Any]], None]
MAX_EVENT_NAMES = 1_000
MAX_QUEUED_READS = 64
READ_SECONDS = 5.0  # a read not answered in this long is given up and the next one sent


@dataclass
class Wanted:
    """Names an event told of: those it said new, changed and deleted."""

    new: set[str] = field(default_factory=set)
    changed: set[str] = field(default_factory=set)
    deleted: set[str] = field(default_factory=set)

    @property
    def names(self) -> list[str]:
        return sorted(self.new | self.changed | self.deleted)

    def merge(self, other: Wanted) -> None:
        self.new |= other.new
        self.changed |= other.changed
        self.deleted |= other.deleted


@dataclass
class NodeReads:
    queued: list[Wanted] = field(default_factory=list)
    sent: float | None = None  # when the read in flight went out


class EventRelay:
    """Listeners of the parameter events of the graph, each value read from its node."""

    def __init__(
        self,
        node: Node,
        reader: Callable[[str], ParameterReader],
        present: Callable[[str], bool],
    ) -> None:
        self.node = node
        self.reader = reader
        self.present = present
        self.lock = threading.Lock()
        self.listeners: list[EventListener] = []
        self.reads: dict[str, NodeReads] = {}
        node.create_subscription(
            ParameterEvent, "/parameter_events", self.on_event, qos_profile_parameter_events
        )

    def subscribe(self, listener: EventListener) -> Callable[[], None]:
        with self.lock:
            self.listeners.append(listener)

        def unsubscribe() -> None:
            with self.lock:
                if listener in self.listeners:
                    self.listeners.remove(listener)

        return unsubscribe

    def dispatch(self, event: dict[str, Any]) -> None:
        with self.lock:
            listeners = tuple(self.listeners)
        for listener in listeners:
            listener(event)

    def on_event(self, event: ParameterEvent) -> None:
        """Queue a read of the names ``event`` tells of; never raises (the executor's thread)."""
        with self.lock:
            if not self.listeners:
                return
        wanted = Wanted(
            {p.name for p in event.new_parameters},
            {p.name for p in event.changed_parameters},
            {p.name for p in event.deleted_parameters},
        )
        node = event.node
        if not wanted.names or len(wanted.names) > MAX_EVENT_NAMES or not self.present(node):
            return
        with self.lock:
            reads = self.reads.setdefault(node, NodeReads())
            if len(reads.queued) >= MAX_QUEUED_READS:
                reads.queued[-1].merge(wanted)
            else:
                reads.queued.append(wanted)
            start = reads.sent is None
        if start:
            self.send(node)

    def send(self, node: str) -> None:
        with self.lock:
            reads = self.reads.get(node)
            if reads is None or not reads.queued:
                self.reads.pop(node, None)
                return
            wanted = reads.queued[0]
            reads.sent = time.monotonic()
        names = wanted.names
        try:
            future = self.reader(node).get_call(names)()
        except Exception:  # the node's clients were let go meanwhile: the read is dropped
            self.finish(node)
            return
        future.add_done_callback(lambda done: self.answered(node, wanted, names, done))

    def answered(self, node: str, wanted: Wanted, names: list[str], future: Future) -> None:
        try:
            values = checked_values(node, names, future.result().values)
        except (NodeAnswerError, AttributeError, Exception):  # any answer: a dropped event
            values = None
        with self.lock:
            reads = self.reads.get(node)
            current = reads is not None and reads.queued and reads.queued[0] is wanted
        if not current:
            return  # given up by the sweep meanwhile
        if values is not None:
            self.dispatch(held_event(node, wanted, names, values))
        self.finish(node)

    def finish(self, node: str) -> None:
        with self.lock:
            reads = self.reads.get(node)
            if reads is not None and reads.queued:
                reads.queued.pop(0)
                reads.sent = None
        self.send(node)

    def sweep(self, gone: Iterable[str]) -> None:
        """Give up reads unanswered for ``READ_SECONDS``; forget the nodes ``gone``."""
        now = time.monotonic()
        with self.lock:
            for name in gone:
                self.reads.pop(name, None)
            late = [n for n, r in self.reads.items() if r.sent and now - r.sent > READ_SECONDS]
        for node in late:
            self.finish(node)


def held_event(node: str, wanted: Wanted, names: list[str], values: list[Any]) -> dict[str, Any]:
    """The event listeners get: each name with the value the node holds (unset: deleted)."""
    new: dict[str, Any] = {}
    changed: dict[str, Any] = {}
    deleted: list[str] = []
    for name, value in zip(names, values, strict=True):
        if value.type == NOT_SET:
            if name in wanted.deleted:
                deleted.append(name)
            continue
        (new if name in wanted.new else changed)[name] = python_value(value)
    return {"kind": "parameters", "node": node, "new": new, "changed": changed, "deleted": deleted}
