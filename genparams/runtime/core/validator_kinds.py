"""The validator table: how each validator is spelled, what it applies to, how it is built.

Parses and checks a validator's argument from a schema (or from generated
code) and builds the validator object from ``validators``. Pure Python, like
the validators themselves.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Callable
from typing import Any

from genparams.runtime.core.errors import GenparamsError
from genparams.runtime.core.pattern_cost import PatternCostError
from genparams.runtime.core.records import Record, store
from genparams.runtime.core.types import INT64_MAX, INT64_MIN
from genparams.runtime.core.validators import (
    ALL_TYPES,
    ARRAYS,
    NUMERIC,
    NUMERIC_ARRAYS,
    SIZED,
    Bounds,
    Compare,
    Custom,
    Length,
    NotEmpty,
    OneOf,
    Pattern,
    SubsetOf,
    Unique,
    Validator,
    fmt,
)


class ValidatorKind(Record):
    """How one validator is spelled in a schema, what it applies to, how it is built."""

    _fields = ("name", "applies_to", "build", "takes_argument")
    __slots__ = _fields
    name: str
    applies_to: frozenset[str]
    build: Callable[[Any, str], Validator]  # (argument, parameter type) -> validator
    takes_argument: bool

    def __init__(
        self,
        name: str,
        applies_to: frozenset[str],
        build: Callable[[Any, str], Validator],
        takes_argument: bool = True,
    ) -> None:
        store(self, "name", name)
        store(self, "applies_to", applies_to)
        store(self, "build", build)
        store(self, "takes_argument", takes_argument)


class ValidatorArgumentError(GenparamsError, ValueError):
    pass


def _number(arg: Any, what: str) -> float:
    if isinstance(arg, bool) or not isinstance(arg, (int, float)):
        raise ValidatorArgumentError(f"{what} must be a number, got {fmt(arg)}")
    if isinstance(arg, float) and math.isnan(arg):
        raise ValidatorArgumentError(f"{what} must be a number, not NaN (nothing compares to NaN)")
    return arg


def _pair(arg: Any, what: str) -> tuple[float, float]:
    if not isinstance(arg, (list, tuple)) or len(arg) != 2:
        raise ValidatorArgumentError(f"{what} takes [low, high], got {fmt(arg)}")
    low, high = _number(arg[0], f"{what} low"), _number(arg[1], f"{what} high")
    if low > high:
        raise ValidatorArgumentError(f"{what} low {low!r} is greater than high {high!r}")
    return low, high


def _element_bounds(arg: Any, param_type: str) -> Bounds:
    """``[low, high]``, or ``{min, max, nan}``: an absent side is open, ``nan: true`` lets NaN
    items pass (as generate_parameter_library's element bounds do)."""
    if not isinstance(arg, dict):
        return Bounds(*_pair(arg, "element_bounds"), each=True, rule="element_bounds")
    if not arg or not set(arg) <= {"min", "max", "nan"} or not {"min", "max"} & set(arg):
        raise ValidatorArgumentError(
            f"element_bounds takes [low, high] or {{min, max, nan}}, got {fmt(arg)}"
        )
    nan = arg.get("nan", False)
    if not isinstance(nan, bool):
        raise ValidatorArgumentError(f"element_bounds nan must be true or false, got {fmt(nan)}")
    if nan and param_type != "double_array":
        raise ValidatorArgumentError("element_bounds nan applies to double_array only")
    integer = param_type == "int_array"
    low = arg.get("min", INT64_MIN if integer else -math.inf)
    high = arg.get("max", INT64_MAX if integer else math.inf)
    bounds = _pair([low, high], "element_bounds")
    return Bounds(*bounds, each=True, rule="element_bounds", nan_passes=nan)


def _choices(arg: Any, what: str) -> tuple[Any, ...]:
    if not isinstance(arg, (list, tuple)) or not arg:
        raise ValidatorArgumentError(f"{what} takes a non-empty list, got {fmt(arg)}")
    return tuple(arg)


def _length(arg: Any, _type: str) -> Length:
    if isinstance(arg, int) and not isinstance(arg, bool):
        if arg < 0:
            raise ValidatorArgumentError(f"length must be >= 0, got {arg}")
        return Length(arg, arg)
    if isinstance(arg, dict) and arg and set(arg) <= {"min", "max", "exact"}:
        for key, item in arg.items():
            if isinstance(item, bool) or not isinstance(item, int) or item < 0:
                raise ValidatorArgumentError(f"length {key} must be an integer >= 0")
        if "exact" in arg:
            if len(arg) > 1:
                raise ValidatorArgumentError("length takes exact, or min and/or max, not both")
            return Length(arg["exact"], arg["exact"])
        low, high = arg.get("min"), arg.get("max")
        if low is not None and high is not None and low > high:
            raise ValidatorArgumentError(f"length min {low} is greater than max {high}")
        return Length(low, high)
    raise ValidatorArgumentError(f"length takes an integer or {{min, max, exact}}, got {fmt(arg)}")


def _pattern(arg: Any, _type: str) -> Pattern:
    if not isinstance(arg, str):
        raise ValidatorArgumentError(f"pattern must be a string, got {fmt(arg)}")
    try:
        return Pattern(arg)  # its cost and syntax; the engine compiles it at its first match
    except PatternCostError as exc:
        raise ValidatorArgumentError(str(exc)) from None
    except re.error as exc:
        raise ValidatorArgumentError(f"pattern {arg!r} is not a valid regex: {exc}") from None


@functools.cache
def _custom_target() -> re.Pattern[str]:
    """``package.module:function``, compiled with the first custom validator."""
    return re.compile(r"[A-Za-z_][\w]*(\.[A-Za-z_][\w]*)*:[A-Za-z_]\w*")


def _custom(arg: Any, _type: str) -> Custom:
    """``'pkg.mod:function'``, or ``{function: 'pkg.mod:function', args: [...]}``."""
    target, args = arg, ()
    if isinstance(arg, dict) and set(arg) <= {"function", "args"} and "function" in arg:
        target, args = arg["function"], arg.get("args", ())
        if not isinstance(args, (list, tuple)):
            raise ValidatorArgumentError(f"custom args must be a list, got {fmt(args)}")
    if not isinstance(target, str) or not _custom_target().fullmatch(target):
        raise ValidatorArgumentError(
            "custom takes 'package.module:function' or "
            f"{{function: 'package.module:function', args: [...]}}, got {fmt(arg)}"
        )
    return Custom(target, tuple(args))


def _compare(rule: str, arg: Any) -> Compare:
    # Called per schema entry, not once at import, so the tests exercise (and mutate) it.
    return Compare(rule, _number(arg, rule))


KINDS: dict[str, ValidatorKind] = {
    k.name: k
    for k in (
        ValidatorKind("gt", NUMERIC, lambda a, _t: _compare("gt", a)),
        ValidatorKind("ge", NUMERIC, lambda a, _t: _compare("ge", a)),
        ValidatorKind("lt", NUMERIC, lambda a, _t: _compare("lt", a)),
        ValidatorKind("le", NUMERIC, lambda a, _t: _compare("le", a)),
        ValidatorKind("bounds", NUMERIC, lambda a, _t: Bounds(*_pair(a, "bounds"))),
        ValidatorKind(
            "element_bounds",
            NUMERIC_ARRAYS,
            _element_bounds,
        ),
        ValidatorKind(
            "one_of",
            frozenset({"int", "double", "string"}),
            lambda a, _t: OneOf(_choices(a, "one_of")),
        ),
        ValidatorKind(
            "subset_of",
            frozenset({"int_array", "double_array", "string_array"}),
            lambda a, _t: SubsetOf(_choices(a, "subset_of")),
        ),
        ValidatorKind("not_empty", SIZED, lambda _a, _t: NotEmpty(), takes_argument=False),
        ValidatorKind("unique", ARRAYS, lambda _a, _t: Unique(), takes_argument=False),
        ValidatorKind("length", SIZED, _length),
        ValidatorKind("pattern", frozenset({"string", "string_array"}), _pattern),
        ValidatorKind("custom", ALL_TYPES | {"any"}, _custom),
    )
}


def build_validator(rule: str, argument: Any, param_type: str) -> Validator:
    """Build one validator; raises ValidatorArgumentError or KeyError for unknown rules."""
    return KINDS[rule].build(argument, param_type)


def checked_validator(rule: str, argument: Any, param_type: str) -> Validator:
    """``build_validator``, and a pattern compiled by the engine that matches it, as a
    schema's validators are checked: a node compiles a pattern only at its first match."""
    built = build_validator(rule, argument, param_type)
    if isinstance(built, Pattern):
        import regex as engine

        try:
            built.compiled()
        except engine.error as exc:
            raise ValidatorArgumentError(
                f"pattern {argument!r} is not a valid regex: {exc}"
            ) from None
    return built
