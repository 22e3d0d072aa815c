"""Custom validators of the joint_trajectory_controller schema.

The schema references each as joint_trajectory_controller_checks:NAME.

Each takes the parameter's value (then the schema's args) and returns None
when it is valid, or a reason (str) when it is not. An empty string also means
valid, as in generate_parameter_library's Python validators, so a body ported from
one (which took the rclpy Parameter: use `value` where it read `param.value`)
may keep returning ""."""

from __future__ import annotations

from typing import Any


def command_interface_type_combinations(value: Any) -> str | None:
    """GPL: joint_trajectory_controller::command_interface_type_combinations; used by
    command_interfaces."""
    # TODO: port GPL's check (a C++ function, or a Python one returning "" when
    # valid, which this stub may keep doing); until then it accepts every value.
    return None


def state_interface_type_combinations(value: Any) -> str | None:
    """GPL: joint_trajectory_controller::state_interface_type_combinations; used by
    state_interfaces."""
    # TODO: port GPL's check (a C++ function, or a Python one returning "" when
    # valid, which this stub may keep doing); until then it accepts every value.
    return None
