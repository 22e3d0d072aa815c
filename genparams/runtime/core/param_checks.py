"""A parameter's validator objects and descriptor texts, made once per distinct rule set.

Parameters that read the same range, choices, validators and extra constraints
share their validator objects and their descriptor's texts: at 10,000 parameters
of a few kinds, a few dozen objects instead of tens of thousands, and compiling
builds each only once.
"""

from __future__ import annotations

from typing import Any, Protocol

from genparams.runtime.core.types import TYPES
from genparams.runtime.core.validator_kinds import build_validator
from genparams.runtime.core.validators import OneOf, RosRange, SubsetOf, Validator

CONFIGURE_ONLY_TEXT = "changes only while the lifecycle node is unconfigured or inactive"
"""The words of ``configure_only``: one source for descriptors, docs and refusals."""


class RuleFields(Protocol):
    """What of a ``ParamSpec`` its checks and texts are made from."""

    @property
    def type(self) -> str: ...
    @property
    def range(self) -> tuple[Any, ...] | None: ...
    @property
    def choices(self) -> tuple[Any, ...] | None: ...
    @property
    def validators(self) -> tuple[tuple[str, Any], ...]: ...
    @property
    def additional_constraints(self) -> str: ...
    @property
    def configure_only(self) -> bool: ...


# Bounded: a process that reads schemas from other nodes (tune, audit) compiles many.
_SHARED_MAX = 4096
_SHARED_CHECKS: dict[tuple[str, str, str, bool], tuple[tuple[Validator, ...], str]] = {}
_DESCRIPTIONS: dict[tuple[str, str], str] = {}


def checks_and_texts(
    spec: RuleFields, extra_checks: tuple[Validator, ...] = ()
) -> tuple[tuple[Validator, ...], str]:
    """The parameter's checks in checking order, and its descriptor's additional_constraints
    (every rule in words, less a scalar range, which the descriptor carries itself)."""
    key = None
    if not extra_checks:
        # repr tells 1 from 1.0 and True, which == does not.
        key = (
            spec.type,
            repr((spec.range, spec.choices, spec.validators)),
            spec.additional_constraints,
            spec.configure_only,
        )
        shared = _SHARED_CHECKS.get(key)
        if shared is not None:
            return shared
    checks = _build_checks(spec, extra_checks)
    made = (checks, _constraints_text(spec, checks))
    if key is not None and len(_SHARED_CHECKS) < _SHARED_MAX:
        _SHARED_CHECKS[key] = made
    return made


def description_text(description: str, unit: str) -> str:
    """The descriptor's description: the text with its unit in brackets."""
    label = (description, unit)
    text = _DESCRIPTIONS.get(label)
    if text is None:
        text = description
        if unit:
            text = f"{description} [{unit}]" if description else f"[{unit}]"
        if len(_DESCRIPTIONS) < _SHARED_MAX:
            _DESCRIPTIONS[label] = text
    return text


def _build_checks(spec: RuleFields, extra_checks: tuple[Validator, ...]) -> tuple[Validator, ...]:
    param_type = TYPES[spec.type]
    checks: list[Validator] = []
    if spec.range is not None:
        low, high, *steps = spec.range
        step = steps[0] if steps else 0
        integer = param_type.scalar_kind == "int"
        checks.append(RosRange(low, high, step, integer=integer, each=param_type.is_array))
    if spec.choices is not None:
        checks.append(SubsetOf(spec.choices) if param_type.is_array else OneOf(spec.choices))
    checks.extend(build_validator(rule, argument, spec.type) for rule, argument in spec.validators)
    checks.extend(extra_checks)
    return tuple(checks)


def _constraints_text(spec: RuleFields, checks: tuple[Validator, ...]) -> str:
    parts = [check.describe() for check in checks]
    first = checks[0] if checks else None
    if isinstance(first, RosRange) and not first.each:
        parts = parts[1:]
    if spec.additional_constraints:
        parts.append(spec.additional_constraints)
    if spec.configure_only:
        parts.append(CONFIGURE_ONLY_TEXT)
    return "; ".join(parts)
