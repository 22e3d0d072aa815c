"""Read a node over the three services reading needs; set it over the set services, once.

rclpy's AsyncParameterClient opens six service clients; each is a pair of DDS
endpoints that every participant must match, about 4 ms apiece. Reading (the
page opening a node, an audit, import-node) needs list, get and describe only;
the set services are opened when a set is made. Every answer is checked by
:mod:`genparams.live.answers` before it is used.
"""

from __future__ import annotations

import itertools
import threading
import time
from collections.abc import Callable, Sequence
from typing import Any

from rcl_interfaces.srv import DescribeParameters, GetParameters, ListParameters
from rclpy.client import Client
from rclpy.node import Node
from rclpy.task import Future

from genparams.live.answers import (
    ReadParameter,
    checked_descriptors,
    checked_list,
    checked_single,
    checked_values,
)
from genparams.runtime.core.errors import GenparamsError

RESEND_SECONDS = 1.0
SET_IDS = itertools.count(1)


class StillWorkingError(GenparamsError, TimeoutError):
    """A set the node has not answered yet: sent once, never again; ``future`` ends later.

    ``set_id`` names the set in the event that tells its outcome (see
    :meth:`genparams.live.graph.Graph.set_parameters`).
    """

    def __init__(self, node: str, future: Future) -> None:
        super().__init__(
            f"{node} is still working on the set: it was sent once and is not sent again;"
            " its change shows when the node makes it"
        )
        self.future = future
        self.set_id = next(SET_IDS)


def wait_future(future: Future, timeout: float, *, cancel: bool = True) -> Any:
    """Block a thread other than the executor's until ``future`` is done."""
    done = threading.Event()
    future.add_done_callback(lambda _: done.set())
    if not done.wait(timeout):
        if cancel:
            future.cancel()
        raise TimeoutError("no answer from the node's parameter services")
    return future.result()


def wait_ready(clients: Sequence[Client], timeout: float) -> bool:
    """Poll often: rclpy's wait_for_service sleeps in steps of 0.25 s."""
    deadline = time.monotonic() + timeout
    while not all(client.service_is_ready() for client in clients):
        if time.monotonic() > deadline:
            return False
        time.sleep(0.005)
    return True


class ParameterReader:
    """The list, get and describe services of one node."""

    def __init__(self, node: Node, target: str) -> None:
        self.node = node
        self.target = target
        self.lister = node.create_client(ListParameters, f"{target}/list_parameters")
        self.getter = node.create_client(GetParameters, f"{target}/get_parameters")
        self.describer = node.create_client(DescribeParameters, f"{target}/describe_parameters")

    @property
    def clients(self) -> tuple[Client, ...]:
        return (self.lister, self.getter, self.describer)

    def wait_ready(self, timeout: float) -> bool:
        return wait_ready(self.clients, timeout)

    def destroy(self) -> None:
        for client in self.clients:
            self.node.destroy_client(client)

    def ready_or_raise(self, timeout: float) -> None:
        if not self.wait_ready(timeout):
            raise TimeoutError(f"{self.target}: parameter services did not appear")

    def list_call(self) -> Callable[[], Future]:
        return lambda: self.lister.call_async(ListParameters.Request(depth=0))

    def get_call(self, names: Sequence[str]) -> Callable[[], Future]:
        return lambda: self.getter.call_async(GetParameters.Request(names=list(names)))

    def describe_call(self, names: Sequence[str]) -> Callable[[], Future]:
        return lambda: self.describer.call_async(DescribeParameters.Request(names=list(names)))


