"""Shapes of the node's source the patch rewrites: a read of a parameter's value, a block
that only declares, the block holding a statement, a free attribute for the parameters."""

from __future__ import annotations

import ast
from collections.abc import Iterator, Mapping
from typing import Any

_READ_ATTRIBUTES = ("value",)


def read_of(call: ast.Call, parents: dict[ast.AST, ast.AST]) -> ast.AST | None:
    parent = parents.get(call)
    if isinstance(parent, ast.Attribute) and parent.attr in _READ_ATTRIBUTES:
        return parent
    if isinstance(parent, ast.Attribute) and parent.attr == "get_parameter_value":
        value_call = parents.get(parent)
        outer = parents.get(value_call) if value_call is not None else None
        if (
            isinstance(value_call, ast.Call)
            and not value_call.args
            and isinstance(outer, ast.Attribute)
            and outer.attr.endswith("_value")
        ):
            return outer
    return None


def always_set(schema: Mapping[str, Any], name: str) -> bool:
    """Whether the schema's parameter ``name`` holds a value whenever the node runs: it
    is declared unconditionally, under its own name (not one per item), and has a default
    or must be given one (not optional)."""
    entry: Any = schema.get("parameters", {})
    for part in name.split("."):
        if not isinstance(entry, dict) or part not in entry:
            return False
        entry = entry[part]
    return (
        isinstance(entry, dict)
        and not entry.get("optional")
        and "when" not in entry
        and "for_each" not in entry  # per item: no parameter has the key's own name
    )


def self_calls(root: ast.AST, method: str) -> Iterator[ast.Call]:
    for node in ast.walk(root):
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr == method
            and isinstance(node.func.value, ast.Name)
            and node.func.value.id == "self"
        ):
            yield node


def _declares(statement: ast.stmt) -> bool:
    return (
        isinstance(statement, ast.Expr)
        and isinstance(statement.value, ast.Call)
        and isinstance(statement.value.func, ast.Attribute)
        and statement.value.func.attr.startswith("declare_parameter")
    )


def declaring_branches(block: ast.For | ast.If) -> list[ast.stmt] | None:
    """Every statement of a loop (without ``else``), or of an ``if`` with its ``elif`` and
    ``else`` branches, when each declares a parameter; None when one does something else."""
    statements = list(block.body)
    rest = block.orelse
    if isinstance(block, ast.For) and rest:
        return None
    if len(rest) == 1 and isinstance(rest[0], ast.If):  # an elif
        inner = declaring_branches(rest[0])
        if inner is None:
            return None
        statements += inner
    else:
        statements += rest
    return statements if all(_declares(s) for s in statements) else None


def only_declares(block: ast.For | ast.If) -> bool:
    return declaring_branches(block) is not None


def only_read_in(name: str, scope: ast.AST, removed: list[ast.stmt]) -> bool:
    """Whether the variable ``name`` is read in ``scope``, each time inside a statement of
    ``removed``."""
    inside = {id(node) for statement in removed for node in ast.walk(statement)}
    loads = [
        node
        for node in ast.walk(scope)
        if isinstance(node, ast.Name) and node.id == name and isinstance(node.ctx, ast.Load)
    ]
    return bool(loads) and all(id(node) in inside for node in loads)


def body_of(statement: ast.stmt, parents: dict[ast.AST, ast.AST]) -> list[ast.stmt] | None:
    parent = parents.get(statement)
    if parent is None:
        return None
    for name in ("body", "orelse", "finalbody"):
        body = getattr(parent, name, None)
        if isinstance(body, list) and statement in body:
            return body
    return None


def free_attribute(cls: ast.ClassDef) -> str:
    used = {
        node.attr
        for node in ast.walk(cls)
        if isinstance(node, ast.Attribute)
        and isinstance(node.value, ast.Name)
        and node.value.id == "self"
    }
    for candidate in ("params", "typed_params", "genparams"):
        if candidate not in used:
            return candidate
    return "genparams_params"
