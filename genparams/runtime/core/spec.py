"""What a generated module hands the runtime: plain data describing each parameter."""

from __future__ import annotations

from collections.abc import Collection, Iterable, Mapping
from typing import TYPE_CHECKING, Any

from genparams.runtime.core.naming import (
    ENTRY_KEY,
    ENTRY_KEY_RULE,
    MAP_SLOT,
    attribute_name,
    attribute_parts,
    entry_beside_problem,
    entry_key_problem,
)
from genparams.runtime.core.param_checks import CONFIGURE_ONLY_TEXT
from genparams.runtime.core.param_kind import KindTable, ParamKind, kind_of
from genparams.runtime.core.param_spec import ParamOptions, ParamSpec
from genparams.runtime.core.records import Record, store
from genparams.runtime.core.types import ParamType
from genparams.runtime.core.validators import Bounds, RosRange, Validator

if TYPE_CHECKING:
    from genparams.runtime.core.rules import CompiledRule
    from genparams.runtime.core.tree import Group


class RuleSpec(Record):
    """A cross-parameter rule: ``check`` is an expression of ``runtime.rules``, kept as text."""

    _fields = ("name", "check", "description")
    __slots__ = _fields
    name: str
    check: str
    description: str

    def __init__(self, name: str, check: str, description: str = "") -> None:
        store(self, "name", name)
        store(self, "check", check)
        store(self, "description", description)


class SchemaSpec(Record):
    """A generated class's parameters.

    Parameters of mapped groups are templates: ``gains.*.p`` stands for
    ``gains.<key>.p`` for every item of the map's ``for_each`` parameter.
    """

    _fields = ("name", "parameters", "groups", "maps", "rules")
    __slots__ = _fields
    name: str
    parameters: tuple[ParamSpec, ...]
    groups: Mapping[str, type[Group]]  # dotted namespace -> generated class ("gains.*": entry)
    maps: Mapping[str, str]  # "gains" -> its for_each parameter
    rules: tuple[RuleSpec, ...]

    def __init__(
        self,
        name: str,
        parameters: tuple[ParamSpec, ...],
        groups: Mapping[str, type[Group]],
        maps: Mapping[str, str] | None = None,
        rules: tuple[RuleSpec, ...] = (),
    ) -> None:
        store(self, "name", name)
        store(self, "parameters", parameters)
        store(self, "groups", groups)
        store(self, "maps", {} if maps is None else maps)
        store(self, "rules", rules)

    @classmethod
    def table(
        cls,
        name: str,
        options: tuple[ParamOptions, ...],
        rows: tuple[tuple[str, Any, int], ...],
        groups: Mapping[str, type[Group]],
        maps: Mapping[str, str] | None = None,
        rules: tuple[RuleSpec, ...] = (),
    ) -> SchemaSpec:
        """The spec of a generated module: each parameter a row ``(name, default, index)``
        of the table, ``index`` naming its entry of ``options`` (shared by every row of
        the same rules)."""
        row = ParamSpec.row
        parameters = tuple([row(name, default, options[index]) for name, default, index in rows])
        seen: set[type[Group]] = set()
        for group in groups.values():
            if group in seen:
                group._SHARED = True  # several groups of one shape: no one group's name
            seen.add(group)
        return cls(name, parameters, groups, maps, rules)


class EntryKeys(Record):
    """The items of a ``for_each`` parameter name mapped entries: distinct, of ENTRY_KEY_RULE."""

    _fields = ("maps", "taken", "rule")
    __slots__ = _fields
    maps: str  # the mapped groups it keys, for messages
    # (in-place map, the names beside its entries): no key may repeat one of them
    taken: tuple[tuple[str, frozenset[str]], ...]
    rule: str

    def __init__(
        self, maps: str, taken: tuple[tuple[str, frozenset[str]], ...] = (), rule: str = "for_each"
    ) -> None:
        store(self, "maps", maps)
        store(self, "taken", taken)
        store(self, "rule", rule)

    def __call__(self, value: Any) -> str | None:
        reason = entry_key_problem(value, self.maps)
        for map_path, names in self.taken if reason is None else ():
            reason = entry_beside_problem(value, map_path, names)
            if reason is not None:
                break
        return None if reason is None else f"{reason} ({self.rule})"

    def describe(self) -> str:
        return f"each item names an entry of {self.maps}: {ENTRY_KEY_RULE}; no repeats"