def answers(calls: Sequence[Callable[[], Future]], timeout: float) -> list[Any]:
    """Send every read; resend those unanswered after ``RESEND_SECONDS``, until ``timeout``.

    A service can be ready before the path of its replies to a new client is
    matched: a request sent then is never answered, so it is sent again. Only
    reads come here; a set is sent once (:func:`send_once`).
    """
    deadline = time.monotonic() + timeout
    results: list[Any] = [None] * len(calls)
    waiting = list(range(len(calls)))
    while waiting:
        futures = {index: calls[index]() for index in waiting}
        attempt = min(RESEND_SECONDS, max(0.0, deadline - time.monotonic()))
        for index, future in futures.items():
            try:
                results[index] = wait_future(future, attempt)
            except TimeoutError:
                if time.monotonic() >= deadline:
                    raise
        waiting = [index for index in waiting if results[index] is None]
    return results


def send_once(node: str, call: Callable[[], Future], timeout: float) -> Any:
    """Send a set once and wait ``timeout`` for its answer; StillWorkingError if none came.

    A set runs the node's on-set callbacks: sending it again would run them again.
    """
    future = call()
    try:
        return wait_future(future, timeout, cancel=False)
    except TimeoutError:
        raise StillWorkingError(node, future) from None


def listed_names(readers: Sequence[ParameterReader], timeout: float) -> list[list[str]]:
    """The names each reader's node lists, checked."""
    listed = answers([reader.list_call() for reader in readers], timeout)
    return [checked_list(r.target, got.result) for r, got in zip(readers, listed, strict=True)]


def values_of(
    readers: Sequence[ParameterReader], names: Sequence[Sequence[str]], timeout: float
) -> list[list[Any]]:
    """Each reader's values of its ``names``, checked.

    rclpy answers a get naming a parameter declared by type only, with no value yet,
    with no values at all: such an answer is asked again in halves, down to the names
    alone, which then read as unset. The calls stay few when few names are unset.
    """
    found: list[dict[str, Any]] = [{} for _ in readers]
    pending = [(index, list(chunk)) for index, chunk in enumerate(names) if chunk]
    while pending:
        replies = answers([readers[i].get_call(chunk) for i, chunk in pending], timeout)
        split = []
        for (index, chunk), reply in zip(pending, replies, strict=True):
            node = readers[index].target
            if len(chunk) == 1:
                found[index][chunk[0]] = checked_single(node, chunk[0], reply.values)
            elif reply.values:
                got = checked_values(node, chunk, reply.values)
                found[index].update(zip(chunk, got, strict=True))
            else:
                half = len(chunk) // 2
                split.extend([(index, chunk[:half]), (index, chunk[half:])])
        pending = split
    return [[got[name] for name in chunk] for got, chunk in zip(found, names, strict=True)]


def read_all(readers: Sequence[ParameterReader], timeout: float) -> dict[str, list[ReadParameter]]:
    """Every parameter of every reader's node; each step's calls go out together.

    TimeoutError when a node's services do not appear or answer; NodeAnswerError when one
    answers what cannot be used.
    """
    for reader in readers:
        reader.ready_or_raise(timeout)
    names = listed_names(readers, timeout)
    read = read_described(readers, names, timeout)
    return {reader.target: parameters for reader, parameters in zip(readers, read, strict=True)}


def read_described(
    readers: Sequence[ParameterReader], names: Sequence[Sequence[str]], timeout: float
) -> list[list[ReadParameter]]:
    values = values_of(readers, names, timeout)
    described = answers(
        [reader.describe_call(chunk) for reader, chunk in zip(readers, names, strict=True)],
        timeout,
    )
    return [
        [
            ReadParameter(*row)
            for row in zip(
                chunk,
                got,
                checked_descriptors(reader.target, chunk, answer.descriptors),
                strict=True,
            )
        ]
        for reader, chunk, got, answer in zip(readers, names, values, described, strict=True)
    ]


def read_named(
    reader: ParameterReader, names: Sequence[str], timeout: float
) -> tuple[list[str], list[ReadParameter]]:
    """Every name the node declares, and those of ``names`` it declares, read in full."""
    reader.ready_or_raise(timeout)
    declared = listed_names([reader], timeout)[0]
    known = set(declared)
    wanted = [name for name in dict.fromkeys(names) if name in known]
    return declared, read_described([reader], [wanted], timeout)[0]
