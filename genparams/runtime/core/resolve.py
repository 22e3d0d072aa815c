"""Pick and check the starting value of every parameter: override, else default."""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping
from typing import Any

from genparams.runtime.core.problems import ParameterProblem
from genparams.runtime.core.spec import CompiledParam, CompiledSchema
from genparams.runtime.core.types import ValueTypeError
from genparams.runtime.core.validators import (
    Bounds,
    Compare,
    Length,
    NotEmpty,
    OneOf,
    Pattern,
    RosRange,
    SubsetOf,
    Unique,
)

# The generator judged every default against these checks when it wrote the module (a
# default one of them refuses is a schema error), and they are pure: they judge it so on
# every node. A default is checked on the node only against the others: custom
# validators (user code, which runs on the node only) and the checks the runtime adds
# (the items of a for_each), and by the cross-parameter rules below. So a pattern's
# engine loads only when a value from outside the schema is matched.
_JUDGED_WHEN_GENERATED = frozenset(
    {RosRange, OneOf, SubsetOf, Compare, Bounds, NotEmpty, Unique, Length, Pattern}
)


def default_problem(param: CompiledParam, value: Any) -> str | None:
    """The first rule the default ``value`` breaks that the generator did not judge, or None."""
    for check in param.checks:
        if type(check) not in _JUDGED_WHEN_GENERATED:
            reason = check(value)
            if reason is not None:
                return reason
    return None


def resolve_values(
    compiled: CompiledSchema,
    given: Mapping[str, Any],
    full_name: Callable[[str], str] = lambda name: name,
    source: str = "override",
    parameters: Mapping[str, CompiledParam] | None = None,
    lenient: bool = False,
) -> tuple[dict[str, Any], list[ParameterProblem]]:
    """Typed values for every parameter, and every problem found (all of them, not the first).

    Cross-parameter rules are checked on the result, so a set of overrides that
    breaks one is reported with the other problems.

    An optional parameter given no value (or None, NOT_SET in ROS) is None.

    ``given`` maps relative names to values in ROS form (as rclpy holds them);
    they are typed as strictly as ROS types them (``lenient``: as schema defaults
    are, a double may be an int). ``parameters`` defaults to
    the fixed parameters of ``compiled``.
    """
    values: dict[str, Any] = {}
    problems: list[ParameterProblem] = []
    if parameters is None:
        parameters = compiled.parameters
    for name, param in parameters.items():
        shown = full_name(name)
        if name in given and not (param.spec.optional and given[name] is None):
            try:
                raw = given[name]
                value = param.type.coerce_default(raw) if lenient else param.type.from_ros(raw)
            except ValueTypeError as exc:
                problems.append(ParameterProblem(shown, f"{source} has the wrong type: {exc}"))
                continue
            origin, judge = source, param.check
        elif param.spec.required:
            problems.append(
                ParameterProblem(
                    shown,
                    f"required parameter is not set (pass -p {shown}:=<{param.type.name}> "
                    "or set it in a params file)",
                )
            )
            continue
        elif param.spec.optional:  # not set: no value to check
            values[name] = None
            continue
        else:
            value, origin = param.type.coerce_default(param.spec.default), "default"
            judge = functools.partial(default_problem, param)
        reason = judge(value)
        if reason is not None:
            problems.append(ParameterProblem(shown, f"{origin} rejected: {reason}"))
            continue
        values[name] = value
    # Rules whose parameters all resolved; the others' problems are already listed.
    for rule in compiled.rules:
        if all(name in values for name in rule.parameters):
            reason = rule.violation(values, full_name)
            if reason is not None:
                problems.append(ParameterProblem("", reason))
    return values, problems
