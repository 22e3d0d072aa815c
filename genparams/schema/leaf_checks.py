"""Checks of one leaf's constraints: range, choices, validators, and whether any value passes.

Each check turns a leaf's raw schema keys into model specs, reporting every
problem through ``report`` (file position comes from the document path), so
one run finds them all.
"""

from __future__ import annotations

import math
from typing import Any

from genparams.runtime.core.suggest import did_you_mean
from genparams.runtime.core.types import INT64_MAX, INT64_MIN, TYPES, ParamType, ValueTypeError
from genparams.runtime.core.validator_kinds import KINDS, ValidatorArgumentError, checked_validator
from genparams.runtime.core.validators import Bounds, Compare, RosRange, Validator
from genparams.schema.loader import Path
from genparams.schema.model import RangeSpec, ValidatorSpec
from genparams.schema.references import Report


def _frozen(value: Any) -> Any:
    """Lists become tuples, so the model is hashable and immutable."""
    if isinstance(value, list):
        return tuple(_frozen(v) for v in value)
    if isinstance(value, dict):
        return {k: _frozen(v) for k, v in value.items()}
    return value


class LeafChecks:
    """The constraint checks of leaves, reporting problems to one sink."""

    def __init__(self, report: Report) -> None:
        self.report = report

    @staticmethod
    def range_validator(value_range: RangeSpec, param_type: ParamType) -> RosRange:
        return RosRange(
            value_range.min,
            value_range.max,
            value_range.step,
            integer=param_type.scalar_kind == "int",
            each=param_type.is_array,
        )

    def range(
        self, leaf: dict[str, Any], doc_path: Path, param_type: ParamType
    ) -> RangeSpec | None:
        if "range" not in leaf:
            return None
        range_path = (*doc_path, "range")
        if not param_type.is_numeric:
            self.report(
                range_path,
                f"range applies to int, double, int_array and double_array, not {param_type.name}",
                at_key=True,
            )
            return None
        raw = leaf["range"]
        values: dict[str, int | float] = {}
        ok = True
        for key in ("min", "max", "step"):
            value = raw.get(key, 0)
            if param_type.scalar_kind == "int":
                if isinstance(value, float) and not value.is_integer():
                    self.report(
                        (*range_path, key), f"{key} must be an integer for {param_type.name}"
                    )
                    ok = False
                    continue
                value = int(value)
                if not INT64_MIN <= value <= INT64_MAX:
                    self.report((*range_path, key), f"{key} {value} does not fit in int64")
                    ok = False
                    continue
            else:
                try:
                    value = float(value)
                except OverflowError:
                    self.report((*range_path, key), f"{key} is too large for a double")
                    ok = False
                    continue
                if math.isnan(value) or (key == "step" and math.isinf(value)):
                    self.report((*range_path, key), f"{key} must be a finite number")
                    ok = False
                    continue
            values[key] = value
        if not ok:
            return None
        if values["min"] > values["max"]:
            self.report(
                (*range_path, "min"),
                f"min {values['min']!r} is greater than max {values['max']!r}",
            )
            return None
        step = values["step"]
        if step and not math.isfinite((values["max"] - values["min"]) / step):
            # ROS computes (value - min) / step, which must stay a finite double.
            self.report(
                (*range_path, "step"),
                f"step {step!r} needs finite min and max and (max - min) / step below 1e308",
            )
            return None
        return RangeSpec(values["min"], values["max"], step)

    def choices(
        self, leaf: dict[str, Any], doc_path: Path, param_type: ParamType
    ) -> tuple[Any, ...] | None:
        if "choices" not in leaf:
            return None
        path = (*doc_path, "choices")
        if (
            param_type.scalar_kind not in ("int", "double", "string")
            or param_type.name == "byte_array"
        ):
            self.report(path, f"choices do not apply to {param_type.name}", at_key=True)
            return None
        element = TYPES[param_type.scalar_kind]
        out = []
        for index, choice in enumerate(leaf["choices"]):
            try:
                out.append(element.coerce_default(choice))
            except ValueTypeError as exc:
                self.report((*path, index), f"choice does not match type: {exc}")
        if len(set(out)) != len(out):
            self.report(path, "choices repeat a value")
        return tuple(out)

    def validators(
        self, leaf: dict[str, Any], doc_path: Path, param_type: ParamType
    ) -> tuple[ValidatorSpec, ...]:
        specs = []
        for index, entry in enumerate(leaf.get("validators", [])):
            path = (*doc_path, "validators", index)
            if isinstance(entry, str):
                rule, argument, bare = entry, None, True
            else:
                ((rule, argument),) = entry.items()
                bare = False
            kind = KINDS.get(rule)
            if kind is None:
                self.report(path, f"unknown validator {rule!r}{did_you_mean(rule, KINDS)}")
                continue
            if param_type.name not in kind.applies_to:
                applies = ", ".join(sorted(kind.applies_to))
                self.report(
                    path, f"validator {rule!r} does not apply to {param_type.name} (only {applies})"
                )
                continue
            if kind.takes_argument and bare:
                self.report(path, f"validator {rule!r} needs an argument: {{{rule}: ...}}")
                continue
            if not kind.takes_argument and not bare and argument not in (None, True):
                self.report(path, f"validator {rule!r} takes no argument: write just {rule}")
                continue
            argument = _frozen(argument) if kind.takes_argument else None
            if rule in ("one_of", "subset_of") and isinstance(argument, tuple):
                argument = self.typed_choices(path, argument, param_type)
            try:
                checked_validator(rule, argument, param_type.name)  # its argument errors, here
            except ValidatorArgumentError as exc:
                self.report(path, str(exc))
                continue
            specs.append(ValidatorSpec(rule, argument))
        return tuple(specs)

    def typed_choices(
        self, path: Path, argument: tuple[Any, ...], param_type: ParamType
    ) -> tuple[Any, ...]:
        element = TYPES[param_type.scalar_kind]
        out = []
        for index, choice in enumerate(argument):
            try:
                out.append(element.coerce_default(choice))
            except ValueTypeError as exc:
                self.report((*path, index), f"choice does not match type: {exc}")
        return tuple(out)

    def check_satisfiable(
        self, doc_path: Path, param_type: ParamType, checks: list[tuple[str, Validator]]
    ) -> None:
        """Numeric limits that leave no valid value are a schema error, not a runtime surprise."""
        if param_type.is_array or not param_type.is_numeric:
            return
        low: float = INT64_MIN if param_type.scalar_kind == "int" else -math.inf
        high: float = INT64_MAX if param_type.scalar_kind == "int" else math.inf
        low_open = high_open = False
        for _key, check in checks:
            bounds = _limits(check)
            if bounds is None:
                continue
            lo, lo_open, hi, hi_open = bounds
            if lo > low or (lo == low and lo_open):
                low, low_open = lo, lo_open
            if hi < high or (hi == high and hi_open):
                high, high_open = hi, hi_open
        if low > high or (low == high and (low_open or high_open)):
            self.report(
                doc_path,
                "range and validators contradict each other: no value satisfies all of them",
                at_key=True,
            )


def _limits(check: Validator) -> tuple[float, bool, float, bool] | None:
    if isinstance(check, RosRange) or (isinstance(check, Bounds) and not check.each):
        return (check.low, False, check.high, False)
    if isinstance(check, Compare):
        return {
            "gt": (check.limit, True, math.inf, False),
            "ge": (check.limit, False, math.inf, False),
            "lt": (-math.inf, False, check.limit, True),
            "le": (-math.inf, False, check.limit, False),
        }[check.rule]
    return None
