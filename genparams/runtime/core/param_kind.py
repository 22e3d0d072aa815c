"""What a compiled parameter shares with every parameter of the same options.

A generated module of 10,000 parameters of ten kinds holds ten ``ParamOptions``;
compiling gives each of them one ``ParamKind`` (type row, validator objects,
descriptor texts), so a compiled parameter is its spec and its kind: two
references instead of six fields.
"""

from __future__ import annotations

from genparams.runtime.core.param_checks import checks_and_texts, description_text
from genparams.runtime.core.param_spec import ParamOptions, ParamSpec
from genparams.runtime.core.records import store
from genparams.runtime.core.types import TYPES, ParamType
from genparams.runtime.core.validators import Validator


class ParamKind:
    """Type row, checks and descriptor texts of a parameter, and its attribute path when
    that is not its name's parts. Shared; never changed once made."""

    __slots__ = ("checks", "constraints_text", "descriptor_description", "own_path", "type")
    type: ParamType
    checks: tuple[Validator, ...]
    constraints_text: str
    descriptor_description: str
    own_path: tuple[str, ...] | None

    def __init__(
        self,
        type: ParamType,
        checks: tuple[Validator, ...],
        constraints_text: str,
        descriptor_description: str,
        own_path: tuple[str, ...] | None = None,
    ) -> None:
        store(self, "type", type)
        store(self, "checks", checks)
        # ``additional_constraints`` of the descriptor (``constraints`` less a scalar range,
        # which travels in the descriptor's own range fields), and its description with unit.
        store(self, "constraints_text", constraints_text)
        store(self, "descriptor_description", descriptor_description)
        # None for most parameters: their path is their ROS name's parts.
        store(self, "own_path", own_path)

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"a ParamKind is shared between parameters: {name} is read-only")

    def with_changes(
        self, checks: tuple[Validator, ...] | None = None, own_path: tuple[str, ...] | None = None
    ) -> ParamKind:
        """A copy with other ``checks`` and the given ``own_path``."""
        return ParamKind(
            self.type,
            self.checks if checks is None else checks,
            self.constraints_text,
            self.descriptor_description,
            own_path,
        )


# The kinds made while compiling one schema, keyed by the options object (kept in the
# value, so its id is not reused while the table lives): options that hold unhashable
# validator arguments (``length: {max: 12}``) share too.
KindTable = dict[int, tuple[ParamOptions, ParamKind]]


def kind_of(
    spec: ParamSpec, extra_checks: tuple[Validator, ...] = (), table: KindTable | None = None
) -> ParamKind:
    """The kind of ``spec``: shared, through ``table``, with every parameter of the same
    options object compiled with it."""
    options = spec.options
    if table is not None and not extra_checks:
        cached = table.get(id(options))
        if cached is not None and cached[0] is options:
            return cached[1]
    checks, constraints_text = checks_and_texts(spec, extra_checks)
    kind = ParamKind(
        TYPES[spec.type], checks, constraints_text, description_text(spec.description, spec.unit)
    )
    if table is not None and not extra_checks:
        table[id(options)] = (options, kind)
    return kind
