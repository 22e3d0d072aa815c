"""What a schema's documentation page says, decided here; the templates only write it out.

Constraints are worded by the runtime's own validators (``Parameter.constraints``),
so the page states exactly the rules a node enforces, in every other output's words.
The "Default configuration" block is the default params file itself (see params_file).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from genparams._version import __version__
from genparams.outputs.params_file import ParamsFile, default_params_file
from genparams.outputs.yaml_text import value_text
from genparams.runtime.core.naming import ENTRY_KEY, OVERRIDE_KEYS
from genparams.schema.model import Group, OpenNamespace, Parameter, Schema

FORMATS = ("markdown", "rst")


@dataclass(frozen=True)
class ParameterDoc:
    name: str  # full dotted ROS name
    type_name: str
    default: str  # as written in a params file; "" when required or optional
    unit: str
    constraints: tuple[str, ...]  # plain words: range and step, choices, every validator
    description: str
    required: bool
    read_only: bool
    deprecated: str  # "" unless deprecated: what to use instead
    old_names: str = ""  # "" unless renamed: its old names, still accepted
    optional: bool = False  # declared by type only: not set until given a value
    condition: str = ""  # "Declared only when mode is 'advanced'", or ""


@dataclass(frozen=True)
class NamespaceDoc:
    name: str  # dotted namespace, "" for the top level
    parameters: tuple[ParameterDoc, ...]
    note: str = ""  # for a mapped group: how its entries are named

    @property
    def is_top_level(self) -> bool:
        return not self.name


@dataclass(frozen=True)
class RuleDoc:
    name: str
    check: str  # the expression as written in the schema, on one line
    description: str


@dataclass(frozen=True)
class DocsPage:
    title: str
    description: str
    class_name: str
    module_name: str
    source_name: str
    version: str
    namespaces: tuple[NamespaceDoc, ...]
    default_params: ParamsFile
    rules: tuple[RuleDoc, ...] = ()

    @property
    def has_rules(self) -> bool:
        return bool(self.rules)

    @property
    def has_required(self) -> bool:
        return any(p.required for ns in self.namespaces for p in ns.parameters)


def docs_page(schema: Schema) -> DocsPage:
    return DocsPage(
        title=schema.name,
        description=schema.description,
        class_name=schema.class_name,
        module_name=schema.module_name,
        source_name=schema.source_name,
        version=__version__,
        namespaces=tuple(
            NamespaceDoc(
                group.spec_path if group.in_place else group.ros_name,
                (
                    *(parameter_doc(p) for p in group.parameters),
                    *(_open_doc(n) for n in group.open_namespaces),
                ),
                _mapped_note(group),
            )
            for group in _documented_groups(schema.root)
        ),
        default_params=default_params_file(schema, comments=False),
        rules=tuple(RuleDoc(r.name, _one_line(r.check), r.description) for r in schema.rules),
    )


def _one_line(check: str) -> str:
    """A check written over several YAML lines, on one line (a line break means a space)."""
    return re.sub(r"\s*\n\s*", " ", check.strip())


def _documented_groups(group: Group) -> Iterator[Group]:
    """Groups holding parameters, each before its children, in schema order."""
    if group.parameters or group.open_namespaces:
        yield group
    for child in group.groups:
        yield from _documented_groups(child)


def _mapped_note(group: Group) -> str:
    if group.per_item:
        return (
            f"One parameter per item of {group.mapped_over}, named by the item; "
            f"in the name below, {ENTRY_KEY} is the item."
        )
    if not group.mapped_over:
        return ""
    what = "key" if group.mapped_over == OVERRIDE_KEYS else "item"
    return f"One entry per {group.keyed_by}; in the names below, {ENTRY_KEY} is the {what}."


def _open_doc(namespace: OpenNamespace) -> ParameterDoc:
    """An open namespace, listed among the parameters: other code declares what it holds."""
    owner = "Open namespace: other code of the node declares the parameters under it."
    return ParameterDoc(
        name=f"{namespace.ros_name}.*",
        type_name="any",
        default="",
        unit="",
        constraints=(),
        description=f"{namespace.description} {owner}".strip(),
        required=False,
        read_only=False,
        deprecated="",
        old_names="",
    )


def parameter_doc(parameter: Parameter) -> ParameterDoc:
    return ParameterDoc(
        name=parameter.ros_name,
        type_name=parameter.type.name,
        default=""
        if parameter.required or parameter.optional
        else value_text(parameter.default, parameter.type),
        unit=parameter.unit,
        constraints=parameter.constraints,
        description=parameter.description,
        required=parameter.required,
        read_only=parameter.read_only,
        deprecated=parameter.deprecated,
        old_names=", ".join(parameter.aliases),
        optional=parameter.optional,
        condition=parameter.condition_words,
    )
