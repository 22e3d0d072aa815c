"""One parameter as a generated module describes it: its name, its default, its options.

A schema of many parameters has few distinct rule sets: at 10,000 parameters of
ten kinds, ten. A ``ParamSpec`` keeps only what is its own (name and default) and
shares one ``ParamOptions`` (type, rules, texts, flags) with every parameter that
reads the same; a generated module writes each options row once and lists its
parameters as a table of ``(name, default, row)``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from genparams.runtime.core.conditions import Condition, condition_holds, condition_text
from genparams.runtime.core.records import Record, store


class ParamOptions(Record):
    """Everything of a parameter but its name and default, shared between parameters."""

    _fields = (
        "type",
        "required",
        "description",
        "read_only",
        "unit",
        "range",
        "choices",
        "validators",
        "additional_constraints",
        "deprecated",
        "aliases",
        "configure_only",
        "adopt",
        "optional",
        "when",
    )
    __slots__ = _fields
    type: str  # one of the nine schema type names
    required: bool
    description: str
    read_only: bool
    unit: str
    # (min, max) or (min, max, step); a missing step means any value in between
    range: tuple[Any, Any] | tuple[Any, Any, Any] | None
    choices: tuple[Any, ...] | None
    validators: tuple[tuple[str, Any], ...]
    additional_constraints: str
    deprecated: str
    aliases: tuple[str, ...]  # old dotted names, relative to the prefix
    configure_only: bool  # lifecycle nodes: set only while unconfigured or inactive
    # declared first by other code of the node: taken over, not refused
    adopt: bool
    # declared by type only: None (NOT_SET on the node) until given a value
    optional: bool
    # declared only when each named parameter passes its test (see conditions):
    # (("mode", ("advanced",)),), (("mode", NoneOf("proxied")),)
    when: Condition

    def __init__(
        self,
        type: str,
        required: bool = False,
        description: str = "",
        read_only: bool = False,
        unit: str = "",
        range: tuple[Any, Any] | tuple[Any, Any, Any] | None = None,
        choices: tuple[Any, ...] | None = None,
        validators: tuple[tuple[str, Any], ...] = (),
        additional_constraints: str = "",
        deprecated: str = "",
        aliases: tuple[str, ...] = (),
        configure_only: bool = False,
        adopt: bool = False,
        optional: bool = False,
        when: Condition = (),
    ) -> None:
        store(self, "type", type)
        store(self, "required", required)
        store(self, "description", description)
        store(self, "read_only", read_only)
        store(self, "unit", unit)
        store(self, "range", range)
        store(self, "choices", choices)
        store(self, "validators", validators)
        store(self, "additional_constraints", additional_constraints)
        store(self, "deprecated", deprecated)
        store(self, "aliases", aliases)
        store(self, "configure_only", configure_only)
        store(self, "adopt", adopt)
        store(self, "optional", optional)
        store(self, "when", when)


class ParamSpec(Record):
    """One parameter (a frozen record): its dotted ROS name relative to the prefix, its
    default, and its ``options``, shared with the parameters that read the same.

    Built with every field by keyword, as before (``ParamSpec("fps", "int", default=30,
    range=(1, 120))``), or from a row of a generated module's table (``ParamSpec.row``).
    Every field of ``ParamOptions`` reads as an attribute (``spec.type``, ``spec.range``).
    """

    _fields = ("name", "type", "default", *ParamOptions._fields[1:])
    __slots__ = ("default", "name", "options")
    name: str
    default: Any
    options: ParamOptions

    def __init__(
        self,
        name: str,
        type: str,
        default: Any = None,
        required: bool = False,
        description: str = "",
        read_only: bool = False,
        unit: str = "",
        range: tuple[Any, Any] | tuple[Any, Any, Any] | None = None,
        choices: tuple[Any, ...] | None = None,
        validators: tuple[tuple[str, Any], ...] = (),
        additional_constraints: str = "",
        deprecated: str = "",
        aliases: tuple[str, ...] = (),
        configure_only: bool = False,
        adopt: bool = False,
        optional: bool = False,
        when: Condition = (),
    ) -> None:
        store(self, "name", name)
        store(self, "default", default)
        options = ParamOptions(
            type,
            required,
            description,
            read_only,
            unit,
            range,
            choices,
            validators,
            additional_constraints,
            deprecated,
            aliases,
            configure_only,
            adopt,
            optional,
            when,
        )
        store(self, "options", options)

    @classmethod
    def row(cls, name: str, default: Any, options: ParamOptions) -> ParamSpec:
        """A parameter of a generated module's table: no copy of the shared ``options``."""
        spec = object.__new__(cls)
        store(spec, "name", name)
        store(spec, "default", default)
        store(spec, "options", options)
        return spec

    def replaced(self, **changes: Any) -> ParamSpec:
        """A copy with ``changes`` (field name -> value), as dataclasses.replace makes."""
        if not changes.keys() - {"name", "default"}:  # a mapped entry's name: options shared
            return ParamSpec.row(
                changes.get("name", self.name), changes.get("default", self.default), self.options
            )
        return ParamSpec(**{**dict(zip(self._fields, self._values(), strict=True)), **changes})

    def __reduce__(self) -> tuple[Any, ...]:
        return (ParamSpec.row, (self.name, self.default, self.options))

    def declared_with(self, values: Mapping[str, Any]) -> bool:
        """Whether the condition (``when``) holds for ``values``, by relative name."""
        return condition_holds(self.options.when, values)

    @property
    def condition_text(self) -> str:
        """``when`` in words: "declared only when mode is 'advanced'"."""
        return condition_text(self.options.when)

    # The shared options, read as the parameter's own fields.
    @property
    def type(self) -> str:
        return self.options.type

    @property
    def required(self) -> bool:
        return self.options.required

    @property
    def description(self) -> str:
        return self.options.description

    @property
    def read_only(self) -> bool:
        return self.options.read_only

    @property
    def unit(self) -> str:
        return self.options.unit

    @property
    def range(self) -> tuple[Any, Any] | tuple[Any, Any, Any] | None:
        return self.options.range

    @property
    def choices(self) -> tuple[Any, ...] | None:
        return self.options.choices

    @property
    def validators(self) -> tuple[tuple[str, Any], ...]:
        return self.options.validators

    @property
    def additional_constraints(self) -> str:
        return self.options.additional_constraints

    @property
    def deprecated(self) -> str:
        return self.options.deprecated

    @property
    def aliases(self) -> tuple[str, ...]:
        return self.options.aliases

    @property
    def configure_only(self) -> bool:
        return self.options.configure_only

    @property
    def adopt(self) -> bool:
        return self.options.adopt

    @property
    def optional(self) -> bool:
        return self.options.optional

    @property
    def when(self) -> Condition:
        return self.options.when
