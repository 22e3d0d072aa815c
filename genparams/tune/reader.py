"""Read a node's parameters with the three services that reading needs.

rclpy's AsyncParameterClient opens six service clients; each is a pair of DDS
endpoints that every participant must match, about 4 ms apiece. Reading (the
page opening a node, an audit) needs list, get and describe only; the set
services are opened when a set is made.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Sequence
from typing import Any

from rcl_interfaces.msg import ParameterType, ParameterValue
from rcl_interfaces.srv import DescribeParameters, GetParameters, ListParameters
from rclpy.client import Client
from rclpy.node import Node
from rclpy.parameter import parameter_value_to_python
from rclpy.task import Future

RESEND_SECONDS = 1.0
TYPE_NAMES = {
    ParameterType.PARAMETER_BOOL: "bool",
    ParameterType.PARAMETER_INTEGER: "int",
    ParameterType.PARAMETER_DOUBLE: "double",
    ParameterType.PARAMETER_STRING: "string",
    ParameterType.PARAMETER_BYTE_ARRAY: "byte_array",
    ParameterType.PARAMETER_BOOL_ARRAY: "bool_array",
    ParameterType.PARAMETER_INTEGER_ARRAY: "int_array",
    ParameterType.PARAMETER_DOUBLE_ARRAY: "double_array",
    ParameterType.PARAMETER_STRING_ARRAY: "string_array",
}


def python_value(value: Any) -> Any:
    """A ParameterValue as JSON-ready Python: arrays as lists, bytes as ints."""
    plain = parameter_value_to_python(value)
    if value.type == ParameterType.PARAMETER_BYTE_ARRAY:
        return [b if isinstance(b, int) else ord(b) for b in plain]
    if isinstance(plain, list | tuple) or hasattr(plain, "tolist"):
        return list(plain)
    return plain


def wait_future(future: Future, timeout: float) -> Any:
    """Block a thread other than the executor's until ``future`` is done."""
    done = threading.Event()
    future.add_done_callback(lambda _: done.set())
    if not done.wait(timeout):
        future.cancel()
        raise TimeoutError("no answer from the node's parameter services")
    return future.result()


def descriptor_range(descriptor: Any) -> dict[str, Any] | None:
    for ranges in (descriptor.integer_range, descriptor.floating_point_range):
        if ranges:
            first = ranges[0]
            return {"min": first.from_value, "max": first.to_value, "step": first.step}
    return None


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
        """Poll often: rclpy's wait_for_service sleeps in steps of 0.25 s."""
        deadline = time.monotonic() + timeout
        while not all(client.service_is_ready() for client in self.clients):
            if time.monotonic() > deadline:
                return False
            time.sleep(0.005)
        return True

    def destroy(self) -> None:
        for client in self.clients:
            self.node.destroy_client(client)


def answers(calls: Sequence[Callable[[], Future]], timeout: float) -> list[Any]:
    """Send every call; resend those unanswered after ``RESEND_SECONDS``, until ``timeout``.

    A service can be ready before the path of its replies to a new client is
    matched: a request sent then is never answered, so it is sent again. Every
    call made here is a read or a set of given values, so sending twice is harmless.
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


def read_all(readers: Sequence[ParameterReader], timeout: float) -> dict[str, list[dict[str, Any]]]:
    """Every parameter of every reader's node; each step's calls go out together."""
    for reader in readers:
        if not reader.wait_ready(timeout):
            raise TimeoutError(f"{reader.target}: parameter services did not appear")

    def lister(r: ParameterReader) -> Callable[[], Future]:
        return lambda: r.lister.call_async(ListParameters.Request(depth=0))

    def getter(r: ParameterReader, n: list[str]) -> Callable[[], Future]:
        return lambda: r.getter.call_async(GetParameters.Request(names=n))

    def describer(r: ParameterReader, n: list[str]) -> Callable[[], Future]:
        return lambda: r.describer.call_async(DescribeParameters.Request(names=n))

    names = [
        sorted(listed.result.names) for listed in answers([lister(r) for r in readers], timeout)
    ]
    pairs = list(zip(readers, names, strict=True))
    got = answers([getter(r, n) for r, n in pairs], timeout)
    described = answers([describer(r, n) for r, n in pairs], timeout)
    return {
        reader.target: parameters_of(
            listed,
            values_or_unset(reader, listed, values.values, timeout),
            descriptors.descriptors,
        )
        for reader, listed, values, descriptors in zip(readers, names, got, described, strict=True)
    }


def read_named(
    reader: ParameterReader, names: Sequence[str], timeout: float
) -> tuple[list[str], list[dict[str, Any]]]:
    """Every name the node declares, and those of ``names`` it declares, read in full."""
    if not reader.wait_ready(timeout):
        raise TimeoutError(f"{reader.target}: parameter services did not appear")
    listed = answers([lambda: reader.lister.call_async(ListParameters.Request(depth=0))], timeout)
    declared = list(listed[0].result.names)
    known = set(declared)
    wanted = [name for name in dict.fromkeys(names) if name in known]
    got, described = answers(
        [
            lambda: reader.getter.call_async(GetParameters.Request(names=wanted)),
            lambda: reader.describer.call_async(DescribeParameters.Request(names=wanted)),
        ],
        timeout,
    )
    values = values_or_unset(reader, wanted, got.values, timeout)
    return declared, parameters_of(wanted, values, described.descriptors)


def values_or_unset(
    reader: ParameterReader, names: Sequence[str], values: Sequence[Any], timeout: float
) -> Sequence[Any]:
    """``values``, or, when the get service answered nothing because a parameter is
    declared by type only and not set, each name's value asked alone (unset: NOT_SET)."""
    if len(values) == len(names):
        return values

    def alone(name: str) -> Callable[[], Future]:
        return lambda: reader.getter.call_async(GetParameters.Request(names=[name]))

    replies = [answer.values for answer in answers([alone(name) for name in names], timeout)]
    return [reply[0] if reply else ParameterValue() for reply in replies]


def parameters_of(
    names: Sequence[str], values: Sequence[Any], descriptors: Sequence[Any]
) -> list[dict[str, Any]]:
    return [
        {
            "name": name,
            "type": TYPE_NAMES.get(value.type, "unset"),
            "value": python_value(value),
            "read_only": descriptor.read_only,
            "description": descriptor.description,
            "constraints": descriptor.additional_constraints,
            "range": descriptor_range(descriptor),
        }
        for name, value, descriptor in zip(names, values, descriptors, strict=True)
    ]
