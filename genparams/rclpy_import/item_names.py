"""A per-item name built in steps, as one expression.

``key = "limits." + joint`` then ``declare_parameter(key, ...)``, or a nested function
called with a part of the name (``def sub(part): declare_parameter(f"{joint}.{part}",
...)``): the name written as literal text and the loop's item alone
(``"limits." + joint``, ``f"{joint}." + "positions"``), so that placing.py finds where
the item sits in it, as it does for a name written in place.
"""

from __future__ import annotations

import ast

from genparams.rclpy_import.scope import Scope, UntranslatableError, last_before
from genparams.rclpy_import.values import Evaluator

_MAX_STEPS = 8  # variables followed inside one another


def folded(node: ast.expr, scope: Scope, variable: str, steps: int = 0) -> ast.expr | None:
    """``node`` with every part but the loop's ``variable`` worked out to text; None when
    a part is neither (a call, a number, a variable assigned more than once before)."""
    if steps > _MAX_STEPS:
        return None
    if isinstance(node, ast.Name) and node.id == variable:
        return node
    try:
        value = Evaluator(scope).value(node)
    except UntranslatableError:
        value = None
    if isinstance(value, str):
        return ast.copy_location(ast.Constant(value), node)
    if isinstance(node, ast.Name):
        assigned = last_before(list(scope.local.get(node.id, [])), node)
        if (
            isinstance(assigned, ast.Assign)
            and len(assigned.targets) == 1
            and isinstance(assigned.targets[0], ast.Name)
        ):
            return folded(assigned.value, scope, variable, steps + 1)
        return None
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left = folded(node.left, scope, variable, steps + 1)
        right = folded(node.right, scope, variable, steps + 1)
        if left is None or right is None:
            return None
        return ast.copy_location(ast.BinOp(left, ast.Add(), right), node)
    if isinstance(node, ast.JoinedStr):
        parts: list[ast.expr] = []
        for part in node.values:
            if isinstance(part, ast.FormattedValue):
                if part.conversion != -1 or part.format_spec is not None:
                    return None
                inner = folded(part.value, scope, variable, steps + 1)
                if isinstance(inner, ast.Name):
                    parts.append(ast.copy_location(ast.FormattedValue(inner, -1, None), part))
                elif isinstance(inner, ast.Constant):
                    parts.append(inner)
                else:
                    return None
            else:
                parts.append(part)
        return ast.copy_location(ast.JoinedStr(parts), node)
    return None
