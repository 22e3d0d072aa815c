"""GPL's ``validation:`` entries, translated to genparams validators one by one.

GPL writes ``name<>: ARGS`` or ``name: ARGS`` (the ``<>`` marks a template
function in C++ and means nothing here), ARGS being a list of arguments, a
single scalar, or null. Built-in names map to built-in validators; any other
name (``control_filters::gt_eq_or_nan<>``) is a function the user writes in
Python, referenced as a custom validator with its arguments.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from genparams.runtime.types import INT64_MAX, INT64_MIN


@dataclass(frozen=True)
class Translated:
    """One GPL validation entry in genparams form; ``custom`` names a function to write."""

    validators: tuple[Any, ...] = ()  # genparams validator entries (str or one-key dict)
    element_low: float | None = None  # lower_element_bounds, merged with upper later
    element_high: float | None = None
    range: tuple[float, float] | None = None  # bounds of a scalar: the descriptor's range, as GPL
    custom: str = ""  # the Python function name the user implements
    problem: str = ""  # why it could not be translated


def gpl_name(key: str) -> str:
    """``gt_eq<>`` -> ``gt_eq``; ``control_filters::gt_eq_or_nan<>`` keeps its namespace."""
    return key[:-2] if key.endswith("<>") else key


def arguments(raw: Any) -> list[Any]:
    """GPL's argument list: ``[0.0]`` -> [0.0], ``3`` -> [3], ``null`` / ``[]`` -> []."""
    if raw is None:
        return []
    if isinstance(raw, list):
        return raw
    return [raw]


def _one(name: str, args: list[Any]) -> Any:
    if len(args) != 1:
        raise ValueError(f"{name} takes one argument, got {len(args)}")
    return args[0]


def _size(rule: Callable[[int], Any]) -> Callable[[str, list[Any], str], Translated]:
    def build(name: str, args: list[Any], _type: str) -> Translated:
        size = _one(name, args)
        if isinstance(size, bool) or not isinstance(size, int):
            raise ValueError(f"{name} takes an integer size, got {size!r}")
        return Translated(validators=({"length": rule(size)},))

    return build


def _compare(rule: str) -> Callable[[str, list[Any], str], Translated]:
    def build(name: str, args: list[Any], param_type: str) -> Translated:
        limit = _one(name, args)
        if param_type.endswith("_array"):
            # GPL compares every element of an array parameter.
            low = limit if rule in ("gt", "ge") else None
            high = limit if rule in ("lt", "le") else None
            if rule in ("gt", "lt"):
                raise ValueError(f"{name} on an array has no genparams form (strict bound)")
            return Translated(element_low=low, element_high=high)
        return Translated(validators=({rule: limit},))

    return build


def _bounds(name: str, args: list[Any], param_type: str) -> Translated:
    if len(args) != 2:
        raise ValueError(f"{name} takes [low, high], got {args!r}")
    if param_type.endswith("_array"):
        return Translated(validators=({"element_bounds": list(args)},))
    return Translated(range=(args[0], args[1]))


def _element_bound(side: str) -> Callable[[str, list[Any], str], Translated]:
    def build(name: str, args: list[Any], _type: str) -> Translated:
        limit = _one(name, args)
        if side == "low":
            return Translated(element_low=limit)
        return Translated(element_high=limit)

    return build


def _choices(rule: str) -> Callable[[str, list[Any], str], Translated]:
    def build(name: str, args: list[Any], _type: str) -> Translated:
        choices = _one(name, args)
        if not isinstance(choices, list):
            raise ValueError(f"{name} takes a list of choices, got {choices!r}")
        return Translated(validators=({rule: choices},))

    return build


def _flag(rule: str) -> Callable[[str, list[Any], str], Translated]:
    def build(name: str, args: list[Any], _type: str) -> Translated:
        if args:
            raise ValueError(f"{name} takes no argument, got {args!r}")
        return Translated(validators=(rule,))

    return build


BUILT_IN: dict[str, Callable[[str, list[Any], str], Translated]] = {
    "gt": _compare("gt"),
    "lt": _compare("lt"),
    "gt_eq": _compare("ge"),
    "lt_eq": _compare("le"),
    "bounds": _bounds,
    "element_bounds": _bounds,
    "lower_element_bounds": _element_bound("low"),
    "upper_element_bounds": _element_bound("high"),
    "size_lt": _size(lambda n: {"max": n - 1}),
    "size_gt": _size(lambda n: {"min": n + 1}),
    "fixed_size": _size(lambda n: n),
    "not_empty": _flag("not_empty"),
    "unique": _flag("unique"),
    "one_of": _choices("one_of"),
    "subset_of": _choices("subset_of"),
}


def custom_function_name(name: str) -> str:
    """The Python function for a GPL custom validator: its last ``::`` part."""
    return name.rsplit("::", 1)[-1]


def translate(key: str, raw: Any, param_type: str, checks_module: str) -> Translated:
    name = gpl_name(key)
    args = arguments(raw)
    build = BUILT_IN.get(name)
    if build is None:
        function = custom_function_name(name)
        if not function.isidentifier():
            return Translated(problem=f"validator {key!r} has no Python function name")
        target = f"{checks_module}:{function}"
        entry: Any = {"function": target, "args": args} if args else target
        return Translated(validators=({"custom": entry},), custom=function)
    try:
        return build(name, args, param_type)
    except ValueError as exc:
        return Translated(problem=str(exc))


def element_bounds(low: float | None, high: float | None, param_type: str) -> dict[str, Any]:
    """One ``element_bounds`` from GPL's separate lower / upper element bounds."""
    if param_type.startswith("int"):
        lower: float = INT64_MIN if low is None else low
        upper: float = INT64_MAX if high is None else high
    else:
        lower = -math.inf if low is None else low
        upper = math.inf if high is None else high
    return {"element_bounds": [lower, upper]}
