"""Scenarios on real rclpy nodes: declare, read, snapshot, set one, set all.

Every scenario runs genparams and the hand-written rclpy declaration of the
same parameters side by side, alternating sample by sample, so background
load on the machine hits both alike.
"""

from __future__ import annotations

import gc
import itertools
import time
import timeit
import types
from collections.abc import Callable, Iterator
from typing import Any

import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient
from rclpy.task import Future

from bench.measure import CPU_CLOCK, WALL_CLOCK, Result, time_calls
from bench.schemas import BenchSchema
from bench.workspace import Prepared, import_fresh

GENPARAMS = "genparams"
PLAIN = "plain rclpy"


class RosSession:
    """One rclpy context and executor for the whole run; a client node to call services."""

    def __init__(self) -> None:
        self.context = Context()
        rclpy.init(context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.client_node = Node("bench_client", context=self.context)
        self.executor.add_node(self.client_node)
        self._names = itertools.count()

    def node(self) -> Node:
        node = Node(f"bench_node_{next(self._names)}", context=self.context)
        self.executor.add_node(node)
        return node

    def destroy(self, node: Node) -> None:
        self.executor.remove_node(node)
        node.destroy_node()

    def client(self, node: Node, timeout: float = 10.0) -> AsyncParameterClient:
        client = AsyncParameterClient(self.client_node, node.get_fully_qualified_name())
        deadline = time.monotonic() + timeout
        while not client.services_are_ready():
            if time.monotonic() > deadline:
                raise TimeoutError(f"parameter services of {node.get_name()} did not appear")
            self.executor.spin_once(timeout_sec=0.05)
        return client

    def wait(self, future: Future, timeout: float = 10.0) -> Any:
        # Not executor.spin_until_future_complete: in this rclpy, every call leaves
        # finished tasks behind in the executor, so each later call gets slower.
        deadline = time.monotonic() + timeout
        while not future.done():
            if time.monotonic() > deadline:
                raise TimeoutError("parameter service call did not complete")
            self.executor.spin_once(timeout_sec=0.1)
        return future.result()

    def close(self) -> None:
        self.executor.shutdown()
        self.client_node.destroy_node()
        rclpy.shutdown(context=self.context)


class Pair:
    """The generated class and the hand-written module of one size, freshly imported."""

    def __init__(self, prepared: Prepared) -> None:
        schema = prepared.schema
        directory = prepared.module_path.parent
        self.schema = schema
        self.params_cls: Any = getattr(
            import_fresh(schema.module_name, directory), schema.class_name
        )
        self.plain: types.ModuleType = import_fresh(schema.plain_module_name, directory)


def interleaved(
    calls: dict[str, Callable[[], Any]],
    repeats: int,
    number: int = 1,
    clock: Callable[[], float] = CPU_CLOCK,
) -> dict[str, tuple[float, ...]]:
    samples: dict[str, list[float]] = {label: [] for label in calls}
    labels = list(calls)
    for round_ in range(repeats):
        gc.collect()  # once per round: a full collection costs ~0.1 s at 10,000 parameters
        # Each side goes first in turn: the first sample after a collection runs colder.
        shift = round_ % len(labels)
        for label in labels[shift:] + labels[:shift]:
            samples[label].extend(time_calls(calls[label], 1, number, clock, collect=False))
    return {label: tuple(values) for label, values in samples.items()}


def declare(session: RosSession, prepared: Prepared, repeats: int) -> list[Result]:
    """The first declaration in a process: each sample imports the modules afresh, untimed."""
    samples: dict[str, list[float]] = {GENPARAMS: [], PLAIN: []}
    for round_ in range(repeats):
        pair = Pair(prepared)
        sides = [(GENPARAMS, pair.params_cls.declare), (PLAIN, pair.plain.declare)]
        for label, declare_on in sides if round_ % 2 == 0 else sides[::-1]:  # each goes first
            node = session.node()
            samples[label].extend(time_calls(lambda: declare_on(node), 1))  # noqa: B023
            missing = [p.name for p in pair.schema.parameters if not node.has_parameter(p.name)]
            if missing:
                raise RuntimeError(f"{label} did not declare {len(missing)} parameters")
            session.destroy(node)
    return [
        Result("declare", label, prepared.schema.size, "s", tuple(values))
        for label, values in samples.items()
    ]


class Declared:
    """Both sides declared on nodes of their own, for the read and set scenarios."""

    def __init__(self, session: RosSession, prepared: Prepared) -> None:
        pair = Pair(prepared)
        self.schema: BenchSchema = prepared.schema
        self.genparams_node = session.node()
        self.cfg = pair.params_cls.declare(self.genparams_node)
        self.plain_node = session.node()
        pair.plain.declare(self.plain_node)
        self.nodes = {GENPARAMS: self.genparams_node, PLAIN: self.plain_node}

    def destroy(self, session: RosSession) -> None:
        for node in self.nodes.values():
            session.destroy(node)


READ_GENPARAMS = "genparams: cfg.<path>"
READ_CHAIN = "plain attribute chain"
READ_NODE = "rclpy: node.get_parameter(name).value"
READ_LOOP = "empty timeit loop (overhead)"
SNAPSHOT_GENPARAMS = "genparams: cfg.snapshot()"
SNAPSHOT_PLAIN = "rclpy: node.get_parameters(all names)"


def attribute_chain(values: dict[str, Any]) -> Any:
    """Plain objects holding the same values under the same dotted attribute paths.

    One ordinary class per namespace, as hand-written config classes would be,
    so attribute reads get CPython's fast path for instance attributes.
    """

    def namespace() -> Any:
        return type("Namespace", (), {})()

    root = namespace()
    for name, value in values.items():
        *groups, leaf = name.split(".")
        level = root
        for group in groups:
            if not hasattr(level, group):
                setattr(level, group, namespace())
            level = getattr(level, group)
        setattr(level, leaf, value)
    return root


def read(declared: Declared, repeats: int, number: int = 200_000) -> list[Result]:
    schema = declared.schema
    path = schema.probe.name
    names = [p.name for p in schema.parameters]
    namespace = {
        "cfg": declared.cfg,
        "plain": attribute_chain(schema.values()),
        "node": declared.plain_node,
        "name": path,
        "names": names,
    }
    statements = {
        READ_GENPARAMS: f"cfg.{path}",
        READ_CHAIN: f"plain.{path}",
        READ_NODE: "node.get_parameter(name).value",
        READ_LOOP: "pass",
        SNAPSHOT_GENPARAMS: "cfg.snapshot()",
        SNAPSHOT_PLAIN: "node.get_parameters(names)",
    }
    if eval(statements[READ_GENPARAMS], namespace) != eval(statements[READ_CHAIN], namespace):
        raise RuntimeError("genparams and the attribute chain read different values")
    results = []
    for _ in range(repeats):
        for label, statement in statements.items():
            count = max(10, number // schema.size) if label == SNAPSHOT_PLAIN else number
            timer = timeit.Timer(statement, timer=CPU_CLOCK, globals=namespace)
            seconds = timer.timeit(count) / count
            scenario = "snapshot" if label.endswith(("snapshot()", "(all names)")) else "read"
            results.append(Result(scenario, label, schema.size, "s", (seconds,)))
    return merge(results)


def merge(results: list[Result]) -> list[Result]:
    """One Result per (scenario, variant, size), with every sample."""
    merged: dict[tuple[str, str, int], Result] = {}
    for result in results:
        key = (result.scenario, result.variant, result.size)
        if key in merged:
            previous = merged[key]
            result = Result(*key, result.unit, previous.samples + result.samples)
        merged[key] = result
    return list(merged.values())


def _alternating(*items: Any) -> Iterator[Any]:
    return itertools.cycle(items)


def _each_call(function: Callable[[Any], Any], arguments: Iterator[Any]) -> Callable[[], None]:
    """A call of ``function`` with the next of ``arguments``, which must succeed."""

    def call() -> None:
        _expect_success(function(next(arguments)))

    return call


def set_calls(declared: Declared) -> dict[str, Callable[[], None]]:
    """Per side, a call of ``node.set_parameters`` of the probe, to its other value each time."""
    probe = declared.schema.probe
    calls = {}
    for label, node in declared.nodes.items():
        values = _alternating(
            [Parameter(probe.name, value=probe.kind.other)],
            [Parameter(probe.name, value=probe.kind.default)],
        )
        calls[label] = _each_call(node.set_parameters, values)
    return calls


def set_one(declared: Declared, repeats: int, number: int = 25) -> list[Result]:
    """``node.set_parameters`` of one parameter, to a new value each time.

    Many short samples (six per repeat): their minimum is what one set costs
    when no other process is competing for the core.
    """
    calls = set_calls(declared)
    samples = interleaved(calls, repeats * 6, number)
    _expect_view_follows(declared)
    return [Result("set_one", label, declared.schema.size, "s", s) for label, s in samples.items()]


def set_one_service(
    session: RosSession, declared: Declared, repeats: int, number: int = 10
) -> list[Result]:
    """One parameter set through the parameter service, from a client node in this process."""
    probe = declared.schema.probe
    calls = {}
    for label, node in declared.nodes.items():
        client = session.client(node)
        values = _alternating(
            [Parameter(probe.name, value=probe.kind.other)],
            [Parameter(probe.name, value=probe.kind.default)],
        )

        def set_remotely(parameters: list[Parameter], client: Any = client) -> Any:
            return session.wait(client.set_parameters(parameters)).results

        calls[label] = _each_call(set_remotely, values)
    # Wall-clock time: a round trip is mostly waiting for the reply.
    samples = interleaved(calls, repeats * 3, number, WALL_CLOCK)
    _expect_view_follows(declared)
    return [
        Result("set_one_service", label, declared.schema.size, "s", s)
        for label, s in samples.items()
    ]


def set_all(declared: Declared, repeats: int) -> list[Result]:
    """Every parameter in one call: ``set_parameters`` (one by one) and atomically."""
    schema = declared.schema
    lists = [
        [Parameter(name, value=value) for name, value in schema.values(other=other).items()]
        for other in (True, False)
    ]
    number = max(1, 1000 // schema.size)
    results: list[Result] = []
    for scenario, method in (
        ("set_all", "set_parameters"),
        ("set_all_atomic", "set_parameters_atomically"),
    ):
        calls = {
            label: _each_call(getattr(node, method), _alternating(*lists))
            for label, node in declared.nodes.items()
        }
        samples = interleaved(calls, repeats, number)
        results.extend(Result(scenario, label, schema.size, "s", s) for label, s in samples.items())
    _expect_view_follows(declared)
    return results


def _expect_success(outcome: Any) -> None:
    results = outcome if isinstance(outcome, list) else [outcome]
    for result in results:
        if not result.successful:
            raise RuntimeError(f"a benchmark set was rejected: {result.reason}")


def _expect_view_follows(declared: Declared) -> None:
    name = declared.schema.probe.name
    value = eval(f"cfg.{name}", {"cfg": declared.cfg})
    if value != declared.genparams_node.get_parameter(name).value:
        raise RuntimeError(f"cfg.{name} does not follow the node")
