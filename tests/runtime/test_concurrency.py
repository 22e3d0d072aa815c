"""Many threads set parameters at once: the view, the node and the rules never disagree.

Four client threads make 500 sets each, valid and invalid mixed: through
``node.set_parameters`` and ``node.set_parameters_atomically`` from the thread,
and through the parameter services of a node served by a MultiThreadedExecutor.
Every individual set carries a value no other set uses, so each ``on_change``
delivery can be traced to the one accepted set that caused it.
"""

from __future__ import annotations

import contextlib
import random
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from rclpy.exceptions import ParameterNotDeclaredException
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient

from genparams.runtime import Changes
from genparams.runtime.node.consistency import parameter_set_lock
from tests.support import RosHarness, load_generated, unique_name

SCHEMA = """\
genparams: 1
name: stress
parameters:
  seq: {type: int, default: 0}
  min_speed: {type: double, default: 1.0, range: {min: 0.0, max: 100.0}}
  max_speed: {type: double, default: 2.0, range: {min: 0.0, max: 100.0}}
  lists:
    topics: {type: string_array, default: [/t0]}
    weights: {type: double_array, default: [1.0]}
rules:
  - {name: speed_order, check: min_speed <= max_speed}
  - {name: one_weight_per_topic, check: len(lists.topics) == len(lists.weights)}
"""
THREADS = 4
SETS_PER_THREAD = 500
NAMES = ("seq", "min_speed", "max_speed", "lists.topics", "lists.weights")


def rules_hold(values: dict[str, Any]) -> bool:
    return bool(
        values["min_speed"] <= values["max_speed"]
        and len(values["lists.topics"]) == len(values["lists.weights"])
    )


def flat(snapshot: Any) -> dict[str, Any]:
    return {
        "seq": snapshot.seq,
        "min_speed": snapshot.min_speed,
        "max_speed": snapshot.max_speed,
        "lists.topics": snapshot.lists.topics,
        "lists.weights": snapshot.lists.weights,
    }


def node_values(node: Node) -> dict[str, Any]:
    values = {n: node.get_parameter(n).value for n in NAMES}
    return {n: v if isinstance(v, (int, float, str)) else tuple(v) for n, v in values.items()}


def unique_speed(token: int, rng: random.Random) -> float:
    """A speed in [0, 100) that no other set uses: the token sits in the low digits."""
    return rng.randrange(0, 60) + token * 1e-6


def random_set(token: int, rng: random.Random) -> tuple[str, list[Parameter]]:
    """One set: ("single", [p]) or ("atomic", [...]). About half break a range or a rule."""
    choice = rng.random()
    if choice < 0.35:
        name = rng.choice(("min_speed", "max_speed"))
        return "single", [Parameter(name, value=unique_speed(token, rng))]
    if choice < 0.45:
        # Out of range, or the wrong type: rejected before any rule is read.
        bad = rng.choice(
            [Parameter("min_speed", value=150.0 + token), Parameter("seq", value=float(token))]
        )
        return "single", [bad]
    parameters = [Parameter("seq", value=token)]
    if choice < 0.8:
        low, high = unique_speed(token, rng), rng.randrange(0, 60) + 0.5
        parameters += [Parameter("min_speed", value=low), Parameter("max_speed", value=high)]
    else:
        count = rng.randrange(1, 4)
        weights = count if rng.random() < 0.6 else count + 1  # a length mismatch breaks a rule
        parameters += [
            Parameter("lists.topics", value=[f"/t{token}_{i}" for i in range(count)]),
            Parameter("lists.weights", value=[1.0 / (i + 1) for i in range(weights)]),
        ]
    return "atomic", parameters


def typed(parameters: list[Parameter]) -> dict[str, Any]:
    return {p.name: tuple(p.value) if isinstance(p.value, list) else p.value for p in parameters}


@pytest.fixture
def fast_switching() -> Iterator[None]:
    """Switch threads often, so unserialized sets would interleave in this short test."""
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-5)
    try:
        yield
    finally:
        sys.setswitchinterval(interval)


@contextlib.contextmanager
def served_node(ros: RosHarness, name: str) -> Iterator[tuple[Node, AsyncParameterClient]]:
    """A node whose parameter services a MultiThreadedExecutor serves, and a client for them."""
    executor = MultiThreadedExecutor(num_threads=4, context=ros.context)
    node = Node(unique_name(name), context=ros.context)
    client_node = Node(unique_name(f"{name}_client"), context=ros.context)
    executor.add_node(node)
    executor.add_node(client_node)
    spinning = threading.Thread(target=executor.spin, daemon=True)
    spinning.start()
    try:
        service = AsyncParameterClient(client_node, node.get_fully_qualified_name())
        assert service.wait_for_services(timeout_sec=10.0)
        yield node, service
    finally:
        executor.shutdown()
        spinning.join(timeout=30.0)  # nothing is destroyed under the executor's wait
        node.destroy_node()
        client_node.destroy_node()


