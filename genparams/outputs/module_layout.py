"""How a generated module lays out its spec and classes to stay small in memory.

A module of 10,000 parameters of ten kinds writes ten options rows and a
table of ``(name, default, row)``; a module of 1,111 groups of three shapes
makes three group classes at run time: every other group's class is an alias
of the first class of its shape, while type checkers (and IDEs) still see one
class per group, with its own docstrings.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from genparams.schema.model import Group, Parameter, Schema


@dataclass(frozen=True)
class OptionsRow:
    """One ``ParamOptions`` of the module: the type and the keyword options."""

    type: str
    options: tuple[tuple[str, Any], ...]


@dataclass(frozen=True)
class SpecTable:
    options: tuple[OptionsRow, ...]
    rows: tuple[tuple[str, Any, int], ...]  # (ROS name, default, index into options)


def _options_row(parameter: Parameter) -> OptionsRow:
    options = tuple((key, value) for key, value in parameter.spec_options if key != "default")
    return OptionsRow(parameter.type.name, options)


def spec_table(schema: Schema) -> SpecTable:
    """Each distinct options row once, in order of first use, and the parameters' rows."""
    index: dict[str, int] = {}
    options: list[OptionsRow] = []
    rows: list[tuple[str, Any, int]] = []
    for parameter in schema.parameters:
        row = _options_row(parameter)
        key = repr(row)  # repr tells 1 from 1.0 and True, which == does not
        if key not in index:
            index[key] = len(options)
            options.append(row)
        default = dict(parameter.spec_options).get("default")
        rows.append((parameter.ros_name, default, index[key]))
    return SpecTable(tuple(options), tuple(rows))


def runtime_classes(schema: Schema) -> dict[str, str]:
    """Each group class name -> the class it is at run time: the first class of its shape.

    Two groups share a class when their classes would behave the same: the same
    attributes for the same ROS names, the same types (the classes of nested groups
    compared as shared), and no entries read by key (``_map``). Docstrings differ
    freely: they are for readers and type checkers, which keep one class per group.
    """
    shared: dict[str, str] = {}
    first_of_shape: dict[tuple[Any, ...], str] = {}
    for group in schema.nested_groups:  # children before parents
        if group.entries_group is not None:
            shared[group.class_name] = group.class_name
            continue
        shape = _shape(group, shared)
        shared[group.class_name] = first_of_shape.setdefault(shape, group.class_name)
    return shared


def _shape(group: Group, shared: dict[str, str]) -> tuple[Any, ...]:
    fields: list[tuple[str, str, str]] = [
        (p.attribute, p.ros_name.rpartition(".")[2], p.annotation) for p in group.parameters
    ]
    for child in group.groups:
        if child.in_place:
            continue
        entry = child.entry_annotation if child.per_item else shared[child.class_name]
        annotation = f"_Mapping[str, {entry}]" if child.mapped_over else entry
        fields.append((child.attribute, child.path[-1] if child.path else "", annotation))
    return tuple(sorted(fields))


@dataclass(frozen=True)
class ModuleLayout:
    table: SpecTable
    classes: dict[str, str]  # group class -> its class at run time

    @property
    def aliased(self) -> bool:
        return any(name != shared for name, shared in self.classes.items())


def layout(schema: Schema) -> ModuleLayout:
    return ModuleLayout(spec_table(schema), runtime_classes(schema))
