"""What a node's parameter services answered, checked once before anything uses it.

A node on the graph answers ``list``, ``get`` and ``describe`` as it likes: fewer
descriptors than names, a value of type 42, a million names, a name a thousand
segments deep, a string of many megabytes. Every answer passes :func:`checked_list`,
:func:`checked_values` and :func:`checked_descriptors` here; what fails is a
:class:`NodeAnswerError` naming the node and what is wrong, which the tools show as a
finding (audit), a 4xx (the page) or an error line (import-node), never a traceback.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from rcl_interfaces.msg import ParameterType, ParameterValue
from rclpy.parameter import parameter_value_to_python

from genparams.runtime.core.errors import GenparamsError

MAX_PARAMETERS = 100_000
"""Names a node may list: about 25 times the largest real node seen."""
MAX_NAME_CHARS = 1_000
MAX_NAME_SEGMENTS = 64
MAX_TEXT_CHARS = 1 << 20
"""The longest string value, description or constraint text."""
MAX_ITEMS = 1 << 20
"""The longest array value."""
MAX_ANSWER_UNITS = 16 << 20
"""Characters and array items of one answer together: what the tools hold and send on."""

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
NOT_SET = ParameterType.PARAMETER_NOT_SET


class NodeAnswerError(GenparamsError, ValueError):
    """An answer of a node's parameter services that cannot be used; the text says why."""


@dataclass(frozen=True)
class ReadParameter:
    """One parameter as the node reported it: its name, value and descriptor, checked."""

    name: str
    value: Any  # rcl_interfaces/ParameterValue
    descriptor: Any  # rcl_interfaces/ParameterDescriptor

    @property
    def type_name(self) -> str:
        return TYPE_NAMES.get(self.value.type, "unset")

    def as_json(self) -> dict[str, Any]:
        """The page's and the audit's view: name, type, value and what the descriptor says."""
        descriptor = self.descriptor
        return {
            "name": self.name,
            "type": self.type_name,
            "value": python_value(self.value),
            "read_only": descriptor.read_only,
            "description": descriptor.description,
            "constraints": descriptor.additional_constraints,
            "range": descriptor_range(descriptor),
        }


def python_value(value: Any) -> Any:
    """A checked ParameterValue as JSON-ready Python: arrays as lists, bytes as ints."""
    if value.type == NOT_SET:
        return None
    plain = parameter_value_to_python(value)
    if value.type == ParameterType.PARAMETER_BYTE_ARRAY:
        return [b if isinstance(b, int) else ord(b) for b in plain]
    if isinstance(plain, list | tuple) or hasattr(plain, "tolist"):
        return list(plain)
    return plain


def descriptor_range(descriptor: Any) -> dict[str, Any] | None:
    for ranges in (descriptor.integer_range, descriptor.floating_point_range):
        if ranges:
            first = ranges[0]
            return {"min": first.from_value, "max": first.to_value, "step": first.step}
    return None


class Budget:
    """The characters and items one answer may hold in all (``MAX_ANSWER_UNITS``)."""

    def __init__(self, node: str, what: str) -> None:
        self.node = node
        self.what = what
        self.left = MAX_ANSWER_UNITS

    def spend(self, units: int) -> None:
        self.left -= units
        if self.left < 0:
            raise self.bad(f"more than {MAX_ANSWER_UNITS} characters and items in all")

    def bad(self, detail: str) -> NodeAnswerError:
        return NodeAnswerError(f"{self.node}: its {self.what} answer cannot be used: {detail}")


def _text(budget: Budget, text: Any, where: str, limit: int = MAX_TEXT_CHARS) -> str:
    if not isinstance(text, str):
        raise budget.bad(f"{where} is not text")
    if len(text) > limit:
        raise budget.bad(f"{where} holds {len(text)} characters (at most {limit})")
    budget.spend(len(text))
    return text


def checked_list(node: str, result: Any) -> list[str]:
    """The names a ``list_parameters`` answer gives, each once, sorted; or NodeAnswerError."""
    budget = Budget(node, "list_parameters")
    names = result.names
    if len(names) > MAX_PARAMETERS:
        raise budget.bad(f"{len(names)} names (at most {MAX_PARAMETERS})")
    for index, name in enumerate(names):
        _text(budget, name, f"name {index}", MAX_NAME_CHARS)
        if not name or name.count(".") >= MAX_NAME_SEGMENTS:
            shown = "an empty name" if not name else f"{name[:40]!r}... nests"
            raise budget.bad(f"{shown} (at most {MAX_NAME_SEGMENTS} segments)")
    return sorted(set(names))


def _check_value(budget: Budget, value: Any, where: str) -> None:
    kind = value.type
    if kind != NOT_SET and kind not in TYPE_NAMES:
        raise budget.bad(f"{where} has type {kind}, which no parameter has")
    arrays = (
        value.byte_array_value,
        value.bool_array_value,
        value.integer_array_value,
        value.double_array_value,
        value.string_array_value,
    )
    for array in arrays:
        if len(array) > MAX_ITEMS:
            raise budget.bad(f"{where} holds {len(array)} items (at most {MAX_ITEMS})")
        budget.spend(len(array))
    _text(budget, value.string_value, f"{where}'s text")
    for item in value.string_array_value:
        _text(budget, item, f"an item of {where}")


def checked_values(node: str, names: Sequence[str], values: Sequence[Any]) -> list[Any]:
    """A ``get_parameters`` answer, one value per name; or NodeAnswerError."""
    budget = Budget(node, "get_parameters")
    if len(values) != len(names):
        raise budget.bad(f"{len(values)} values for {len(names)} names")
    for name, value in zip(names, values, strict=True):
        _check_value(budget, value, f"the value of {name!r}")
    return list(values)


def checked_descriptors(node: str, names: Sequence[str], descriptors: Sequence[Any]) -> list[Any]:
    """A ``describe_parameters`` answer, one descriptor per name; or NodeAnswerError."""
    budget = Budget(node, "describe_parameters")
    if len(descriptors) != len(names):
        raise budget.bad(f"{len(descriptors)} descriptors for {len(names)} names")
    for name, descriptor in zip(names, descriptors, strict=True):
        where = f"the descriptor of {name!r}"
        _text(budget, descriptor.description, f"{where}'s description")
        _text(budget, descriptor.additional_constraints, f"{where}'s constraints")
        if len(descriptor.integer_range) > 1 or len(descriptor.floating_point_range) > 1:
            raise budget.bad(f"{where} has more than one range")
        if descriptor.type != NOT_SET and descriptor.type not in TYPE_NAMES:
            raise budget.bad(f"{where} has type {descriptor.type}, which no parameter has")
    return list(descriptors)


def checked_single(node: str, name: str, values: Sequence[Any]) -> Any:
    """The answer to a ``get_parameters`` of one name: its value, or unset when none came."""
    if not values:
        return ParameterValue(type=NOT_SET)
    return checked_values(node, [name], values)[0]
