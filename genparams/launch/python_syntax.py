"""What a statement of a ``.launch.py`` holds, binds and leaves, read from its syntax alone."""

from __future__ import annotations

import ast


def targets(node: ast.AST) -> list[ast.expr]:
    """What a statement binds: assignment targets, loop variables, ``as`` names, a ``def``."""
    if isinstance(node, ast.Assign):
        return list(node.targets)
    if isinstance(node, ast.AnnAssign | ast.AugAssign | ast.For):
        return [node.target]
    if isinstance(node, ast.With):
        return [item.optional_vars for item in node.items if item.optional_vars is not None]
    if isinstance(node, ast.FunctionDef):
        return [ast.Name(node.name)]
    return []


def names(target: ast.expr) -> list[str]:
    """The variables a target binds (``a, (b, *c)`` binds a, b and c)."""
    if isinstance(target, ast.Name):
        return [target.id]
    if isinstance(target, ast.Tuple | ast.List):
        return [name for item in target.elts for name in names(item)]
    if isinstance(target, ast.Starred):
        return names(target.value)
    return []


def walk(body: list[ast.stmt]) -> list[ast.AST]:
    """The nodes of ``body``, not those of the functions it defines."""
    found: list[ast.AST] = []
    pending: list[ast.AST] = list(body)
    while pending:
        node = pending.pop()
        found.append(node)
        if not isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda):
            pending.extend(ast.iter_child_nodes(node))
    return found


def leaves(body: list[ast.stmt], loop: bool) -> bool:
    """Whether ``body`` holds a ``return`` (or, under an ``if``, a ``break``/``continue``)
    that leaves what encloses it; loops and functions inside it keep their own."""
    for statement in body:
        if isinstance(statement, ast.Return):
            return True
        if isinstance(statement, ast.Break | ast.Continue) and not loop:
            return True
        if isinstance(statement, ast.If | ast.With | ast.Try | ast.Match):
            inner = [s for part in bodies(statement) for s in part]
            if leaves(inner, loop):
                return True
        if isinstance(statement, ast.For | ast.While):
            if leaves([*statement.body, *statement.orelse], loop=True):
                return True
    return False


def bodies(statement: ast.stmt) -> list[list[ast.stmt]]:
    """The statements a compound statement holds."""
    if isinstance(statement, ast.If | ast.For | ast.While):
        return [statement.body, statement.orelse]
    if isinstance(statement, ast.With):
        return [statement.body]
    if isinstance(statement, ast.Try):
        return [statement.body, statement.orelse, statement.finalbody,
                *(h.body for h in statement.handlers)]  # fmt: skip
    if isinstance(statement, ast.Match):
        return [case.body for case in statement.cases]
    return []