def test_concurrent_sets_stay_consistent(
    ros: RosHarness, tmp_path: Path, fast_switching: None
) -> None:
    schema = tmp_path / "stress.yaml"
    schema.write_text(SCHEMA)
    module = load_generated(schema, tmp_path)
    with served_node(ros, "stress") as (node, service):
        cfg = module.StressParams.declare(node)
        initial = cfg.snapshot()
        deliveries: list[Changes[Any]] = []
        inside = [0]
        overlapping = []

        def on_change(changes: Changes[Any]) -> None:
            inside[0] += 1
            if inside[0] != 1:
                overlapping.append(changes)
            deliveries.append(changes)
            inside[0] -= 1

        cfg.on_change(on_change)

        accepted: dict[int, dict[str, Any]] = {}  # token -> the values of an accepted set
        rejected: set[int] = set()
        # (name, value) that only one set uses -> its token: seq for atomic sets, else the value.
        markers: dict[tuple[str, Any], int] = {}
        record = threading.Lock()
        failures: list[str] = []
        stop = threading.Event()

        def through_service(parameters: list[Parameter]) -> bool:
            done = threading.Event()
            future = service.set_parameters_atomically(parameters)
            future.add_done_callback(lambda _: done.set())
            if not done.wait(10.0):
                raise TimeoutError("set_parameters_atomically through the service timed out")
            return bool(future.result().result.successful)

        def client(index: int) -> None:
            rng = random.Random(index)
            try:
                for i in range(SETS_PER_THREAD):
                    token = (index + 1) * 100_000 + i + 1
                    kind, parameters = random_set(token, rng)
                    if kind == "atomic" and rng.random() < 0.3:
                        ok = through_service(parameters)
                    elif kind == "atomic":
                        ok = node.set_parameters_atomically(parameters).successful
                    else:
                        (result,) = node.set_parameters(parameters)
                        ok = result.successful
                    values = typed(parameters)
                    marker = "seq" if kind == "atomic" else parameters[0].name
                    with record:
                        markers[(marker, values[marker])] = token
                        if ok:
                            accepted[token] = values
                        else:
                            rejected.add(token)
            except Exception as exc:  # reported by the main thread
                failures.append(f"client {index}: {exc!r}")

        observed = [0]

        def observer() -> None:
            while not stop.is_set():
                snapshot = flat(cfg.snapshot())
                if not rules_hold(snapshot):
                    failures.append(f"a snapshot breaks a rule: {snapshot}")
                with parameter_set_lock(node):  # no set in progress: node and view must agree
                    on_node = node_values(node)
                    in_view = flat(cfg.snapshot())
                if on_node != in_view:
                    differ = {
                        n: (on_node[n], in_view[n]) for n in NAMES if on_node[n] != in_view[n]
                    }
                    failures.append(f"node and view differ (node, view): {differ}")
                observed[0] += 1
                time.sleep(0.001)

        started = time.monotonic()
        clients = [threading.Thread(target=client, args=(i,)) for i in range(THREADS)]
        watcher = threading.Thread(target=observer)
        watcher.start()
        for thread in clients:
            thread.start()
        for thread in clients:
            thread.join(timeout=60.0)
        stop.set()
        watcher.join(timeout=10.0)
        elapsed = time.monotonic() - started

        assert failures == []
        assert overlapping == []
        assert len(accepted) + len(rejected) == THREADS * SETS_PER_THREAD
        assert 0.2 < len(accepted) / (THREADS * SETS_PER_THREAD) < 0.8  # a real mix
        assert observed[0] > 10

        # on_change deliveries form one chain in commit order, each caused by one accepted set.
        previous = initial
        caused_by = []
        for changes in deliveries:
            assert changes.before is previous
            previous = changes.after
            after = flat(changes.after)
            assert rules_hold(after), after
            changed = {c.name: c.new for c in changes}
            tokens = {markers[item] for item in changed.items() if item in markers}
            assert len(tokens) == 1, changed
            (token,) = tokens
            assert token in accepted, (changed, "comes from a rejected set")
            cause = accepted[token]
            assert all(cause[n] == v for n, v in changed.items()), (changed, cause)
            assert all(after[n] == v for n, v in cause.items())
            caused_by.append(token)
        assert sorted(caused_by) == sorted(accepted)  # every accepted set delivered once

        # Afterwards: node == view == the last delivery.
        final = flat(cfg.snapshot())
        assert node_values(node) == final
        assert final == flat(deliveries[-1].after)
        assert elapsed < 30.0


