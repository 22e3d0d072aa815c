"""Parameters as rclpy sees them: descriptors, values in ROS form, batched declaration."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from rcl_interfaces.msg import (
    FloatingPointRange,
    IntegerRange,
    ParameterDescriptor,
    SetParametersResult,
)
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime.core.rules import CompiledRule
from genparams.runtime.core.spec import CompiledParam
from genparams.runtime.node import rclpy_internals as internals


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


def declare_batch(node: Node, declarations: Sequence[Declaration]) -> None:
    """Declare parameters with their descriptors, one on-set and post-set round each.

    Node.declare_parameters infers the type from the value, which turns an
    empty list into BYTE_ARRAY; this path keeps the declared type.
    """
    parameters = [parameter for parameter, _ in declarations]
    internals.declare_with_descriptors(node, parameters, {p.name: d for p, d in declarations})


def replace_batch(
    node: Node, declarations: Sequence[Declaration], removed: Sequence[str]
) -> SetParametersResult:
    """Declare and undeclare parameters in one atomic change with one parameter event.

    rclpy's undeclare_parameter neither publishes the deletion nor undeclares a
    read-only parameter; a NOT_SET value under a dynamically typed descriptor
    does both, and new parameters in the same batch are announced together.
    """
    parameters = [parameter for parameter, _ in declarations]
    descriptors = {p.name: d for p, d in declarations}
    for name in removed:
        parameters.append(Parameter(name))
        descriptors[name] = ParameterDescriptor(name=name, dynamic_typing=True)
    return internals.set_with_descriptors(node, parameters, descriptors)
