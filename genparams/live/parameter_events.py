"""``/parameter_events`` as a hint only: what listeners get is what the node holds.

Any node can publish ``ParameterEvent(node=/camera, gain=9.5)``, and a message does
not tell who sent it. So an event is taken as "these names of that node changed":
the names said new or changed are read from the node over its ``get_parameters``
service, and listeners get the values the node answered. Names said deleted pass
as names only: the page reads the whole node again on those. Reads go out from the
executor without blocking it, one at a time per node; a flood of events queues at
most ``MAX_QUEUED_READS`` reads of at most ``MAX_EVENT_NAMES`` names per node, and
only for nodes in the graph.
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
        """The names to read: a value is shown only as the node answers it. Deleted names are
        not read: the page reads the whole node again on a deletion (or a new name)."""
        return sorted(self.new | self.changed)

    @property
    def count(self) -> int:
        return len(self.new | self.changed | self.deleted)

    def merge(self, other: Wanted) -> None:
        self.new |= other.new
        self.changed |= other.changed
        self.deleted |= other.deleted

    def halves(self) -> tuple[Wanted, Wanted]:
        """Two reads of half the names each (the deletions go with the first)."""
        names = self.names
        first, second = set(names[: len(names) // 2]), set(names[len(names) // 2 :])
        return (
            Wanted(self.new & first, self.changed & first, self.deleted),
            Wanted(self.new & second, self.changed & second, set()),
        )


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
        if not wanted.count or wanted.count > MAX_EVENT_NAMES or not self.present(node):
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
        if not names:  # deletions only: nothing to read
            self.dispatch(held_event(node, wanted, [], []))
            self.finish(node)
            return
        try:
            future = self.reader(node).get_call(names)()
        except Exception:  # the node's clients were let go meanwhile: the read is dropped
            self.finish(node)
            return
        future.add_done_callback(lambda done: self.answered(node, wanted, names, done))

    def answered(self, node: str, wanted: Wanted, names: list[str], future: Future) -> None:
        """Dispatch what the node answered. rclpy answers a get naming any name it does not
        hold with no values at all: such a read is asked again in halves, and a name alone
        that still gets none is left out (a forged name, or one the node no longer holds)."""
        try:
            answered = list(future.result().values)
        except Exception:  # a cancelled or failed call: a dropped event
            answered = None
        with self.lock:
            reads = self.reads.get(node)
            current = bool(reads and reads.queued and reads.queued[0] is wanted)
            if current and reads is not None and answered == [] and len(names) > 1:
                reads.queued[0:1] = wanted.halves()
                reads.sent = None
                again = True
            else:
                again = False
        if not current:
            return  # given up by the sweep meanwhile
        if again:
            self.send(node)
            return
        values: list[Any] | None = None
        if answered == [] and len(names) == 1:
            names, values = [], []
        elif answered is not None:
            try:
                values = checked_values(node, names, answered)
            except NodeAnswerError:
                values = None
        if values is not None:
            event = held_event(node, wanted, names, values)
            if event["new"] or event["changed"] or event["deleted"]:
                self.dispatch(event)
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
    """The event listeners get: each name read with the value the node holds, and the names
    said deleted (the page reads the whole node again for those)."""
    new: dict[str, Any] = {}
    changed: dict[str, Any] = {}
    deleted = sorted(wanted.deleted)
    for name, value in zip(names, values, strict=True):
        if value.type != NOT_SET:
            (new if name in wanted.new else changed)[name] = python_value(value)
    return {"kind": "parameters", "node": node, "new": new, "changed": changed, "deleted": deleted}
