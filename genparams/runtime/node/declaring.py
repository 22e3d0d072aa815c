"""Parameters as rclpy sees them: descriptors, values in ROS form, batched declaration."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from rcl_interfaces.msg import (
    FloatingPointRange,
    IntegerRange,
    ParameterDescriptor,
    SetParametersResult,
)
from rclpy.exceptions import InvalidParameterValueException
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime.core.errors import ParameterDeclarationError
from genparams.runtime.core.problems import ParameterProblem
from genparams.runtime.core.spec import CompiledParam
from genparams.runtime.node import rclpy_internals as internals

if TYPE_CHECKING:
    from genparams.runtime.core.rules import CompiledRule  # loaded with the first rule


def descriptor_for(
    param: CompiledParam, full_name: str, rules: Sequence[CompiledRule] = ()
) -> ParameterDescriptor:
    """The parameter's descriptor; ``rules`` (those that read it) are stated after its own
    constraints, so ``ros2 param describe`` shows them."""
    constraints = [param.constraints_text] if param.constraints_text else []
    constraints += [rule_text(rule) for rule in rules]
    descriptor = ParameterDescriptor(
        name=full_name,
        type=param.type.ros_type,
        description=param.descriptor_description,
        additional_constraints="; ".join(constraints),
        read_only=param.spec.read_only,
        dynamic_typing=param.type.is_dynamic,
    )
    ros_range = param.descriptor_range
    if ros_range is not None:
        if ros_range.integer:
            descriptor.integer_range = [
                IntegerRange(
                    from_value=int(ros_range.low),
                    to_value=int(ros_range.high),
                    step=int(ros_range.step),
                )
            ]
        else:
            descriptor.floating_point_range = [
                FloatingPointRange(
                    from_value=float(ros_range.low),
                    to_value=float(ros_range.high),
                    step=float(ros_range.step),
                )
            ]
    return descriptor


def rule_text(rule: CompiledRule) -> str:
    """A rule as a descriptor states it: ``rule speed_order: min_speed <= max_speed (why)``."""
    check = " ".join(rule.check.split())  # one line, however the schema wrapped it
    return f"rule {rule.name}: {check}" + (f" ({rule.description})" if rule.description else "")


def ros_parameter(param: CompiledParam, full_name: str, value: Any) -> Parameter:
    """A typed-view value as an rclpy Parameter of the declared type (never inferred),
    or, for a parameter of type ``any``, of the value's own type.

    None, an optional parameter not set, is NOT_SET: rclpy stores it so under a
    statically typed descriptor, as ``declare_parameter(name, Parameter.Type.X)`` does.
    """
    if value is None:
        return Parameter(full_name, Parameter.Type.NOT_SET)
    kind = param.type.of_value(value)
    return Parameter(full_name, Parameter.Type(kind.ros_type), kind.to_ros(value))


Declaration = tuple[Parameter, ParameterDescriptor]


DECLARE_ROUND = 256
"""Parameters declared per atomic round of rclpy's set path (one on-set, post-set and
ParameterEvent each): a bounded number of rounds, and no round so large that a user's
on-set callback walks thousands of parameters at once."""


class DeclarationRefusedError(ParameterDeclarationError, InvalidParameterValueException):
    """A round of a class's declaration was refused (an on-set callback, or rclpy's own
    descriptor check); every parameter of the class declared before it is undeclared again.

    An InvalidParameterValueException, as rclpy raises when a declaration is refused,
    so code that handles rclpy's refusal handles this one.
    """

    def __init__(self, schema: str, node: str, problems: Sequence[ParameterProblem]) -> None:
        ParameterDeclarationError.__init__(self, schema, node, problems)


def declare_batch(
    node: Node, declarations: Sequence[Declaration], schema: str = "", size: int = DECLARE_ROUND
) -> None:
    """Declare parameters with their descriptors in atomic rounds of at most ``size``:
    all or nothing. When a round is refused or raises, every parameter the earlier rounds
    declared is undeclared again (and announced deleted) before the error propagates.

    Node.declare_parameters infers the type from the value, which turns an
    empty list into BYTE_ARRAY; this path keeps the declared type.
    """
    attempted: list[str] = []
    try:
        for start in range(0, len(declarations), size):
            round_ = declarations[start : start + size]
            parameters = [parameter for parameter, _ in round_]
            attempted.extend(parameter.name for parameter in parameters)
            descriptors = {parameter.name: descriptor for parameter, descriptor in round_}
            result = internals.declare_with_descriptors(node, parameters, descriptors)
            if not result.successful:
                raise DeclarationRefusedError(
                    schema,
                    node.get_fully_qualified_name(),
                    [_refusal(node, round_, result.reason)],
                )
    except BaseException:
        internals.forget_declared(node, attempted)
        raise


def _refusal(node: Node, round_: Sequence[Declaration], reason: str) -> ParameterProblem:
    """What refused a round: the parameter rclpy's descriptor check refuses, else the round
    (an on-set callback refuses a whole request, naming no parameter)."""
    for parameter, descriptor in round_:
        if not internals.descriptor_check(node, parameter, descriptor, False).successful:
            return ParameterProblem(parameter.name, reason)
    if len(round_) == 1:
        return ParameterProblem(round_[0][0].name, f"refused by an on-set callback: {reason}")
    first, last = round_[0][0].name, round_[-1][0].name
    return ParameterProblem(
        "",
        f"an on-set callback refused the round declaring {len(round_)} parameters "
        f"({first} to {last}): {reason}",
    )


def replace_batch(
    node: Node, declarations: Sequence[Declaration], removed: Sequence[str]
) -> SetParametersResult:
    """Declare and undeclare parameters in one atomic change with one parameter event.

    rclpy's undeclare_parameter neither publishes the deletion nor undeclares a
    read-only parameter; a NOT_SET value under a dynamically typed descriptor
    does both, and new parameters in the same batch are announced together.
    New parameters declared by type only (NOT_SET, optional) cannot share that change,
    where NOT_SET undeclares: they are declared in a round just before it, and
    undeclared again if it is refused.
    """
    unset = [(p, d) for p, d in declarations if p.type_ == Parameter.Type.NOT_SET]
    if unset:  # declared by type only: a round of their own, undone if the change is refused
        result = internals.declare_with_descriptors(
            node, [p for p, _ in unset], {p.name: d for p, d in unset}
        )
        if not result.successful:
            return result
    parameters = [p for p, _ in declarations if p.type_ != Parameter.Type.NOT_SET]
    descriptors = {p.name: d for p, d in declarations if p.type_ != Parameter.Type.NOT_SET}
    for name in removed:
        parameters.append(Parameter(name))
        descriptors[name] = ParameterDescriptor(name=name, dynamic_typing=True)
    result = internals.set_with_descriptors(node, parameters, descriptors)
    if not result.successful:
        internals.forget_declared(node, [p.name for p, _ in unset])
    return result