class CompiledParam(Record):
    """A ParamSpec made ready for checking: type row, attribute path, validator objects.

    Compared and hashed by identity (one per parameter, cached with its schema):
    it keys the updates of every set, where hashing all its fields cost ~1 us.
    Identity also lets a spec hold unhashable validator arguments (``length: {max: 12}``).
    """

    _fields = ("spec", "kind")
    __slots__ = _fields
    spec: ParamSpec
    # Shared with every parameter of the same options. Two fields, not six: at 10,000
    # parameters keeping the type and checks here too cost 0.15 MiB, reading them
    # through the kind costs about 0.1 us a set (two property reads).
    kind: ParamKind

    def __init__(self, spec: ParamSpec, kind: ParamKind) -> None:
        store(self, "spec", spec)
        store(self, "kind", kind)

    __eq__ = object.__eq__  # by identity, see above
    __hash__ = object.__hash__

    @property
    def name(self) -> str:
        return self.spec.name

    @property
    def type(self) -> ParamType:
        return self.kind.type

    @property
    def checks(self) -> tuple[Validator, ...]:
        return self.kind.checks

    @property
    def constraints_text(self) -> str:
        """The descriptor's ``additional_constraints``: ``constraints`` less a scalar range,
        which travels in the descriptor's own range fields."""
        return self.kind.constraints_text

    @property
    def descriptor_description(self) -> str:
        """The descriptor's description: the text with its unit."""
        return self.kind.descriptor_description

    @property
    def attribute_path(self) -> tuple[str, ...]:
        """The attributes from the top level to this parameter's value."""
        path = self.kind.own_path
        if path is None:
            name = self.spec.name
            path = _NAME_PARTS.get(name)
            if path is None:
                path = tuple(name.split("."))
                if len(_NAME_PARTS) < _NAME_PARTS_MAX:
                    _NAME_PARTS[name] = path
        return path

    def with_path(self, name: str, path: tuple[str, ...]) -> CompiledParam:
        """This parameter under another ``name`` (an entry of a template) at ``path``."""
        kind = self.kind
        path_of_its_own = own_path(name, path)
        if path_of_its_own is not None or kind.own_path is not None:
            kind = kind.with_changes(own_path=path_of_its_own)
        return compiled_from(self.spec.replaced(name=name), kind)

    def with_checks(self, checks: tuple[Validator, ...]) -> CompiledParam:
        """This parameter with other checks (those a tool can run where it is)."""
        return compiled_from(self.spec, self.kind.with_changes(checks, self.kind.own_path))

    def from_ros(self, value: Any) -> Any:
        """A ROS value in typed-view form; None (NOT_SET) stays None for an optional parameter."""
        if value is None and self.spec.optional:
            return None
        return self.type.from_ros(value)

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
    def descriptor_range(self) -> RosRange | None:
        """The range the descriptor carries: a scalar's ``range``, or an array's item bounds
        (its ``range`` or ``element_bounds``). ROS keeps a range on an array but applies it
        to no item (genparams does), as generate_parameter_library's descriptors have it."""
        if not self.type.name.endswith("_array"):
            return self.ros_range
        for check in self.checks:
            if isinstance(check, RosRange) and check.each:
                return check
            if isinstance(check, Bounds) and check.each:
                integer = self.type.name == "int_array"
                return RosRange(check.low, check.high, 0, integer, each=True)
        return None

    @property
    def constraints(self) -> tuple[str, ...]:
        """Every rule of this parameter in plain words, in checking order: the one text that
        docstrings, docs, default params files, JSON Schema and descriptors all state."""
        parts = [check.describe() for check in self.checks]
        if self.spec.additional_constraints:
            parts.append(self.spec.additional_constraints)
        if self.spec.configure_only:
            parts.append(CONFIGURE_ONLY_TEXT)
        return tuple(parts)


