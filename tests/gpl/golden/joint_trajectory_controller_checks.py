"""Custom validators of the joint_trajectory_controller schema.

The schema references each as joint_trajectory_controller_checks:NAME.

Each takes the parameter's value (then the schema's args) and returns None
when it is valid, or a reason (str) when it is not."""

from __future__ import annotations

from typing import Any


def command_interface_type_combinations(value: Any) -> str | None:
    """GPL: joint_trajectory_controller::command_interface_type_combinations; used by
    command_interfaces."""
    # TODO: write the check GPL's C++ function made; this stub accepts every value.
    return None


def state_interface_type_combinations(value: Any) -> str | None:
    """GPL: joint_trajectory_controller::state_interface_type_combinations; used by
    state_interfaces."""
    # TODO: write the check GPL's C++ function made; this stub accepts every value.
    return None
