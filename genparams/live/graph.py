"""The live ROS graph as the tuning page, the audit and import-node see it: the one reader.

One rclpy node of our own, spun by an executor in a background thread, does
everything ``ros2 param`` does: it lists the nodes (hidden ones, whose names start
with ``_``, only when asked), reads a node over its parameter services
(:mod:`genparams.live.services`, every answer checked by :mod:`genparams.live.answers`),
sets it (once), follows the latched schema topics of the nodes in the graph
(:mod:`genparams.live.schema_topics`) and ``/parameter_events``
(:mod:`genparams.live.parameter_events`, each value read from its node).
"""

from __future__ import annotations

import logging
import threading
import time
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from typing import Any

import rclpy
from rcl_interfaces.srv import SetParameters, SetParametersAtomically
from rclpy.context import Context
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor, ShutdownException
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.task import Future

from genparams.live.answers import NodeAnswerError, ReadParameter
from genparams.live.parameter_events import EventListener, EventRelay
from genparams.live.schema_topics import SchemaTopics
from genparams.live.services import (
    ParameterReader,
    StillWorkingError,
    answers,
    read_all,
    read_named,
    send_once,
    wait_ready,
)

LOG = logging.getLogger("genparams.live")
SWEEP_SECONDS = 1.0
# A node asked for before discovery has told of it keeps its clients this long: a node
# started a moment ago may take seconds to appear on a loaded machine.
UNSEEN_GRACE_SECONDS = 60.0
# The outcome of a set whose node left the graph before answering it.
SET_ABANDONED = (
    "the node left the graph before answering the set: whether it took effect is unknown"
)
NAMES_FRESH_SECONDS = 0.2  # how long a listing of the graph answers "is this node there?"


def is_hidden(full_name: str) -> bool:
    """A hidden node, as ROS counts them: its base name starts with ``_``."""
    return full_name.rpartition("/")[2].startswith("_")