MAPPED = """\
genparams: 1
name: mapped_stress
parameters:
  joints: {type: string_array, default: [j0, j1]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0, validators: [{ge: 0.0}]}
"""
KEY_POOL = ("j0", "j1", "j2", "j3", "j4")


def mapped_state(node: Node) -> tuple[tuple[str, ...], dict[str, float]]:
    joints = tuple(node.get_parameter("joints").value)
    names = node.list_parameters(["gains"], 0).names
    return joints, {name: node.get_parameter(name).value for name in names}


def mapped_view(snapshot: Any) -> tuple[tuple[str, ...], dict[str, float]]:
    return snapshot.joints, {f"gains.{key}.p": entry.p for key, entry in snapshot.gains.items()}


def test_concurrent_key_changes_and_entry_sets_keep_entries_in_step(
    ros: RosHarness, tmp_path: Path, fast_switching: None
) -> None:
    """Threads change the key list and set entries at once: the entries on the node are
    always exactly those of the view's keys, with the view's values."""
    schema = tmp_path / "mapped_stress.yaml"
    schema.write_text(MAPPED)
    module = load_generated(schema, tmp_path)
    with served_node(ros, "mapped_stress") as (node, service):
        cfg = module.MappedStressParams.declare(node)
        failures: list[str] = []
        outcomes = {"accepted": 0, "refused": 0, "undeclared": 0}
        record = threading.Lock()
        stop = threading.Event()

        def count(outcome: str) -> None:
            with record:
                outcomes[outcome] += 1

        def through_service(parameters: list[Parameter]) -> bool:
            done = threading.Event()
            future = service.set_parameters(parameters)
            future.add_done_callback(lambda _: done.set())
            if not done.wait(10.0):
                raise TimeoutError("set_parameters through the service timed out")
            return bool(future.result().results[0].successful)

        def client(index: int) -> None:
            rng = random.Random(index)
            try:
                for _ in range(150):
                    choice = rng.random()
                    if choice < 0.3:
                        keys = rng.sample(KEY_POOL, rng.randrange(0, 4))
                        parameters = [Parameter("joints", Parameter.Type.STRING_ARRAY, keys)]
                    elif choice < 0.45:  # keys and an entry that may or may not exist yet
                        keys = rng.sample(KEY_POOL, rng.randrange(1, 4))
                        parameters = [
                            Parameter("joints", Parameter.Type.STRING_ARRAY, keys),
                            Parameter(f"gains.{keys[0]}.p", value=rng.uniform(-1.0, 5.0)),
                        ]
                    else:
                        name = f"gains.{rng.choice(KEY_POOL)}.p"
                        parameters = [Parameter(name, value=rng.uniform(-1.0, 5.0))]
                    try:
                        if len(parameters) > 1:
                            ok = node.set_parameters_atomically(parameters).successful
                        elif rng.random() < 0.3:
                            ok = through_service(parameters)
                        else:
                            ok = node.set_parameters(parameters)[0].successful
                    except ParameterNotDeclaredException:
                        count("undeclared")
                        continue
                    count("accepted" if ok else "refused")
            except Exception as exc:  # reported by the main thread
                failures.append(f"client {index}: {exc!r}")

        def observer() -> None:
            while not stop.is_set():
                with parameter_set_lock(node):  # no set in progress: node and view must agree
                    on_node, in_view = mapped_state(node), mapped_view(cfg.snapshot())
                if on_node != in_view:
                    failures.append(f"node and view differ: {on_node} != {in_view}")
                time.sleep(0.001)

        clients = [threading.Thread(target=client, args=(i,)) for i in range(THREADS)]
        watcher = threading.Thread(target=observer)
        watcher.start()
        for thread in clients:
            thread.start()
        for thread in clients:
            thread.join(timeout=60.0)
        stop.set()
        watcher.join(timeout=10.0)

        assert failures == []
        assert all(count > 20 for count in outcomes.values()), outcomes  # a real mix
        joints, entries = mapped_state(node)
        assert (joints, entries) == mapped_view(cfg.snapshot())
        assert sorted(entries) == sorted(f"gains.{key}.p" for key in joints)
        assert tuple(cfg.gains) == joints
