"""Read every parameter of a running node with the live graph's one reader."""

from __future__ import annotations

from typing import Any

from genparams.import_node.convert import NOT_SET, Reported
from genparams.live.answers import ReadParameter, python_value
from genparams.live.graph import Graph


def read_node(node: str, timeout: float) -> list[Reported]:
    """What ``ros2 param list``, ``get`` and ``describe`` show of ``node``.

    Raises TimeoutError when the node's services do not appear or answer in time, and
    :class:`~genparams.live.answers.NodeAnswerError` when what they answer cannot be used."""
    graph = Graph("genparams_import_node")
    try:
        read = graph.read_raw([node], timeout)[node]
    finally:
        graph.close()
    return [_reported(parameter) for parameter in read]


def _range(ranges: Any) -> tuple[Any, Any, Any] | None:
    return (ranges[0].from_value, ranges[0].to_value, ranges[0].step) if ranges else None


def _reported(parameter: ReadParameter) -> Reported:
    value, descriptor = parameter.value, parameter.descriptor
    return Reported(
        name=parameter.name,
        type=value.type,
        value=None if value.type == NOT_SET else python_value(value),
        description=descriptor.description,
        additional_constraints=descriptor.additional_constraints,
        read_only=descriptor.read_only,
        dynamic_typing=descriptor.dynamic_typing,
        descriptor_type=descriptor.type,
        integer_range=_range(descriptor.integer_range),
        floating_point_range=_range(descriptor.floating_point_range),
    )
