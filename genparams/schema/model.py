"""The typed, immutable model of a schema. Templates read it; they decide nothing.

Source and target names sit side by side: ``ros_name`` (what ROS and params
files see) and ``attribute`` / ``class_name`` (what Python code sees).
"""

from __future__ import annotations

import functools
from collections.abc import Iterator
from dataclasses import dataclass, replace
from typing import Any

from genparams.runtime.core.conditions import Condition, NoneOf
from genparams.runtime.core.naming import ENTRY_KEY, OVERRIDE_KEYS
from genparams.runtime.core.param_spec import ParamSpec
from genparams.runtime.core.spec import CompiledParam, EntryKeys, compile_param
from genparams.runtime.core.types import ParamType
from genparams.schema.errors import Location


@dataclass(frozen=True)
class RangeSpec:
    min: int | float
    max: int | float
    step: int | float

    def as_tuple(self) -> tuple[int | float, ...]:
        """The runtime's ``range``: (min, max), with the step only when there is one."""
        return (self.min, self.max, self.step) if self.step else (self.min, self.max)


@dataclass(frozen=True)
class ValidatorSpec:
    rule: str
    argument: Any  # JSON-like, lists made tuples

    def as_tuple(self) -> tuple[str, Any]:
        return (self.rule, self.argument)


@dataclass(frozen=True)
class Parameter:
    ros_name: str  # dotted, relative to the prefix: "camera.fps"
    path: tuple[str, ...]
    attribute: str  # Python attribute in its group
    type: ParamType
    default: Any  # typed-view value; None when required
    required: bool
    description: str
    read_only: bool
    unit: str
    range: RangeSpec | None
    choices: tuple[Any, ...] | None
    validators: tuple[ValidatorSpec, ...]
    additional_constraints: str
    deprecated: str
    aliases: tuple[str, ...]  # old dotted names, relative to the prefix
    location: Location
    configure_only: bool = False  # lifecycle nodes: set only while unconfigured or inactive
    adopt: bool = False  # other code may declare it first; genparams takes it over
    # For a for_each parameter: the mapped groups its items name (their checks join its own).
    keys_entries_of: str = ""
    optional: bool = False  # declared by type only: no value until an override or a set
    per_item_of: str = ""  # a per-item parameter (``offsets.*``): the list naming its entries
    # Declared only when each named parameter passes its test: (("mode", ("a",)),) holds
    # one of the values, (("mode", NoneOf("a")),) none of them (see runtime conditions)
    when: Condition = ()

    @property
    def annotation(self) -> str:
        if self.optional or self.when:  # not set, or not declared: None
            return f"{self.type.annotation} | None"
        return self.type.annotation

    @property
    def condition_words(self) -> str:
        """``when`` as a sentence: "Declared only when mode is 'advanced'"; "" without one."""
        text = self.runtime_spec.condition_text
        return text[:1].upper() + text[1:]

    @property
    def default_words(self) -> str:
        """What the parameter holds when nothing overrides it, in every output's words."""
        if self.required:
            return "Required."
        if self.optional:
            return "Not set by default."
        return f"Default: {self.default!r}."

    @functools.cached_property
    def docstring(self) -> str:
        """Hover text in IDEs: description, unit, default and constraints."""
        default = self.default_words
        deprecated = f"Deprecated: {self.deprecated.rstrip('.')}." if self.deprecated else ""
        facts = (
            self.stated("type", "unit"),
            default,
            self.stated("condition", "read_only", "constraints"),
            deprecated,
            self.stated("old_names"),
        )
        head = self.description or self.ros_name
        if self.per_item_of:
            where = self.ros_name.replace(ENTRY_KEY, "<item>")
            each = f"One parameter per item of {self.per_item_of}: {where}."
            head = f"{self.description or where}\n\n{each}"
            return f"{head} " + " ".join(f for f in facts if f)
        return f"{head}\n\n" + " ".join(f for f in facts if f)

    def stated(self, *facts: str) -> str:
        """The named facts in the words every output states them in (docstrings, comments
        of default params files, JSON Schema hover text), those that apply, in order."""
        words = self._fact_words
        return " ".join(words[fact] for fact in facts if words[fact])

    @functools.cached_property
    def _fact_words(self) -> dict[str, str]:
        return {
            "type": f"Type: {self.type.name}.",
            "unit": f"Unit: {self.unit}." if self.unit else "",
            "read_only": "Read-only." if self.read_only else "",
            "condition": f"{self.condition_words}." if self.when else "",
            "constraints": f"Constraints: {self.all_constraints_text}." if self.constraints else "",
            "old_names": f"Old names: {', '.join(self.aliases)}." if self.aliases else "",
        }

    @functools.cached_property
    def compiled(self) -> CompiledParam:
        """This parameter compiled by the runtime, exactly as a node compiles it: its checks
        judge values offline and word every constraint, so no output words one itself."""
        extra = (EntryKeys(self.keys_entries_of),) if self.keys_entries_of else ()
        return compile_param(self.runtime_spec, extra)

    @property
    def runtime_spec(self) -> ParamSpec:
        """The ``ParamSpec`` a generated module holds for this parameter."""
        return ParamSpec(self.ros_name, self.type.name, **dict(self.spec_options))

    @functools.cached_property
    def constraints(self) -> tuple[str, ...]:
        """Every constraint in the runtime's words, the range included."""
        return self.compiled.constraints

    @functools.cached_property
    def all_constraints_text(self) -> str:
        """Every constraint on one line (hover text, comments)."""
        return "; ".join(self.constraints)

    @functools.cached_property
    def spec_options(self) -> tuple[tuple[str, Any], ...]:
        """Keyword arguments of the runtime ParamSpec that differ from their defaults."""
        options: list[tuple[str, Any]] = []
        if self.required:
            options.append(("required", True))
        elif self.optional:
            options.append(("optional", True))
        else:
            options.append(("default", self.default))
        for key, value, empty in (
            ("description", self.description, ""),
            ("read_only", self.read_only, False),
            ("unit", self.unit, ""),
            ("range", self.range.as_tuple() if self.range else None, None),
            ("choices", self.choices, None),
            ("validators", tuple(v.as_tuple() for v in self.validators), ()),
            ("additional_constraints", self.additional_constraints, ""),
            ("deprecated", self.deprecated, ""),
            ("aliases", self.aliases, ()),
            ("configure_only", self.configure_only, False),
            ("adopt", self.adopt, False),
            ("when", self.when, ()),
        ):
            if value != empty:
                options.append((key, value))
        return tuple(options)


