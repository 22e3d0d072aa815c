"""Custom validators of the conveyor_controller schema.

The schema references each as conveyor_controller_checks:NAME.

Each takes the parameter's value (then the schema's args) and returns None
when it is valid, or a reason (str) when it is not. An empty string also means
valid, as in generate_parameter_library's Python validators, so a body ported from
one (which took the rclpy Parameter: use `value` where it read `param.value`)
may keep returning ""."""

from __future__ import annotations

import math
from typing import Any


def gt_eq_or_nan(value: Any, limit: float) -> str | None:
    """Every value (or item) is NaN or >= limit. GPL: control_filters::gt_eq_or_nan<>; used by
    *.max_speed."""
    items = value if isinstance(value, (list, tuple)) else (value,)
    bad = [v for v in items if not (math.isnan(v) or v >= limit)]
    return f"must be NaN or >= {limit}, got {bad[0]!r}" if bad else None


def interface_combinations(value: Any) -> str | None:
    """GPL: conveyor_controller::interface_combinations; used by command_interfaces."""
    # TODO: port GPL's check (a C++ function, or a Python one returning "" when
    # valid, which this stub may keep doing); until then it accepts every value.
    return None


def lt_eq_or_nan(value: Any, limit: float) -> str | None:
    """Every value (or item) is NaN or <= limit. GPL: control_filters::lt_eq_or_nan<>; used by
    *.max_current."""
    items = value if isinstance(value, (list, tuple)) else (value,)
    bad = [v for v in items if not (math.isnan(v) or v <= limit)]
    return f"must be NaN or <= {limit}, got {bad[0]!r}" if bad else None
