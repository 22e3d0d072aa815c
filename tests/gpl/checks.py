"""A custom validator with an argument, as real schemas use (NaN means "no limit")."""

from __future__ import annotations

import math


def at_least_or_nan(value: float, limit: float) -> str | None:
    if math.isnan(value) or value >= limit:
        return None
    return f"must be NaN or >= {limit}"
