"""Follow another node's parameters through its parameter events, as typed changes.

Events carry the new values of what changed, so most are applied to the last
known snapshot directly. A change of a ``for_each`` key list declares and
undeclares entries on the node, so it is followed by a full read, and the
callback gets the difference.
"""

from __future__ import annotations

import threading
import time
import traceback
from collections.abc import Callable
from typing import Any, Generic, Protocol, TypeVar

from rcl_interfaces.msg import ParameterEvent
from rclpy.node import Node
from rclpy.parameter import parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from rclpy.subscription import Subscription
from rclpy.task import Future
from rclpy.timer import Timer

from genparams.runtime.core.changes import Change, Changes
from genparams.runtime.core.entries import expand
from genparams.runtime.core.params_view import ParamsView
from genparams.runtime.core.spec import CompiledParam, CompiledSchema
from genparams.runtime.core.tree import get_path, replace_values
from genparams.runtime.core.types import ValueTypeError
from genparams.runtime.remote.typed_future import TypedFuture

P = TypeVar("P", bound=ParamsView)


class Watched(Protocol[P]):
    """What a watch uses of the client it follows the target with (``client.RemoteParams``)."""

    @property
    def node(self) -> Node: ...
    @property
    def target(self) -> str: ...
    @property
    def client(self) -> AsyncParameterClient: ...
    @property
    def compiled(self) -> CompiledSchema: ...

    def get(self) -> TypedFuture[P]:
        """A full read of the target's parameters, as a snapshot."""

    def relative_name(self, full_name: str) -> str | None:
        """``full_name`` relative to the prefix; None if it is not under it."""


class RemoteWatch(Generic[P]):
    """Mirrors the target's parameters; see ``RemoteParams.watch``.

    Parameter events are not replayed to late subscribers, so the first snapshot is
    read only once the event subscription is connected (or after ``CONNECT_TIMEOUT``):
    from ``ready`` on, no change goes unreported. Events that arrive while a
    snapshot is being read are applied after it; one that the snapshot already
    holds is then no change, and reports nothing.
    """

    CONNECT_TIMEOUT = 5.0
    READ_ATTEMPTS = 3

    def __init__(self, remote: Watched[P], callback: Callable[[Changes[P]], None]) -> None:
        self.remote = remote
        self.callback = callback
        self.lock = threading.RLock()  # events and snapshots may arrive on several threads
        self.latest: P | None = None
        self.known: dict[str, CompiledParam] = {}  # fixed parameters and current entries
        self.key_lists = frozenset(remote.compiled.maps.values())
        self.reading = True  # a full read is in flight: events wait for it
        self.waiting: list[ParameterEvent] = []
        self.ready: TypedFuture[P] = TypedFuture()
        self.subscription: Subscription | None = remote.client.on_parameter_event(self.on_event)
        self.connect_deadline = time.monotonic() + self.CONNECT_TIMEOUT
        self.connecting: Timer | None = remote.node.create_timer(0.02, self.read_when_connected)

    def cancel(self) -> None:
        """Stop watching; the callback is not called again."""
        with self.lock:
            self.stop_connecting()
            if self.subscription is not None:
                self.remote.node.destroy_subscription(self.subscription)
                self.subscription = None

    def stop_connecting(self) -> None:
        if self.connecting is not None:
            self.remote.node.destroy_timer(self.connecting)
            self.connecting = None

    def read_when_connected(self) -> None:
        with self.lock:
            if self.connecting is None or self.subscription is None:
                return
            publishers = self.remote.node.count_publishers(self.subscription.topic_name)
            connected = self.subscription.get_publisher_count() >= publishers
            if not connected and time.monotonic() < self.connect_deadline:
                return
            self.stop_connecting()
        self.read_all()

    def read_all(self, attempt: int = 1) -> None:
        self.reading = True
        self.remote.get().add_done_callback(lambda future: self.on_snapshot(future, attempt))

    def on_snapshot(self, future: Future, attempt: int) -> None:
        with self.lock:
            try:
                snapshot = future.result()
            except Exception as exc:
                if self.ready.done() and attempt < self.READ_ATTEMPTS:
                    # A new key list is stored before its entries are declared: read again.
                    self.read_all(attempt + 1)
                    return
                self.reading = False
                if not self.ready.done():
                    self.ready.set_exception(exc)
                else:
                    self.log_error(f"cannot read {self.remote.target}")
                return
            before = self.latest
            first = before is None
            if before is not None:
                self.report(before, snapshot, self.difference(before, snapshot))
            self.take(snapshot)
            self.reading = False
            waiting, self.waiting = self.waiting, []
            for event in waiting:
                self.apply(event)
        if first:
            self.ready.set_result(snapshot)

    def take(self, snapshot: P) -> None:
        self.latest = snapshot
        compiled = self.remote.compiled
        self.known = dict(compiled.parameters)
        if compiled.templates:
            fixed = {n: get_path(snapshot, p.attribute_path) for n, p in self.known.items()}
            self.known.update(expand(compiled, fixed))

    def values(self, snapshot: P) -> dict[str, Any]:
        compiled = self.remote.compiled
        values = {n: get_path(snapshot, p.attribute_path) for n, p in compiled.parameters.items()}
        if compiled.templates:
            entries = expand(compiled, values)
            values.update({n: get_path(snapshot, p.attribute_path) for n, p in entries.items()})
        return values

    def difference(self, before: P, after: P) -> list[Change]:
        old, new = self.values(before), self.values(after)
        return [
            Change(name, old.get(name), new.get(name))
            for name in dict.fromkeys([*old, *new])
            if old.get(name) != new.get(name)
        ]

    def on_event(self, event: ParameterEvent) -> None:
        if event.node != self.remote.target:
            return
        with self.lock:
            self.apply(event)

    def apply(self, event: ParameterEvent) -> None:
        if self.reading:
            self.waiting.append(event)
            return
        before = self.latest
        assert before is not None  # set by the first read, which ended `reading`
        changed: list[Change] = []
        paths: dict[tuple[str, ...], Any] = {}
        for message in (*event.new_parameters, *event.changed_parameters):
            name = self.remote.relative_name(message.name)
            if name in self.key_lists:
                self.read_all()  # entries come and go: read them all again
                return
            param = self.known.get(name) if name is not None else None
            if param is None:
                continue
            try:
                new = param.type.from_ros(parameter_value_to_python(message.value))
            except ValueTypeError as exc:
                self.remote.node.get_logger().warning(
                    f"{self.remote!r}: ignoring {message.name}: {exc}"
                )
                continue
            old = get_path(before, param.attribute_path)
            if old != new:
                changed.append(Change(param.name, old, new))
                paths[param.attribute_path] = new
        if changed:
            after = replace_values(before, paths, extra=("_binding",))
            self.latest = after
            self.report(before, after, changed)

    def report(self, before: P, after: P, changed: list[Change]) -> None:
        if not changed:
            return
        try:
            self.callback(Changes(before, after, tuple(changed)))
        except Exception:  # a subscriber's bug must not stop the watch
            self.log_error(f"watch callback {self.callback!r} raised")

    def log_error(self, what: str) -> None:
        self.remote.node.get_logger().error(f"{self.remote!r}: {what}:\n{traceback.format_exc()}")
