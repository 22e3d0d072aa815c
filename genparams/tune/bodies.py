"""What the tuning API reads from a request: node names and set bodies, or a clear refusal.

Anything a client sends that is not what the API takes becomes :class:`RequestError`
(a 400 naming the problem), never an exception from deeper down: JSON nested too
deep, integers outside int64, numbers no double holds, text that is not UTF-8
(a lone surrogate), invalid node names, wrong shapes.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from rclpy.parameter import Parameter

from genparams.runtime.naming import absolute, node_name_problem
from genparams.tune.graph import ros_parameter

INT64 = (-(1 << 63), (1 << 63) - 1)


class RequestError(ValueError):
    """A request the API cannot take; its text says why."""


@dataclass(frozen=True)
class SetRequest:
    node: str
    parameters: list[Parameter]
    atomic: bool


def node_name(given: object) -> str:
    """A fully qualified node name, or RequestError."""
    if not isinstance(given, str) or not given:
        raise RequestError("node: a node name such as /camera_driver is required")
    text(given, "node")
    problem = node_name_problem(given)
    if problem is not None:
        raise RequestError(f"node {given!r}: {problem}")
    return absolute(given)


def text(value: str, where: str) -> str:
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        raise RequestError(f"{where}: not valid UTF-8 text") from None
    return value


def carried(value: Any, where: str, integer: bool) -> None:
    """Refuse what no ROS parameter can hold: text that is not UTF-8; ints past int64."""
    if isinstance(value, bool):
        return
    if integer and isinstance(value, int) and not INT64[0] <= value <= INT64[1]:
        raise RequestError(
            f"{where}: {value if value.bit_length() < 128 else 'integer'} is outside int64"
        )
    if isinstance(value, str):
        text(value, where)
    if isinstance(value, list):
        for item in value:
            carried(item, where, integer)


def set_request(body: bytes) -> SetRequest:
    """``{"node": ..., "params": [{"name", "type", "value"}...], "atomic": bool}`` read."""
    try:
        data = json.loads(body)
    except RecursionError:
        raise RequestError("the body nests too deep") from None
    except ValueError as exc:
        raise RequestError(f"the body is not JSON: {exc}") from None
    if not isinstance(data, dict):
        raise RequestError("the body must be a JSON object")
    node = node_name(data.get("node"))
    params = data.get("params")
    if not isinstance(params, list) or not params:
        raise RequestError("params: a list of {name, type, value} is required")
    atomic = data.get("atomic", False)
    if not isinstance(atomic, bool):
        raise RequestError("atomic: true or false")
    parameters = []
    for index, item in enumerate(params):
        where = f"params[{index}]"
        if not isinstance(item, dict):
            raise RequestError(f"{where}: an object {{name, type, value}} is required")
        name, type_name, value = item.get("name"), item.get("type"), item.get("value")
        if not isinstance(name, str) or not name:
            raise RequestError(f"{where}.name: a parameter name is required")
        if not isinstance(type_name, str):
            raise RequestError(f"{where}.type: a parameter type is required")
        text(name, f"{where}.name")
        carried(value, name, type_name in ("int", "int_array"))
        try:
            parameter = ros_parameter(name, type_name, value)
        except (KeyError, ValueError, TypeError, OverflowError, AssertionError) as exc:
            raise RequestError(f"{name}: {type(exc).__name__}: {exc}") from None
        parameters.append(parameter)
    return SetRequest(node, parameters, atomic)