@dataclass(frozen=True)
class Field:
    """One attribute of a generated class: a parameter or a nested group."""

    attribute: str
    annotation: str
    docstring: str


@dataclass(frozen=True)
class OpenNamespace:
    """A namespace whose parameters other code declares (a plugin, a filter chain).

    genparams declares nothing under it; params files may set anything there,
    and docs say who owns it.
    """

    ros_name: str  # dotted; holds ``*`` inside a mapped group
    path: tuple[str, ...]
    description: str
    location: Location


@dataclass(frozen=True)
class Group:
    """A namespace; with ``mapped_over``, a mapped group: one entry per item of that parameter.

    Inside a mapped group, names hold ``*`` where an entry's key goes:
    the parameter ``p`` of the mapped group ``gains`` is ``gains.*.p``.
    An ``in_place`` mapped group (schema key ``"*"``) adds no name of its own:
    its entries sit in its parent namespace beside the parent's other names,
    and Python reads them by key on the parent (``cfg.constraints["elbow"]``).
    """

    ros_name: str  # dotted namespace, "" for the top level
    path: tuple[str, ...]
    attribute: str  # attribute in the parent group ("" for the top level)
    class_name: str  # for a mapped group, the class of one entry
    parameters: tuple[Parameter, ...]
    groups: tuple[Group, ...]
    mapped_over: str = ""  # ROS name of the string_array parameter whose items key the entries
    open_namespaces: tuple[OpenNamespace, ...] = ()
    in_place: bool = False  # a "*" group: path and ros_name are its parent's
    # A leaf with for_each: one parameter per item, named by the item (``offsets.<item>``);
    # its one parameter is the template (``offsets.*``), and it has no class of its own.
    per_item: bool = False

    @property
    def keyed_by(self) -> str:
        """What keys the entries, in every output's words: "item of joints", or for an open
        group (``for_each: overrides``) "key given under sensors"."""
        if self.mapped_over == OVERRIDE_KEYS:
            return f"key given under {self.ros_name} in the overrides"
        return f"item of {self.mapped_over}"

    @property
    def entry_annotation(self) -> str:
        """The type of one entry: the entry class, or the value of a per-item parameter."""
        return self.parameters[0].annotation if self.per_item else self.class_name

    @property
    def entries_group(self) -> Group | None:
        """The in-place mapped group whose entries this group holds by key, if any."""
        return next((g for g in self.groups if g.in_place), None)

    @property
    def spec_path(self) -> str:
        """The runtime's key for this group's class: one entry's path for a mapped group."""
        return ".".join((*self.path, ENTRY_KEY)) if self.mapped_over else self.ros_name

    @property
    def annotation(self) -> str:
        """The type of this group as an attribute of its parent."""
        return f"_Mapping[str, {self.entry_annotation}]" if self.mapped_over else self.class_name

    @property
    def field_docstring(self) -> str:
        if self.per_item:
            return self.parameters[0].docstring
        if self.mapped_over:
            return f"Mapped group {self.ros_name}: one entry per {self.keyed_by}."
        return f"Namespace {self.ros_name}."

    @property
    def fields(self) -> tuple[Field, ...]:
        fields = [Field(p.attribute, p.annotation, p.docstring) for p in self.parameters]
        fields.extend(
            Field(g.attribute, g.annotation, g.field_docstring)
            for g in self.groups
            if not g.in_place
        )
        return tuple(sorted(fields, key=lambda f: f.attribute))

    @property
    def docstring(self) -> str:
        if self.mapped_over:
            where = self.ros_name or "the top level"
            return f"One entry of {where}, for each {self.keyed_by}."
        return f"Parameters under {self.ros_name}." if self.ros_name else ""

    @property
    def slots(self) -> tuple[str, ...]:
        """Field attributes; ``_map`` holds the entries of an in-place mapped group."""
        names = tuple(f.attribute for f in self.fields)
        return ("_map", *names) if self.entries_group is not None else names  # ruff's order

    def walk_groups(self) -> Iterator[Group]:
        """Every group below this one, children before parents (definition order);
        per-item parameters (a leaf with for_each) included."""
        for group in self.groups:
            yield from group.walk_groups()
            yield group

    def walk_parameters(self) -> Iterator[Parameter]:
        yield from self.parameters
        for group in self.groups:
            yield from group.walk_parameters()

    def walk_open_namespaces(self) -> Iterator[OpenNamespace]:
        yield from self.open_namespaces
        for group in self.groups:
            yield from group.walk_open_namespaces()


