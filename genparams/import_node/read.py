"""Read every parameter of a running node over its list, get and describe services."""

from __future__ import annotations

from typing import Any

from rcl_interfaces.msg import ParameterValue
from rcl_interfaces.srv import DescribeParameters, GetParameters, ListParameters

from genparams.import_node.convert import NOT_SET, Reported
from genparams.tune.graph import Graph
from genparams.tune.reader import answers, python_value


def read_node(node: str, timeout: float) -> list[Reported]:
    """What ``ros2 param list``, ``get`` and ``describe`` show of ``node``, one call each.

    Raises TimeoutError when the node's services do not appear or answer in time."""
    graph = Graph("genparams_import_node")
    try:
        reader = graph.reader(node)
        if not reader.wait_ready(timeout):
            raise TimeoutError(f"{node}: parameter services did not appear in {timeout:g} s")
        # A service is ready before its replies to a new client can arrive: the first
        # requests are sent again until answered.
        listing = answers(
            [lambda: reader.lister.call_async(ListParameters.Request(depth=0))], timeout
        )
        names = sorted(listing[0].result.names)
        got, described = answers(
            [
                lambda: reader.getter.call_async(GetParameters.Request(names=names)),
                lambda: reader.describer.call_async(DescribeParameters.Request(names=names)),
            ],
            timeout,
        )
        values = list(got.values)
        descriptors = described.descriptors
        if len(values) != len(names):
            # rclpy answers a get naming a parameter declared by type only, with no value
            # yet, with no values at all: ask one name at a time, that one reads as unset.
            values = [_value(reader.getter, name, timeout) for name in names]
    finally:
        graph.close()
    return [_reported(n, v, d) for n, v, d in zip(names, values, descriptors, strict=True)]


def _value(getter: Any, name: str, timeout: float) -> Any:
    asked = answers([lambda: getter.call_async(GetParameters.Request(names=[name]))], timeout)
    return asked[0].values[0] if asked[0].values else ParameterValue(type=NOT_SET)


def _reported(name: str, value: Any, descriptor: Any) -> Reported:
    integer = descriptor.integer_range[0] if descriptor.integer_range else None
    floating = descriptor.floating_point_range[0] if descriptor.floating_point_range else None
    return Reported(
        name=name,
        type=value.type,
        value=None if value.type == NOT_SET else python_value(value),
        description=descriptor.description,
        additional_constraints=descriptor.additional_constraints,
        read_only=descriptor.read_only,
        dynamic_typing=descriptor.dynamic_typing,
        descriptor_type=descriptor.type,
        integer_range=None
        if integer is None
        else (integer.from_value, integer.to_value, integer.step),
        floating_point_range=None
        if floating is None
        else (floating.from_value, floating.to_value, floating.step),
    )
