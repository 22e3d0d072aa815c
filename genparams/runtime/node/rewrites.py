"""Requests rewritten inside genparams' set path, before rclpy checks them.

genparams adds no pre-set callback: rclpy joins the lists its pre-set callbacks
return, so a callback of genparams handing back the request would turn an
application's refusal (a pre-set callback returning ``[]``) into a set, and
would read each item before rclpy refuses one that is no Parameter. Rewrites
run in the node's set path instead (``consistency.NodeSets``), under its set
lock, after rclpy ran the pre-set callbacks and checked the items: typed empty
arrays (below) and the other names of renamed parameters (``aliases.py``).
A class with neither adds no list copy to a set.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from rclpy.parameter import Parameter

from genparams.runtime.core.spec import CompiledParam

Rewrite = Callable[[list[Parameter]], list[Parameter]]

_ARRAY_TYPES = (
    Parameter.Type.BYTE_ARRAY,
    Parameter.Type.BOOL_ARRAY,
    Parameter.Type.INTEGER_ARRAY,
    Parameter.Type.DOUBLE_ARRAY,
    Parameter.Type.STRING_ARRAY,
)


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