@dataclass(frozen=True)
class Rule:
    """A cross-parameter rule; ``check`` goes to generated code as text, parsed at run time."""

    name: str
    check: str
    description: str
    parameters: tuple[str, ...]  # ROS names the check reads, in order of appearance
    location: Location  # of the check

    @property
    def spec_options(self) -> tuple[tuple[str, Any], ...]:
        """Keyword arguments of the runtime RuleSpec that differ from their defaults."""
        return (("description", self.description),) if self.description else ()


@dataclass(frozen=True)
class Schema:
    name: str
    description: str
    source_name: str  # file name of the schema, for the generated header
    class_name: str
    module_name: str
    root: Group
    rules: tuple[Rule, ...] = ()

    @property
    def nested_groups(self) -> tuple[Group, ...]:
        """The groups that are classes: per-item parameters have none."""
        return tuple(g for g in self.root.walk_groups() if not g.per_item)

    @property
    def parameters(self) -> tuple[Parameter, ...]:
        return tuple(sorted(self.root.walk_parameters(), key=lambda p: p.ros_name))

    @property
    def open_namespaces(self) -> tuple[OpenNamespace, ...]:
        return tuple(sorted(self.root.walk_open_namespaces(), key=lambda n: n.ros_name))

    @property
    def docstring(self) -> str:
        """Module and class docstring. Stripped, because ruff format strips docstrings."""
        return self.description.strip() or f"Parameters of {self.name}."

    @property
    def maps(self) -> tuple[tuple[str, str], ...]:
        """(mapped group, its for_each parameter), for the runtime."""
        return tuple((g.ros_name, g.mapped_over) for g in self.root.walk_groups() if g.mapped_over)

    @property
    def uses_mapping(self) -> bool:
        return bool(self.maps)

    @property
    def uses_any(self) -> bool:
        """Whether a parameter is of type ``any``, annotated with the runtime's RosValue."""
        return any(p.type.is_dynamic for p in self.parameters)

    @property
    def uses_none_of(self) -> bool:
        """Whether a condition is negated (``when: {mode: {not: x}}``): the module then
        imports the runtime's NoneOf; modules without one read exactly as before it."""
        return any(isinstance(t, NoneOf) for p in self.parameters for _, t in p.when)

    @property
    def uses_entries_by_key(self) -> bool:
        """Whether a generated class reads in-place entries by key (``__getitem__``)."""
        return any(g.entries_group is not None for g in (self.root, *self.nested_groups))

    @property
    def class_names(self) -> tuple[str, ...]:
        return tuple(sorted([self.class_name, *(g.class_name for g in self.nested_groups)]))


def with_entry_keys(root: Group) -> Group:
    """``root`` with each for_each parameter told which mapped groups its items name."""
    keyed: dict[str, list[str]] = {}
    for group in root.walk_groups():  # the order the runtime compiles SchemaSpec.maps in
        if group.mapped_over and group.mapped_over != OVERRIDE_KEYS:
            keyed.setdefault(group.mapped_over, []).append(group.ros_name or "the top level")
    if not keyed:
        return root

    def mark(group: Group) -> Group:
        parameters = tuple(
            replace(p, keys_entries_of=", ".join(keyed[p.ros_name])) if p.ros_name in keyed else p
            for p in group.parameters
        )
        return replace(group, parameters=parameters, groups=tuple(map(mark, group.groups)))

    return mark(root)
