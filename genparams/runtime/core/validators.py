"""Built-in validators: small objects with one signature.

A validator is called with a typed-view value and returns ``None`` when the
value is valid, or a reason naming the rule when it is not. Each validator can
also describe itself in plain words (for docs, descriptors and error
messages). This module is pure Python: the code generator uses it to check
schema defaults, the runtime to check every change.
"""

from __future__ import annotations

import importlib
import math
import operator
import re
import time
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any, Protocol

from genparams.runtime.core.records import Record, store

if TYPE_CHECKING:
    import regex as regex_engine

from genparams.runtime.core.pattern_cost import check_pattern_cost

# rclpy compares doubles against range bounds and steps with this tolerance.
ROS_RELATIVE_TOLERANCE = 1e-6

NUMERIC = frozenset({"int", "double"})
NUMERIC_ARRAYS = frozenset({"int_array", "double_array"})
ARRAYS = frozenset({"byte_array", "bool_array", "int_array", "double_array", "string_array"})
SIZED = ARRAYS | {"string"}
ALL_TYPES = SIZED | {"bool", "int", "double"}


class Validator(Protocol):
    @property
    def rule(self) -> str: ...

    def __call__(self, value: Any) -> str | None: ...

    def describe(self) -> str: ...


_COMPARISONS: dict[str, tuple[str, Callable[[Any, Any], bool]]] = {
    "gt": (">", operator.gt),
    "ge": (">=", operator.ge),
    "lt": ("<", operator.lt),
    "le": ("<=", operator.le),
}