class Setter:
    """The set services of one node, opened when a set is first made."""

    def __init__(self, node: Node, target: str) -> None:
        self.node = node
        self.primed = False  # see prime
        self.single = node.create_client(SetParameters, f"{target}/set_parameters")
        self.atomic = node.create_client(
            SetParametersAtomically, f"{target}/set_parameters_atomically"
        )

    def prime(self, timeout: float) -> None:
        """Send an empty set, again until answered: the node sets nothing and runs no
        callback (rclpy and rclcpp set each listed parameter, and none is listed), and
        once it answered, the path of the node's replies to these clients is matched, so
        the real set, sent once, is not answered into the void."""
        if not self.primed:
            empty = SetParameters.Request(parameters=[])
            answers([lambda: self.single.call_async(empty)], timeout)
            self.primed = True

    def destroy(self) -> None:
        for client in (self.single, self.atomic):
            self.node.destroy_client(client)


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
        self.absent: set[str] = set()  # nodes the last sweep found gone (see sweep)
        self.seen: set[str] = set()  # held nodes some sweep found in the graph
        self.asked: dict[str, float] = {}  # held node -> when its first client was made
        self.sweeps = 0  # sweeps done so far
        self.readers: dict[str, ParameterReader] = {}
        self.setters: dict[str, Setter] = {}
        self.unanswered: dict[str, set[Future]] = {}  # node -> sets it has not answered yet
        self.listing: tuple[float, Counter[str]] = (0.0, Counter())
        self.topics = SchemaTopics(
            self.node, self.lock, self.node_names, self.claimants, self.schema_arrived
        )
        self.events = EventRelay(self.node, self.reader, self.present)
        self.node.create_timer(0.25, self.topics.watch)
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
                LOG.exception("genparams: the ROS executor went on after an error")

    def close(self) -> None:
        """Stop spinning, then destroy: nothing is destroyed under the executor's wait."""
        self.closing.set()
        self.executor.shutdown(timeout_sec=1.0)
        self.thread.join(timeout=10.0)
        self.node.destroy_node()
        rclpy.shutdown(context=self.context)

    # The graph ---------------------------------------------------------------

    def counted_names(self) -> Counter[str]:
        """Every node in the graph but ours, with how many nodes have that name."""
        own = self.node.get_fully_qualified_name()
        found = Counter(
            f"{namespace.rstrip('/')}/{name}"
            for name, namespace in self.node.get_node_names_and_namespaces()
        )
        del found[own]
        with self.lock:
            self.listing = (time.monotonic(), found)
        return found

    def node_names(self, hidden: bool = True) -> list[str]:
        """The nodes in the graph, each once; without ``hidden``, none whose name starts with _."""
        return sorted(n for n in self.counted_names() if hidden or not is_hidden(n))

    def recent_names(self) -> Counter[str]:
        """:meth:`counted_names`, from a listing at most ``NAMES_FRESH_SECONDS`` old."""
        with self.lock:
            when, names = self.listing
        return names if time.monotonic() - when <= NAMES_FRESH_SECONDS else self.counted_names()

    def claimants(self, node_name: str) -> int:
        """How many nodes in the graph have the name ``node_name``."""
        return self.recent_names()[node_name]

    def present(self, node_name: str) -> bool:
        """Whether ``node_name`` is in the graph (a name not in a recent listing: asked again)."""
        return node_name in self.recent_names() or node_name in self.counted_names()

    def watch_schema_topics(self) -> None:
        self.topics.watch()

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
            held = {*self.readers, *self.setters}
        held |= self.topics.held()
        with self.lock:
            self.seen = (self.seen & held) | (present & held)
            seen, asked = set(self.seen), dict(self.asked)
        gone = {
            n
            for n in held
            if n not in present and (n in seen or now - asked.get(n, now) > UNSEEN_GRACE_SECONDS)
        }
        gone_nodes, self.absent = gone & self.absent, gone
        for name in gone_nodes:
            self.abandon_sets(name)
            self.forget(name)
            with self.lock:
                self.seen.discard(name)
                self.asked.pop(name, None)
        self.topics.sweep(gone_nodes)
        self.events.sweep(gone_nodes)
        self.sweeps += 1

    # Schemas ------------------------------------------------------------------

    def schema_arrived(self, owner: str) -> None:
        with self.lock:
            self.asked.setdefault(owner, time.monotonic())
        self.dispatch({"kind": "schema", "node": owner})

    def schema_state(self, node_name: str) -> tuple[dict[str, Any] | None, str | None]:
        """(the node's schema, None) when trusted; (None, the problem) when not; or neither."""
        return self.topics.state(node_name)

    def schema(self, node_name: str) -> dict[str, Any] | None:
        """The node's schema message, when it is well formed and its own."""
        return self.schema_state(node_name)[0]

    def wait_for_schemas(self, names: Iterable[str], timeout: float) -> None:
        self.topics.wait(set(names), timeout)

    # Parameter services -------------------------------------------------------

    def note_asked(self, node_name: str) -> None:
        """Remember when clients were first made for ``node_name``, and if it was there then."""
        self.asked.setdefault(node_name, time.monotonic())
        if node_name in self.listing[1]:  # called with the lock held
            self.seen.add(node_name)

    def reader(self, node_name: str) -> ParameterReader:
        with self.lock:
            found = self.readers.get(node_name)
            if found is None:
                found = self.readers[node_name] = ParameterReader(self.node, node_name)
                self.note_asked(node_name)
            return found

    def setter(self, node_name: str) -> Setter:
        with self.lock:
            found = self.setters.get(node_name)
            if found is None:
                found = self.setters[node_name] = Setter(self.node, node_name)
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
        for held in (reader, setter):
            if held is not None:
                held.destroy()

    def abandon_sets(self, node_name: str) -> None:
        """End the sets a node left the graph without answering: their outcome is unknown.

        rclpy never ends a call whose server went away; without this, a page would show
        such a set as sent and not yet confirmed for as long as it stays open.
        """
        with self.lock:
            futures = self.unanswered.pop(node_name, set())
        for future in futures:
            future.cancel()  # its done callback tells the outcome as a "set" event

    def services_ready(self, node_name: str, timeout: float) -> bool:
        return self.reader(node_name).wait_ready(timeout)

    def read_node(self, node_name: str, timeout: float = 5.0) -> list[dict[str, Any]]:
        """Every parameter of a node: name, type, value and descriptor, as JSON-ready dicts.

        TimeoutError when it does not answer; NodeAnswerError when its answers cannot be used."""
        return [p.as_json() for p in self.read_raw([node_name], timeout)[node_name]]

    def read_raw(
        self, node_names: Sequence[str], timeout: float = 5.0
    ) -> dict[str, list[ReadParameter]]:
        """Every parameter of each node as it answered: name, value and descriptor, checked."""
        return read_all([self.reader(name) for name in node_names], timeout)

    def read_nodes(
        self, node_names: Sequence[str], timeout: float = 5.0
    ) -> dict[str, list[dict[str, Any]]]:
        read = self.read_raw(node_names, timeout)
        return {name: [p.as_json() for p in parameters] for name, parameters in read.items()}

    def read_parameters(
        self, node_name: str, names: Sequence[str], timeout: float = 5.0
    ) -> tuple[list[str], list[dict[str, Any]]]:
        """Every name the node declares, and the parameters ``names`` in full."""
        declared, read = read_named(self.reader(node_name), names, timeout)
        return declared, [p.as_json() for p in read]

    def set_parameters(
        self, node_name: str, parameters: list[Parameter], atomic: bool, timeout: float = 5.0
    ) -> list[dict[str, Any]]:
        """Set through the node's services, sent once; one result per parameter (atomic: the
        same one). StillWorkingError when the node has not answered within ``timeout``: its
        answer, when it comes, goes to the listeners as a ``set`` event (:func:`set_event`)."""
        setter = self.setter(node_name)
        client = setter.atomic if atomic else setter.single
        if not wait_ready([setter.single, setter.atomic], timeout):
            raise TimeoutError(f"{node_name}: parameter services did not appear")
        setter.prime(timeout)
        messages = [p.to_parameter_msg() for p in parameters]
        request: Any = (SetParametersAtomically if atomic else SetParameters).Request(
            parameters=messages
        )
        try:
            answer = send_once(node_name, lambda: client.call_async(request), timeout)
        except StillWorkingError as working:
            set_id = working.set_id  # the name `working` is gone once the block ends

            def answered(done: Future) -> None:
                with self.lock:
                    self.unanswered.get(node_name, set()).discard(done)
                self.dispatch(set_event(node_name, set_id, parameters, atomic, done))

            with self.lock:
                self.unanswered.setdefault(node_name, set()).add(working.future)
            working.future.add_done_callback(answered)
            raise
        return set_results(node_name, parameters, answer, atomic)

    # /parameter_events ---------------------------------------------------------

    def subscribe(self, listener: EventListener) -> Callable[[], None]:
        return self.events.subscribe(listener)

    def dispatch(self, event: dict[str, Any]) -> None:
        self.events.dispatch(event)


