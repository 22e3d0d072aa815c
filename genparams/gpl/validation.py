"""GPL's ``validation:`` entries, translated to genparams validators one by one.

GPL writes ``name<>: ARGS`` or ``name: ARGS`` (the ``<>`` marks a template
function in C++ and means nothing here), ARGS being a list of arguments, a
single scalar, or null. Built-in names map to built-in validators; any other
name (``control_filters::gt_eq_or_nan<>``) is a function the user writes in
Python, referenced as a custom validator with its arguments.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any


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
        return Translated(element_low=args[0], element_high=args[1])
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


# The open side of an integer range in GPL's generated Python module.
GPL_INT_LOW = -(2**31) - 1
GPL_INT_HIGH = 2**31 - 1


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def descriptor_range(validation: dict[Any, Any], param_type: str) -> tuple[float, float] | None:
    """The descriptor range GPL's Python module declares, or None.

    GPL reads it off the validations of an int or double parameter (arrays included), in
    file order: any validation whose name holds ``bounds``, ``lt`` or ``gt`` and takes two
    numbers sets both sides; one number sets the lower side for a name holding ``lower``
    and for ``gt_eq``, one step above it for ``gt``, the upper side for a name holding
    ``upper`` and for ``lt_eq``, one step below it for ``lt``. A step is 1 for integers,
    the double epsilon for doubles. An open side is GPL's: +-inf, or +-(2**31 - 1)."""
    integer = param_type in ("int", "int_array")
    if not integer and param_type not in ("double", "double_array"):
        return None
    step: float = 1 if integer else sys.float_info.epsilon
    low: float | None = None
    high: float | None = None
    for key, raw in validation.items():
        name = str(key)
        if not any(word in name for word in ("bounds", "lt", "gt")):
            continue
        base = name.replace("<>", "")
        args = arguments(raw)
        if not all(_is_number(arg) for arg in args):
            continue
        if len(args) == 2:
            low, high = args
        elif len(args) != 1:
            continue
        elif "lower" in name or base == "gt_eq":
            low = args[0]
        elif base == "gt":
            low = args[0] + step
        elif "upper" in name or base == "lt_eq":
            high = args[0]
        elif base == "lt":
            high = args[0] - step
    if low is None and high is None:
        return None
    if integer:
        return (GPL_INT_LOW if low is None else low, GPL_INT_HIGH if high is None else high)
    return (-math.inf if low is None else low, math.inf if high is None else high)


_SCALAR_BOUNDS = frozenset({"gt", "gt_eq", "lt", "lt_eq"})
_ELEMENT_SIDES = frozenset({"lower_element_bounds", "upper_element_bounds"})


def combination_refused(validation: dict[Any, Any]) -> str:
    """The combination of range validations GPL's generator refuses in one parameter
    (since GPL 1.0; it warned before), in words, or ""."""
    names = {gpl_name(str(key)) for key in validation}
    if "bounds" in names and names & _SCALAR_BOUNDS:
        return "'bounds' beside gt/gt_eq/lt/lt_eq"
    if "element_bounds" in names and names & _ELEMENT_SIDES:
        return "'element_bounds' beside lower_element_bounds/upper_element_bounds"
    return ""


def element_bounds(low: float, high: float, param_type: str) -> dict[str, Any]:
    """One ``element_bounds`` from GPL's element bounds: NaN items pass, as in GPL."""
    if param_type == "double_array":
        return {"element_bounds": {"min": low, "max": high, "nan": True}}
    return {"element_bounds": [low, high]}