def fmt(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


class Compare(Record):
    """``gt``, ``ge``, ``lt``, ``le`` against a number."""

    __slots__ = ("holds", "limit", "rule")
    _fields = ("rule", "limit")
    rule: str
    limit: float
    holds: Callable[[Any, Any], bool]

    def __init__(self, rule: str, limit: float) -> None:
        store(self, "rule", rule)
        store(self, "limit", limit)
        store(self, "holds", _COMPARISONS[rule][1])

    def __call__(self, value: Any) -> str | None:
        if self.holds(value, self.limit):  # NaN compares false, so it is rejected
            return None
        symbol = _COMPARISONS[self.rule][0]
        return f"must be {symbol} {self.limit!r} ({self.rule}), got {fmt(value)}"

    def describe(self) -> str:
        return f"must be {_COMPARISONS[self.rule][0]} {self.limit!r}"


class Bounds(Record):
    """Inclusive bounds; with ``each``, applied to every element of an array."""

    _fields = ("low", "high", "each", "rule", "nan_passes")
    __slots__ = _fields
    low: float
    high: float
    each: bool
    rule: str
    nan_passes: bool  # generate_parameter_library's element bounds let NaN items pass

    def __init__(
        self,
        low: float,
        high: float,
        each: bool = False,
        rule: str = "bounds",
        nan_passes: bool = False,
    ) -> None:
        store(self, "low", low)
        store(self, "high", high)
        store(self, "each", each)
        store(self, "rule", rule)
        store(self, "nan_passes", nan_passes)

    def _check_one(self, value: Any) -> bool:
        if self.nan_passes and isinstance(value, float) and math.isnan(value):
            return True
        return bool(self.low <= value <= self.high)

    def __call__(self, value: Any) -> str | None:
        items = value if self.each else (value,)
        for index, item in enumerate(items):
            if not self._check_one(item):
                where = f"item {index} " if self.each else ""
                return (
                    f"{where}must be within [{self.low!r}, {self.high!r}] ({self.rule}), "
                    f"got {fmt(item)}"
                )
        return None

    def describe(self) -> str:
        scope = "every item " if self.each else ""
        text = f"{scope}within [{self.low!r}, {self.high!r}]"
        return f"{text} or NaN" if self.nan_passes else text


class RosRange(Record):
    """The ``range:`` key, with exactly the semantics rclpy applies to descriptor ranges.

    For arrays it applies to every element (ROS itself has no array ranges).
    """

    _fields = ("low", "high", "step", "integer", "each", "rule")
    __slots__ = _fields
    low: float
    high: float
    step: float
    integer: bool
    each: bool
    rule: str

    def __init__(
        self,
        low: float,
        high: float,
        step: float,
        integer: bool,
        each: bool = False,
        rule: str = "range",
    ) -> None:
        store(self, "low", low)
        store(self, "high", high)
        store(self, "step", step)
        store(self, "integer", integer)
        store(self, "each", each)
        store(self, "rule", rule)

    def _problem(self, value: Any) -> str | None:
        if self.integer:
            if value == self.low or value == self.high:  # rclpy: edges are always valid
                return None
            if not self.low <= value <= self.high:
                return self._out_of_range()
            if self.step and (value - self.low) % self.step != 0:
                return self._off_step()
            return None
        if math.isnan(value):
            return self._out_of_range()
        tol = ROS_RELATIVE_TOLERANCE
        at_edge = math.isclose(value, self.low, rel_tol=tol) or math.isclose(
            value, self.high, rel_tol=tol
        )
        if not (self.low < value < self.high or at_edge):
            return self._out_of_range()
        if self.step and not at_edge:
            steps = round((value - self.low) / self.step)
            if not math.isclose(self.low + steps * self.step, value, rel_tol=tol):
                return self._off_step()
        return None

    def _out_of_range(self) -> str:
        return f"must be within [{self.low!r}, {self.high!r}] ({self.rule})"

    def _off_step(self) -> str:
        return f"must be {self.low!r} plus a whole number of steps of {self.step!r} ({self.rule})"

    def __call__(self, value: Any) -> str | None:
        items = value if self.each else (value,)
        for index, item in enumerate(items):
            problem = self._problem(item)
            if problem is not None:
                where = f"item {index} " if self.each else ""
                return f"{where}{problem}, got {fmt(item)}"
        return None

    def describe(self) -> str:
        text = f"within [{self.low!r}, {self.high!r}]"
        if self.step:
            text += f" in steps of {self.step!r}"
        return ("every item " if self.each else "") + text


class OneOf(Record):
    _fields = ("choices", "rule")
    __slots__ = _fields
    choices: tuple[Any, ...]
    rule: str

    def __init__(self, choices: tuple[Any, ...], rule: str = "one_of") -> None:
        store(self, "choices", choices)
        store(self, "rule", rule)

    def __call__(self, value: Any) -> str | None:
        if value in self.choices:
            return None
        return f"must be one of {fmt(list(self.choices))} ({self.rule}), got {fmt(value)}"

    def describe(self) -> str:
        return "one of " + ", ".join(fmt(c) for c in self.choices)


class SubsetOf(Record):
    _fields = ("choices", "rule")
    __slots__ = _fields
    choices: tuple[Any, ...]
    rule: str

    def __init__(self, choices: tuple[Any, ...], rule: str = "subset_of") -> None:
        store(self, "choices", choices)
        store(self, "rule", rule)

    def __call__(self, value: Any) -> str | None:
        for index, item in enumerate(value):
            if item not in self.choices:
                return (
                    f"item {index} must be one of {fmt(list(self.choices))} ({self.rule}), "
                    f"got {fmt(item)}"
                )
        return None

    def describe(self) -> str:
        return "every item one of " + ", ".join(fmt(c) for c in self.choices)


class NotEmpty(Record):
    _fields = ("rule",)
    __slots__ = _fields
    rule: str

    def __init__(self, rule: str = "not_empty") -> None:
        store(self, "rule", rule)

    def __call__(self, value: Any) -> str | None:
        return None if len(value) else f"must not be empty ({self.rule})"

    def describe(self) -> str:
        return "not empty"


class Unique(Record):
    _fields = ("rule",)
    __slots__ = _fields
    rule: str

    def __init__(self, rule: str = "unique") -> None:
        store(self, "rule", rule)

    def __call__(self, value: Any) -> str | None:
        seen: set[Any] = set()
        for item in value:
            if item in seen:
                return f"must not repeat items ({self.rule}), {fmt(item)} appears twice"
            seen.add(item)
        return None

    def describe(self) -> str:
        return "no repeated items"


class Length(Record):
    _fields = ("min", "max", "rule")
    __slots__ = _fields
    min: int | None
    max: int | None
    rule: str

    def __init__(
        self, min: int | None = None, max: int | None = None, rule: str = "length"
    ) -> None:
        store(self, "min", min)
        store(self, "max", max)
        store(self, "rule", rule)

    def __call__(self, value: Any) -> str | None:
        size = len(value)
        if (self.min is None or size >= self.min) and (self.max is None or size <= self.max):
            return None
        return f"length must be {self._bounds()} ({self.rule}), got {size}"

    def _bounds(self) -> str:
        if self.min == self.max:
            return f"exactly {self.min}"
        if self.max is None:
            return f"at least {self.min}"
        if self.min is None:
            return f"at most {self.max}"
        return f"between {self.min} and {self.max}"

    def describe(self) -> str:
        return f"length {self._bounds()}"


# A pattern like '^(a|aa)+$' backtracks exponentially on some values; a parameter set
# from any node on the network must not stall the node, nor a schema default the
# generator. Matching a value (a string, or every item of an array together) gives up
# after this long and the value is refused.
PATTERN_TIMEOUT_S = 0.05


class Pattern(Record):
    """Python ``re`` syntax, matched by the ``regex`` module (its V0 mode) with a time limit.

    Built, it has checked the pattern's cost and its syntax (with ``re``, which every
    process has loaded); the ``regex`` engine (about 10 ms to import) loads and compiles
    the pattern when the first value is matched, so a node whose starting values need no
    match never loads it.
    """

    __slots__ = ("_compiled", "regex", "rule")
    _fields = ("regex", "rule")
    regex: str
    rule: str
    _compiled: regex_engine.Pattern[str] | None

    def __init__(self, regex: str, rule: str = "pattern") -> None:
        check_pattern_cost(regex)  # before any engine expands its counted repeats
        re.compile(regex)  # the syntax users write, with re's error messages
        store(self, "regex", regex)
        store(self, "rule", rule)
        store(self, "_compiled", None)

    def compiled(self) -> regex_engine.Pattern[str]:
        """The engine's pattern, compiled on first use (a race compiles it twice, harmlessly).

        Raises the engine's error for the few patterns ``re`` reads and it refuses
        (``{s3``, ``[[::]]``): the generator and the reader of schema messages compile
        every pattern so, to refuse those as they check.
        """
        found = self._compiled
        if found is None:
            import regex as engine

            found = engine.compile(self.regex, flags=engine.V0)
            store(self, "_compiled", found)
        return found

    def __call__(self, value: Any) -> str | None:
        try:
            compiled = self.compiled()  # before the clock starts: the first loads the engine
        except Exception as exc:  # a pattern no generator checked (a spec built by hand)
            return f"cannot be matched against {self.regex!r} ({self.rule}): {exc}"
        items = (value,) if isinstance(value, str) else value
        # One time budget for the whole value: an array of many items shares it.
        deadline = time.monotonic() + PATTERN_TIMEOUT_S
        for index, item in enumerate(items):
            where = "" if isinstance(value, str) else f"item {index} "
            try:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise TimeoutError
                found = compiled.search(item, timeout=left)
            except TimeoutError:
                return (
                    f"{where}could not be matched against {self.regex!r} ({self.rule}) within "
                    f"{PATTERN_TIMEOUT_S * 1000:g} ms: the pattern backtracks too much on "
                    f"{fmt(item)}"
                )
            if found is None:
                return f"{where}must match {self.regex!r} ({self.rule}), got {fmt(item)}"
        return None

    def describe(self) -> str:
        return f"matches {self.regex!r}"


class Custom(Record):
    """A user function ``module:function`` taking the value then ``args``: None (or ``""``,
    as generate_parameter_library's Python validators return) or a reason.

    ``args`` are fixed arguments from the schema, so one function serves several
    limits (``{custom: {function: 'pkg.checks:at_least_or_nan', args: [0.0]}}``).
    """

    _fields = ("target", "args", "rule")
    __slots__ = _fields
    target: str
    args: tuple[Any, ...]
    rule: str

    def __init__(self, target: str, args: tuple[Any, ...] = (), rule: str = "custom") -> None:
        store(self, "target", target)
        store(self, "args", args)
        store(self, "rule", rule)

    def resolve(self) -> Callable[..., Any]:
        module_name, _, function_name = self.target.partition(":")
        module = importlib.import_module(module_name)
        function = getattr(module, function_name)
        if not callable(function):
            raise TypeError(f"{self.target} is not callable")
        return function  # type: ignore[no-any-return]

    @property
    def call_text(self) -> str:
        """How the check reads in messages: ``pkg.checks:f`` or ``pkg.checks:f(0.0)``."""
        if not self.args:
            return self.target
        return f"{self.target}({', '.join(fmt(a) for a in self.args)})"

    def __call__(self, value: Any) -> str | None:
        try:
            outcome = self.resolve()(value, *self.args)
        except Exception as exc:  # a failing check must reject, never crash the service
            return f"custom validator {self.call_text} raised {type(exc).__name__}: {exc}"
        if outcome is None or outcome is True or outcome == "":
            return None  # "" is valid in generate_parameter_library's Python convention
        if outcome is False:
            return f"rejected by custom validator {self.call_text}"
        return f"{outcome} ({self.call_text})"

    def describe(self) -> str:
        return f"passes {self.call_text}"


def first_failure(validators: Sequence[Validator], value: Any) -> str | None:
    for validator in validators:
        reason = validator(value)
        if reason is not None:
            return reason
    return None
