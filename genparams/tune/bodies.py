"""What the tuning API reads from a request: node names, set and check bodies, or a refusal.

Anything a client sends that is not what the API takes becomes :class:`RequestError`
(a 400 naming the problem), never an exception from deeper down. A body is read
by the one JSON codec (:func:`genparams.runtime.core.json_codec.loads`: size, nesting,
numbers no double holds, lone surrogates), each value is typed by the runtime's
rules (:func:`genparams.tune.checking.json_parameter`: the wrong JSON type and
integers outside int64 are refused), and node names by ROS's rules.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from rclpy.parameter import Parameter

from genparams.runtime.core.errors import GenparamsError
from genparams.runtime.core.json_codec import API_LIMITS, JsonError, loads
from genparams.runtime.core.naming import absolute, node_name_problem
from genparams.tune.checking import json_parameter


class RequestError(GenparamsError, ValueError):
    """A request the API cannot take; its text says why."""


@dataclass(frozen=True)
class Edits:
    """A body of ``/api/set`` or ``/api/check``: (name, type, JSON value) per parameter."""

    node: str
    params: list[tuple[str, str, Any]]
    atomic: bool


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


def edits(body: bytes) -> Edits:
    """``{"node": ..., "params": [{"name", "type", "value"}...], "atomic": bool}`` read."""
    try:
        data = loads(body, API_LIMITS)
    except JsonError as exc:
        raise RequestError(f"the body: {exc}") from None
    if not isinstance(data, dict):
        raise RequestError("the body must be a JSON object")
    node = node_name(data.get("node"))
    params = data.get("params")
    if not isinstance(params, list) or not params:
        raise RequestError("params: a list of {name, type, value} is required")
    atomic = data.get("atomic", False)
    if not isinstance(atomic, bool):
        raise RequestError("atomic: true or false")
    found = []
    for index, item in enumerate(params):
        where = f"params[{index}]"
        if not isinstance(item, dict):
            raise RequestError(f"{where}: an object {{name, type, value}} is required")
        name, type_name = item.get("name"), item.get("type")
        if not isinstance(name, str) or not name:
            raise RequestError(f"{where}.name: a parameter name is required")
        if not isinstance(type_name, str):
            raise RequestError(f"{where}.type: a parameter type is required")
        if "value" not in item:
            raise RequestError(f"{where}.value: a value is required")
        found.append((name, type_name, item["value"]))
    return Edits(node, found, atomic)


def set_request(body: bytes) -> SetRequest:
    """A set body, every value typed as its parameter's type (refused, never converted)."""
    wanted = edits(body)
    try:
        parameters = [json_parameter(*edit) for edit in wanted.params]
    except ValueError as exc:
        raise RequestError(str(exc)) from None
    return SetRequest(wanted.node, parameters, wanted.atomic)
