"""What a generated module hands the runtime: plain data describing each parameter."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from genparams.naming import attribute_name
from genparams.types import TYPES, ParamType
from genparams.validators import OneOf, RosRange, SubsetOf, Validator, build_validator

if TYPE_CHECKING:
    from genparams.runtime.tree import Group


@dataclass(frozen=True)
class ParamSpec:
    name: str  # dotted ROS name relative to the prefix
    type: str  # one of the nine schema type names
    default: Any = None
    required: bool = False
    description: str = ""
    read_only: bool = False
    unit: str = ""
    range: tuple[Any, Any, Any] | None = None  # (min, max, step)
    choices: tuple[Any, ...] | None = None
    validators: tuple[tuple[str, Any], ...] = ()
    additional_constraints: str = ""
    deprecated: str = ""


@dataclass(frozen=True)
class SchemaSpec:
    name: str
    parameters: tuple[ParamSpec, ...]
    groups: Mapping[str, type[Group]]  # dotted namespace -> generated class


@dataclass(frozen=True)
class CompiledParam:
    """A ParamSpec made ready for checking: type row, attribute path, validator objects."""

    spec: ParamSpec
    type: ParamType
    attribute_path: tuple[str, ...]
    checks: tuple[Validator, ...]

    @property
    def name(self) -> str:
        return self.spec.name

    def check(self, value: Any) -> str | None:
        """The first rule ``value`` breaks, as a reason, or None."""
        for check in self.checks:
            reason = check(value)
            if reason is not None:
                return reason
        return None

    @property
    def ros_range(self) -> RosRange | None:
        first = self.checks[0] if self.checks else None
        return first if isinstance(first, RosRange) and not first.each else None

    @property
    def constraints_text(self) -> str:
        parts = [c.describe() for c in self.checks if c is not self.ros_range]
        if self.spec.additional_constraints:
            parts.append(self.spec.additional_constraints)
        return "; ".join(parts)

    @property
    def descriptor_description(self) -> str:
        text = self.spec.description
        if self.spec.unit:
            text = f"{text} [{self.spec.unit}]" if text else f"[{self.spec.unit}]"
        return text


def compile_param(spec: ParamSpec) -> CompiledParam:
    param_type = TYPES[spec.type]
    checks: list[Validator] = []
    if spec.range is not None:
        low, high, step = spec.range
        checks.append(
            RosRange(
                low,
                high,
                step,
                integer=param_type.scalar_kind == "int",
                each=param_type.is_array,
            )
        )
    if spec.choices is not None:
        checks.append(SubsetOf(spec.choices) if param_type.is_array else OneOf(spec.choices))
    checks.extend(build_validator(rule, argument, spec.type) for rule, argument in spec.validators)
    return CompiledParam(
        spec=spec,
        type=param_type,
        attribute_path=tuple(attribute_name(part) for part in spec.name.split(".")),
        checks=tuple(checks),
    )


@dataclass(frozen=True)
class CompiledSchema:
    spec: SchemaSpec
    parameters: Mapping[str, CompiledParam]  # by relative ROS name


_COMPILED: dict[int, CompiledSchema] = {}


def compile_schema(spec: SchemaSpec) -> CompiledSchema:
    """Compile once per generated class; later calls are a dict lookup."""
    compiled = _COMPILED.get(id(spec))
    if compiled is None or compiled.spec is not spec:
        compiled = CompiledSchema(spec, {p.name: compile_param(p) for p in spec.parameters})
        _COMPILED[id(spec)] = compiled
    return compiled
