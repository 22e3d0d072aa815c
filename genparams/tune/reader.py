"""Read a node's parameters with the three services that reading needs.

rclpy's AsyncParameterClient opens six service clients; each is a pair of DDS
endpoints that every participant must match, about 4 ms apiece. Reading (the
page opening a node, an audit) needs list, get and describe only; the set
services are opened when a set is made.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Sequence
from typing import Any

from rcl_interfaces.msg import ParameterType, ParameterValue
from rcl_interfaces.srv import DescribeParameters, GetParameters, ListParameters
from rclpy.client import Client
from rclpy.node import Node
from rclpy.parameter import parameter_value_to_python
from rclpy.task import Future

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


def read_all(readers: Sequence[ParameterReader], timeout: float) -> dict[str, list[dict[str, Any]]]:
    """Every parameter of every reader's node; each step's calls go out together."""
    for reader in readers:
        if not reader.wait_ready(timeout):
            raise TimeoutError(f"{reader.target}: parameter services did not appear")
    listing = [r.lister.call_async(ListParameters.Request(depth=0)) for r in readers]
    names = [sorted(wait_future(f, timeout).result.names) for f in listing]
    getting = [
        r.getter.call_async(GetParameters.Request(names=n))
        for r, n in zip(readers, names, strict=True)
    ]
    describing = [
        r.describer.call_async(DescribeParameters.Request(names=n))
        for r, n in zip(readers, names, strict=True)
    ]
    return {
        reader.target: parameters_of(
            listed,
            values_or_unset(reader, listed, wait_future(got, timeout).values, timeout),
            wait_future(described, timeout).descriptors,
        )
        for reader, listed, got, described in zip(readers, names, getting, describing, strict=True)
    }


def read_named(
    reader: ParameterReader, names: Sequence[str], timeout: float
) -> tuple[list[str], list[dict[str, Any]]]:
    """Every name the node declares, and those of ``names`` it declares, read in full."""
    if not reader.wait_ready(timeout):
        raise TimeoutError(f"{reader.target}: parameter services did not appear")
    listing = reader.lister.call_async(ListParameters.Request(depth=0))
    declared = list(wait_future(listing, timeout).result.names)
    known = set(declared)
    wanted = [name for name in dict.fromkeys(names) if name in known]
    got = reader.getter.call_async(GetParameters.Request(names=wanted))
    described = reader.describer.call_async(DescribeParameters.Request(names=wanted))
    values = values_or_unset(reader, wanted, wait_future(got, timeout).values, timeout)
    return declared, parameters_of(wanted, values, wait_future(described, timeout).descriptors)


def values_or_unset(
    reader: ParameterReader, names: Sequence[str], values: Sequence[Any], timeout: float
) -> Sequence[Any]:
    """``values``, or, when the get service answered nothing because a parameter is
    declared by type only and not set, each name's value asked alone (unset: NOT_SET)."""
    if len(values) == len(names):
        return values
    alone = [reader.getter.call_async(GetParameters.Request(names=[name])) for name in names]
    answers = [wait_future(future, timeout).values for future in alone]
    return [answer[0] if answer else ParameterValue() for answer in answers]


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