# The attribute paths of names the set path asked for (bounded: a node sets a few
# parameters often; keeping a path for each of 10,000 parameters cost 0.7 MiB).
_NAME_PARTS_MAX = 1024
_NAME_PARTS: dict[str, tuple[str, ...]] = {}


def compiled_from(spec: ParamSpec, kind: ParamKind) -> CompiledParam:
    return CompiledParam(spec, kind)


def own_path(name: str, path: tuple[str, ...]) -> tuple[str, ...] | None:
    """``path`` when it is not the parts of ``name``, else None (made again on each read)."""
    return None if path == tuple(name.split(".")) else path


def compile_param(
    spec: ParamSpec, extra_checks: tuple[Validator, ...] = (), kinds: KindTable | None = None
) -> CompiledParam:
    kind = kind_of(spec, extra_checks, kinds)
    path = own_path(spec.name, attribute_parts(spec.name))
    return compiled_from(spec, kind if path is None else kind.with_changes(own_path=path))


class CompiledSchema(Record):
    """A generated class's parameters made ready: compiled once per class (compile_schema)."""

    _fields = ("spec", "parameters", "templates", "aliases", "rules", "rules_by_parameter")
    __slots__ = _fields
    spec: SchemaSpec
    parameters: Mapping[str, CompiledParam]  # fixed parameters, by relative ROS name
    templates: Mapping[str, CompiledParam]  # "gains.*.p"
    aliases: Mapping[str, str]  # old name -> current name
    rules: tuple[CompiledRule, ...]
    rules_by_parameter: Mapping[str, tuple[CompiledRule, ...]]

    def __init__(
        self,
        spec: SchemaSpec,
        parameters: Mapping[str, CompiledParam],
        templates: Mapping[str, CompiledParam] | None = None,
        aliases: Mapping[str, str] | None = None,
        rules: tuple[CompiledRule, ...] = (),
        rules_by_parameter: Mapping[str, tuple[CompiledRule, ...]] | None = None,
    ) -> None:
        store(self, "spec", spec)
        store(self, "parameters", parameters)
        store(self, "templates", {} if templates is None else templates)
        store(self, "aliases", {} if aliases is None else aliases)
        store(self, "rules", rules)
        store(self, "rules_by_parameter", {} if rules_by_parameter is None else rules_by_parameter)

    def replaced(self, **changes: Any) -> CompiledSchema:
        """A copy with ``changes`` (field name -> value), as dataclasses.replace makes."""
        return CompiledSchema(**{**dict(zip(self._fields, self._values(), strict=True)), **changes})

    @property
    def adopted(self) -> frozenset[str]:
        """Names other code of the node may declare first (``adopt: true``)."""
        return frozenset(name for name, p in self.parameters.items() if p.spec.adopt)

    @property
    def maps(self) -> Mapping[str, str]:
        return self.spec.maps

    def rules_reading(self, names: Iterable[str]) -> tuple[CompiledRule, ...]:
        """The rules that read any of ``names``: only these can break when they change."""
        found: dict[str, CompiledRule] = {}
        for name in names:
            for rule in self.rules_by_parameter.get(name, ()):
                found[rule.name] = rule
        return tuple(found.values())


