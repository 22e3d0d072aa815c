"""What a ``for`` loop around declarations means: the items of a loop over literal
values (read once per item), or, for a loop over a value known at run time, what its
body's declarations are per item of (a parameter's list, the keys under a prefix in the
overrides, the node's own parameter names)."""

from __future__ import annotations

import ast
from typing import Any

from genparams.rclpy_import.declarations import Context
from genparams.rclpy_import.overrides import keys_under, over_own_parameters
from genparams.rclpy_import.reads import bind, parameter_read
from genparams.rclpy_import.scope import Scope, UntranslatableError, unparsed
from genparams.rclpy_import.values import Evaluator


def literal_bindings(
    loop: ast.For | ast.AsyncFor, scope: Scope, context: Context
) -> list[dict[str, Any] | None] | None:
    """The loop variable's bindings, one per item, when the loop runs over values read
    statically (``for axis in ("x", "y"):``); None when they are known only at run time."""
    if not isinstance(loop, ast.For) or context.runtime_loop is not None:
        return None
    try:
        items = Evaluator(scope).value(loop.iter)
    except UntranslatableError:
        return None
    if not isinstance(items, (list, tuple)):
        return None
    return [bind(loop.target, item) for item in items]


def runtime_loop_context(loop: ast.For | ast.AsyncFor, scope: Scope, context: Context) -> Context:
    """The context of the body of a loop over a value known at run time: what it runs
    over, and the parameter, overrides prefix or own parameter names it reads."""
    targets = frozenset(n.id for n in ast.walk(loop.target) if isinstance(n, ast.Name))
    variable = loop.target.id if isinstance(loop.target, ast.Name) else None
    first = context.runtime_loop is None and variable is not None
    keys = keys_under(loop.iter, scope) if first else None
    inner = context.changed(
        runtime_loop=context.runtime_loop or unparsed(loop.iter),
        loop_targets=context.loop_targets | targets,
        loop_parameter=parameter_read(loop.iter, scope) if first else None,
        loop_variable=variable if first else None,
        loop_prefix=keys.prefix if keys is not None else None,
        loop_source=keys.source if keys is not None else None,
    )
    if variable is not None and over_own_parameters(loop.iter):
        inner = inner.changed(own_name=variable)
    return inner


def reads_own_parameter(call: ast.Call, context: Context) -> bool:
    """A read named by a loop's item over the node's own parameter names: of one it
    declared already, not a parameter of its own."""
    name = call.args[0] if call.args else None
    return isinstance(name, ast.Name) and name.id == context.own_name
