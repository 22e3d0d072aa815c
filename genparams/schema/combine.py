"""Several classes declared on one node, seen as one schema of that node's parameters.

A node may declare several generated classes, each under a prefix (the
steering controllers declare two at the root). Params-file outputs (the
defaults file, the JSON Schema) describe the node, so they need the union:
every parameter renamed under its class's prefix, namespaces of the same name
merged. Cross-parameter rules stay with their own class: they are not part of
the union (check-params checks them class by class).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

from genparams.schema.errors import SchemaError, SchemaProblem
from genparams.schema.model import Group, Parameter, Schema


def combined_schema(schemas: Sequence[tuple[Schema, str]]) -> Schema:
    """One schema of every ``(schema, prefix)``; raises SchemaError if two declare one name."""
    first = schemas[0][0]
    if len(schemas) == 1 and not schemas[0][1]:
        return first
    root = Group("", (), "", first.root.class_name, (), ())
    for schema, prefix in schemas:
        root = _merge(root, _under(schema.root, prefix))
    seen: dict[str, Parameter] = {}
    for parameter in root.walk_parameters():
        if parameter.ros_name in seen:
            raise SchemaError(
                [SchemaProblem(parameter.location, parameter.ros_name, "declared by two classes")]
            )
        seen[parameter.ros_name] = parameter
    return dataclasses.replace(
        first,
        name="+".join(s.name for s, _ in schemas),
        description=" ".join(s.description.strip() for s, _ in schemas if s.description),
        source_name=", ".join(s.source_name for s, _ in schemas),
        root=root,
        rules=(),
    )


def _under(root: Group, prefix: str) -> Group:
    """``root`` with every name moved under ``prefix`` (nested namespaces, one per token)."""
    if not prefix:
        return root
    tokens = tuple(prefix.split("."))
    inner = dataclasses.replace(_renamed(root, prefix), attribute=tokens[-1])
    for depth in range(len(tokens) - 1, 0, -1):
        path = tokens[:depth]
        inner = Group(".".join(path), path, path[-1], path[-1].title(), (), (inner,))
    return Group("", (), "", root.class_name, (), (inner,))


def _renamed(group: Group, prefix: str) -> Group:
    tokens = tuple(prefix.split("."))

    def name(dotted: str) -> str:
        return f"{prefix}.{dotted}" if dotted else prefix

    return dataclasses.replace(
        group,
        ros_name=name(group.ros_name),
        path=(*tokens, *group.path),
        mapped_over=name(group.mapped_over) if group.mapped_over else "",
        parameters=tuple(
            dataclasses.replace(
                p,
                ros_name=name(p.ros_name),
                path=(*tokens, *p.path),
                aliases=tuple(name(a) for a in p.aliases),
            )
            for p in group.parameters
        ),
        groups=tuple(_renamed(g, prefix) for g in group.groups),
    )


def _merge(one: Group, other: Group) -> Group:
    """Two groups at the same path as one: parameters of both, same-named subgroups merged."""
    groups = {g.path[-1]: g for g in one.groups}
    for group in other.groups:
        key = group.path[-1]
        groups[key] = _merge(groups[key], group) if key in groups else group
    return dataclasses.replace(
        one, parameters=(*one.parameters, *other.parameters), groups=tuple(groups.values())
    )
