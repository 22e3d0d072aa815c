"""What a class's methods see, and what a call hands a function it reads: names in scope
and argument values, read without running anything."""

from __future__ import annotations

import ast
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from genparams.rclpy_import.resolve import ClassFound
from genparams.rclpy_import.scope import Scope, UntranslatableError
from genparams.rclpy_import.values import Evaluator


def class_scope(chain: list[ClassFound]) -> Scope:
    """Names in a class's methods: its module's, and its (and its bases') attributes
    and methods, the nearest class winning."""
    module = chain[0].module
    constants: dict[str, Any] = {}
    functions: dict[str, ast.FunctionDef] = {}
    for cls in reversed(chain):
        constants.update(cls.module.class_constants(cls.definition))
        for statement in cls.definition.body:
            if isinstance(statement, ast.FunctionDef):
                functions[f"self.{statement.name}"] = statement
    scope = module.scope()
    return replace(
        scope,
        class_name=chain[0].definition.name,
        class_constants=constants,
        functions={**scope.functions, **functions},
    )


def bound_arguments(
    function: ast.FunctionDef | ast.AsyncFunctionDef,
    call: ast.Call,
    caller: Scope,
    scope: Scope,
    declared: Mapping[str, Any],
    reads: list[str] | None = None,
) -> dict[str, Any]:
    """The values ``call`` gives ``function``'s arguments (or their defaults), as far
    as they can be read (``declared``: the defaults of the parameters declared so far);
    a method's or constructor's ``self`` takes none."""
    names = [a.arg for a in function.args.args]
    if (
        names
        and names[0] == "self"
        and (isinstance(call.func, ast.Attribute) or function.name == "__init__")
    ):
        names = names[1:]
    bound: dict[str, Any] = {}
    defaults = function.args.defaults
    for name, default in zip(names[len(names) - len(defaults) :], defaults, strict=False):
        try:
            bound[name] = Evaluator(scope).value(default)
        except UntranslatableError:
            pass
    arguments: list[tuple[str, ast.expr]] = list(zip(names, call.args, strict=False))
    arguments += [(k.arg, k.value) for k in call.keywords if k.arg is not None]
    known = replace(caller, parameters=dict(declared))
    for name, argument in arguments:
        evaluator = Evaluator(known)
        try:
            bound[name] = evaluator.value(argument)
        except UntranslatableError:
            bound.pop(name, None)
        if reads is not None:
            reads.extend(evaluator.parameters_read)
    return bound
