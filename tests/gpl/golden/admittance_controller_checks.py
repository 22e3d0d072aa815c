"""Custom validators of the admittance_controller schema.

The schema references each as admittance_controller_checks:NAME.

Each takes the parameter's value (then the schema's args) and returns None
when it is valid, or a reason (str) when it is not. An empty string also means
valid, as in generate_parameter_library's Python validators, so a body ported from
one (which took the rclpy Parameter: use `value` where it read `param.value`)
may keep returning ""."""

from __future__ import annotations

from typing import Any


def no_args_validator(value: Any) -> str | None:
    """GPL: custom_validators::no_args_validator; used by interpolation_mode."""
    # TODO: port GPL's check (a C++ function, or a Python one returning "" when
    # valid, which this stub may keep doing); until then it accepts every value.
    return None


def validate_double_array_custom_func(value: Any, arg0: Any, arg1: Any) -> str | None:
    """GPL: custom_validators::validate_double_array_custom_func; used by
    admittance.damping_ratio."""
    # TODO: port GPL's check (a C++ function, or a Python one returning "" when
    # valid, which this stub may keep doing); until then it accepts every value.
    return None