def compile_rules(spec: SchemaSpec) -> tuple[CompiledRule, ...]:
    if not spec.rules:
        return ()
    # The expression language loads with the first class that has rules.
    from genparams.runtime.core.rules import RuleError, compile_rule

    types = {p.name: p.type for p in spec.parameters if ENTRY_KEY not in p.name.split(".")}
    compiled = []
    for rule in spec.rules:
        try:
            compiled.append(compile_rule(rule.name, rule.check, rule.description, types))
        except RuleError as exc:  # generated code was checked; a hand-written spec may not be
            raise ValueError(f"{spec.name}: rule {rule.name!r}: {exc}") from None
    return tuple(compiled)


_COMPILED: dict[int, CompiledSchema] = {}


def compile_schema(spec: SchemaSpec) -> CompiledSchema:
    """Compile once per generated class; later calls are a dict lookup."""
    compiled = _COMPILED.get(id(spec))
    if compiled is None or compiled.spec is not spec:
        compiled = _compile(spec)
        _COMPILED[id(spec)] = compiled
    return compiled


def compile_uncached(spec: SchemaSpec) -> CompiledSchema:
    """Compile a spec built at run time (a schema read from a node's message), uncached."""
    return _compile(spec)


def in_place_maps(spec: SchemaSpec) -> frozenset[str]:
    """Maps whose entries sit beside other names of their namespace (schema key ``"*"``).

    Their namespace is a group of its own (or the top level), so Python reads
    the entries by key on it, through its ``_map`` slot.
    """
    return frozenset(path for path in spec.maps if path == "" or path in spec.groups)


def attribute_path(name: str, in_place: Collection[str]) -> tuple[str, ...]:
    """Python path of a ROS name: keywords spelled ``from_``; ``_map`` before in-place keys."""
    parts = name.split(".")
    path: list[str] = []
    for index, part in enumerate(parts):
        if part == ENTRY_KEY and ".".join(parts[:index]) in in_place:
            path.append(MAP_SLOT)
        path.append(attribute_name(part, top_level=index == 0))
    return tuple(path)


def _names_beside(spec: SchemaSpec, map_path: str) -> frozenset[str]:
    """The fixed names directly in an in-place map's namespace."""
    depth = len(map_path.split(".")) if map_path else 0
    names = set()
    for name in (*(p.name for p in spec.parameters), *spec.groups):
        parts = name.split(".")
        inside = ".".join(parts[:depth]) == map_path and len(parts) > depth
        if inside and parts[depth] != ENTRY_KEY:
            names.add(parts[depth])
    return frozenset(names)


def _compile(spec: SchemaSpec) -> CompiledSchema:
    keyed: dict[str, list[str]] = {}
    for map_path, key_name in spec.maps.items():
        keyed.setdefault(key_name, []).append(map_path)
    in_place = in_place_maps(spec)
    parameters: dict[str, CompiledParam] = {}
    templates: dict[str, CompiledParam] = {}
    aliases: dict[str, str] = {}
    kinds: KindTable = {}  # parameters of one options object share one kind
    for param_spec in spec.parameters:
        maps = keyed.get(param_spec.name)
        extra: tuple[Validator, ...] = ()
        if maps:
            taken = tuple((m, _names_beside(spec, m)) for m in maps if m in in_place)
            extra = (EntryKeys(", ".join(m or "the top level" for m in maps), taken),)
        compiled = compile_param(param_spec, extra, kinds)
        if in_place:
            path = own_path(param_spec.name, attribute_path(param_spec.name, in_place))
            if path != compiled.kind.own_path:
                compiled = compiled_from(param_spec, compiled.kind.with_changes(own_path=path))
        is_template = ENTRY_KEY in param_spec.name.split(".")
        (templates if is_template else parameters)[param_spec.name] = compiled
        aliases.update(dict.fromkeys(param_spec.aliases, param_spec.name))
    rules = compile_rules(spec)
    by_parameter: dict[str, tuple[CompiledRule, ...]] = {}
    if rules:
        from genparams.runtime.core.rules import rules_by_parameter

        by_parameter = rules_by_parameter(rules)
    return CompiledSchema(spec, parameters, templates, aliases, rules, by_parameter)