def set_results(
    node_name: str, parameters: Sequence[Parameter], answer: Any, atomic: bool
) -> list[dict[str, Any]]:
    """One result per parameter of a set's answer; NodeAnswerError when it cannot be used."""
    results = [answer.result] * len(parameters) if atomic else list(answer.results)
    if len(results) != len(parameters):
        count = f"{len(results)} results for {len(parameters)} values"
        raise NodeAnswerError(f"{node_name}: its set answer cannot be used: {count}")
    return [
        {"name": p.name, "successful": bool(r.successful), "reason": str(r.reason)}
        for p, r in zip(parameters, results, strict=True)
    ]


def set_event(
    node_name: str, set_id: int, parameters: Sequence[Parameter], atomic: bool, done: Future
) -> dict[str, Any]:
    """The outcome of a set answered after the wait: its results, or why there are none."""
    event: dict[str, Any] = {"kind": "set", "node": node_name, "set": set_id}
    if done.cancelled():
        event["results"] = []
        event["error"] = SET_ABANDONED
        event["unknown"] = True  # not refused: the node may have made the change
        return event
    try:
        event["results"] = set_results(node_name, parameters, done.result(), atomic)
    except Exception as exc:  # a cancelled call or an unusable answer: told, not raised
        event["results"] = []
        event["error"] = str(exc) or type(exc).__name__
    return event
