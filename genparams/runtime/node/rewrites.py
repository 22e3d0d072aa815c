"""Requests rewritten before rclpy checks them: one pre-set callback per node.

rclpy concatenates the lists its pre-set callbacks return, so two callbacks
that each hand back the request would make it set every parameter twice.
genparams installs a single pre-set callback per node and passes the request
through each binding's rewrite in turn.

Old names are mirrored onto current names this way (``aliases.py``). Typed
empty arrays (below) are not a pre-set callback: the node's set path applies
them (``consistency.NodeSets``), so a class without old names adds no pre-set
callback and no list copy to a set.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING

from rclpy.parameter import Parameter

from genparams.runtime.core.spec import CompiledParam

if TYPE_CHECKING:
    from rclpy.node import Node

Rewrite = Callable[[list[Parameter]], list[Parameter]]

_ATTRIBUTE = "_genparams_rewrites"
_INSTALLING = threading.Lock()

_ARRAY_TYPES = (
    Parameter.Type.BYTE_ARRAY,
    Parameter.Type.BOOL_ARRAY,
    Parameter.Type.INTEGER_ARRAY,
    Parameter.Type.DOUBLE_ARRAY,
    Parameter.Type.STRING_ARRAY,
)


def add_rewrite(node: Node, rewrite: Rewrite) -> None:
    """Run ``rewrite`` on every set request of ``node``, after those added before it."""
    with _INSTALLING:
        rewrites: list[Rewrite] | None = getattr(node, _ATTRIBUTE, None)
        if rewrites is None:
            rewrites = []
            setattr(node, _ATTRIBUTE, rewrites)
            node.add_pre_set_parameters_callback(_chain(rewrites))
        rewrites.append(rewrite)


def _chain(rewrites: list[Rewrite]) -> Callable[[Sequence[Parameter]], list[Parameter]]:
    def pre_set(parameters: Sequence[Parameter]) -> list[Parameter]:
        # rclpy copies what this returns into a list of its own, so an unchanged
        # request is handed back as it came: a set is on the hot path.
        request = parameters if isinstance(parameters, list) else list(parameters)
        for rewrite in tuple(rewrites):
            request = rewrite(request)
        return request

    return pre_set


def typed_empty_arrays(declared: Mapping[str, CompiledParam]) -> Rewrite:
    """An empty array request takes the declared array type of the parameter it sets.

    An empty list carries no element type: `ros2 param set /node gains "[]"` sends a
    BOOL_ARRAY, rclpy's own ``Parameter`` makes it a BYTE_ARRAY. rclpy would refuse
    either for an ``int_array`` parameter although the value fits it.
    ``declared`` (full name -> parameter) is read at each set, so entries that
    mapped groups add later are covered.
    """

    def rewrite(parameters: list[Parameter]) -> list[Parameter]:
        for parameter in parameters:  # a plain loop: any() over a generator costs on every set
            if not parameter.value and _is_empty_array(parameter):  # most values are truthy
                break
        else:
            return parameters
        return [
            _retyped(parameter, declared) if _is_empty_array(parameter) else parameter
            for parameter in parameters
        ]

    return rewrite


_BYTES, _BOOLS, _INTS, _DOUBLES, _STRINGS = _ARRAY_TYPES


def _is_empty_array(parameter: Parameter) -> bool:
    # Identity tests: `in` a set of Enum members calls Enum.__hash__, in Python, every set.
    kind = parameter.type_
    return (
        kind is _DOUBLES or kind is _INTS or kind is _STRINGS or kind is _BOOLS or kind is _BYTES
    ) and len(parameter.value) == 0


def _retyped(parameter: Parameter, declared: Mapping[str, CompiledParam]) -> Parameter:
    param = declared.get(parameter.name)
    if param is None or not param.type.is_array:
        return parameter
    wanted = Parameter.Type(param.type.ros_type)
    if parameter.type_ == wanted:
        return parameter
    return Parameter(parameter.name, wanted, [])
