"""Custom validators of the diff_drive_controller schema.

The schema references each as diff_drive_controller_checks:NAME.

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
    angular.z.max_acceleration, angular.z.max_deceleration_reverse, angular.z.max_jerk,
    angular.z.max_velocity, linear.x.max_acceleration, linear.x.max_deceleration_reverse,
    linear.x.max_jerk, linear.x.max_velocity."""
    items = value if isinstance(value, (list, tuple)) else (value,)
    bad = [v for v in items if not (math.isnan(v) or v >= limit)]
    return f"must be NaN or >= {limit}, got {bad[0]!r}" if bad else None


def lt_eq_or_nan(value: Any, limit: float) -> str | None:
    """Every value (or item) is NaN or <= limit. GPL: control_filters::lt_eq_or_nan<>; used by
    angular.z.max_acceleration_reverse, angular.z.max_deceleration, angular.z.min_jerk,
    angular.z.min_velocity, linear.x.max_acceleration_reverse, linear.x.max_deceleration,
    linear.x.min_jerk, linear.x.min_velocity."""
    items = value if isinstance(value, (list, tuple)) else (value,)
    bad = [v for v in items if not (math.isnan(v) or v <= limit)]
    return f"must be NaN or <= {limit}, got {bad[0]!r}" if bad else None
