"""Python's own operators and a few builtins on values a launch file's Python knows before
launch runs: literals, constants, loop variables, arguments of its functions. A value only
launch knows (a substitution, an action, an ``Unknown``) is never computed with."""

from __future__ import annotations

import ast
import operator
from collections.abc import Callable
from typing import Any

from genparams.errors import GenparamsError
from genparams.launch.nodes import Substituted
from genparams.rclpy_import.limits import MAX_ITEMS, computable
from genparams.rclpy_import.ros_names import BINARY


class LaunchText(Substituted):
    """The text a launch substitution will give (``LaunchConfiguration``, ``FindPackageShare``
    ...): Python holds the substitution object while the description is built, so a test or
    a loop on it is decided only when launch runs."""

    __slots__ = ()


class NotPlainError(GenparamsError):
    """The operation needs a value Python does not hold before launch runs, or fails."""


COMPARE: dict[type[ast.cmpop], Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq,
    ast.NotEq: operator.ne,
    ast.Lt: operator.lt,
    ast.LtE: operator.le,
    ast.Gt: operator.gt,
    ast.GtE: operator.ge,
    ast.In: lambda a, b: a in b,
    ast.NotIn: lambda a, b: a not in b,
    ast.Is: lambda a, b: a is b,
    ast.IsNot: lambda a, b: a is not b,
}


def is_plain(value: Any) -> bool:
    """A value Python holds as such while the description is built."""
    if isinstance(value, LaunchText):
        return False
    if isinstance(value, list | tuple):
        return all(is_plain(item) for item in value)
    if isinstance(value, dict):
        return all(is_plain(k) and is_plain(v) for k, v in value.items())
    return value is None or isinstance(value, bool | int | float | str | slice)


def plain(*values: Any) -> None:
    for value in values:
        if not is_plain(value):
            raise NotPlainError


def binary(op: ast.operator, left: Any, right: Any) -> Any:
    plain(left, right)
    if not computable(op, left, right):
        raise NotPlainError
    try:
        return BINARY[type(op)](left, right)
    except (KeyError, ArithmeticError, TypeError, ValueError) as exc:
        raise NotPlainError from exc


def compare(ops: list[ast.cmpop], values: list[Any]) -> bool:
    plain(*values)
    try:
        return all(
            COMPARE[type(op)](a, b) for op, a, b in zip(ops, values, values[1:], strict=False)
        )
    except (KeyError, TypeError) as exc:
        raise NotPlainError from exc


def items(value: Any) -> list[Any]:
    """What ``for x in value`` goes over: a list, a tuple, a dict's keys."""
    if isinstance(value, list | tuple) and not isinstance(value, LaunchText):
        found = list(value)
    elif isinstance(value, dict):
        found = list(value)
    else:
        raise NotPlainError
    if len(found) > MAX_ITEMS:
        raise NotPlainError(f"over {MAX_ITEMS} items")
    return found


def _range(*args: Any) -> list[int]:
    if not all(isinstance(a, int) and not isinstance(a, bool) for a in args) or not args:
        raise NotPlainError
    try:
        span = range(*args)
    except (TypeError, ValueError) as exc:
        raise NotPlainError from exc
    if len(span) > MAX_ITEMS:
        raise NotPlainError(f"over {MAX_ITEMS} items")
    return list(span)


def _zip(*args: Any) -> list[tuple[Any, ...]]:
    return list(zip(*[items(a) for a in args], strict=False))


def _enumerate(iterable: Any, start: Any = 0) -> list[tuple[int, Any]]:
    if not isinstance(start, int):
        raise NotPlainError
    return list(enumerate(items(iterable), start))


BUILTINS: dict[str, Callable[..., Any]] = {
    "range": _range,
    "zip": _zip,
    "enumerate": _enumerate,
    "len": len,
    "list": lambda value=(): items(value),
    "tuple": lambda value=(): tuple(items(value)),
    "sorted": lambda value: sorted(items(value)),
    "reversed": lambda value: list(reversed(items(value))),
    "str": str,
    "int": int,
    "float": float,
    "bool": bool,
    "min": min,
    "max": max,
    "abs": abs,
    "round": round,
}
# Methods of text, lists and dicts that build a value and change nothing.
METHODS: dict[str, Callable[..., Any]] = {
    "upper": str.upper,
    "lower": str.lower,
    "strip": str.strip,
    "replace": str.replace,
    "format": str.format,
    "startswith": str.startswith,
    "endswith": str.endswith,
    "split": str.split,
    "join": lambda sep, values: sep.join(items(values)),
    "keys": lambda d: list(d.keys()),
    "values": lambda d: list(d.values()),
    "items": lambda d: list(d.items()),
    "get": lambda d, key, default=None: d.get(key, default),
}


# These take a list or a dict whatever it holds (actions too): only its shape counts.
STRUCTURAL = {"len", "list", "tuple", "reversed", "enumerate", "zip", "keys", "values",
              "items", "get"}  # fmt: skip


def builtin(
    name: str, function: Callable[..., Any], args: list[Any], keywords: dict[str, Any]
) -> Any:
    if name in STRUCTURAL:
        for arg in (*args, *keywords.values()):
            if not isinstance(arg, list | tuple | dict) or isinstance(arg, LaunchText):
                plain(arg)
    else:
        plain(*args, *keywords.values())
    try:
        return function(*args, **keywords)
    except NotPlainError:
        raise
    except (ArithmeticError, TypeError, ValueError, AttributeError, KeyError) as exc:
        raise NotPlainError from exc
