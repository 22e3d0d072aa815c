"""What a node's statements read: parameters read back (``self.get_parameter('a').value``),
conditions on one, the function's own assignments, the calls of an expression in the order
they run, and the guard of a script's entry point."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from typing import Any

from genparams.rclpy_import.scope import (
    Scope,
    UntranslatableError,
    assigned_once_before,
    read_call,
)
from genparams.rclpy_import.values import Evaluator
from genparams.runtime.core.conditions import KeyTest, NoneOf, both, negated

DECLARE_ONE = "declare_parameter"
DECLARE_MANY = "declare_parameters"
_NESTED = (ast.Lambda, ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)


def condition_on(test: ast.expr, scope: Scope) -> tuple[str, KeyTest] | None:
    """``read == literal`` (or ``!=``), ``literal == read``, ``read in (literals)`` (or
    ``not in``), a truth test (``read``: true, which only a bool parameter compares equal
    to) or ``not`` of any of these: the parameter read and the test it passes (the values
    that make the test true, or NoneOf the values that make it false); None for any other."""
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        inner = condition_on(test.operand, scope)
        return None if inner is None else (inner[0], negated(inner[1]))
    tested = parameter_read(test, scope)
    if tested is not None:
        return tested, (True,)
    if not isinstance(test, ast.Compare) or len(test.ops) != 1:
        return None
    left, right, op = test.left, test.comparators[0], test.ops[0]
    if isinstance(op, (ast.Eq, ast.NotEq)) and parameter_read(left, scope) is None:
        left, right = right, left
    name = parameter_read(left, scope)
    if name is None or not isinstance(op, (ast.Eq, ast.NotEq, ast.In, ast.NotIn)):
        return None
    try:
        value = Evaluator(scope).value(right)
    except UntranslatableError:
        return None
    if isinstance(op, (ast.Eq, ast.NotEq)):
        values: tuple[Any, ...] = (value,)
    elif isinstance(value, (list, tuple)) and value:
        values = tuple(value)
    else:
        return None
    return name, (values if isinstance(op, (ast.Eq, ast.In)) else NoneOf(*values))


def branch_condition(
    outer: str | None, outer_when: tuple[str, KeyTest] | None, tested: tuple[str, KeyTest] | None
) -> tuple[str, KeyTest] | None:
    """The ``when`` of a branch whose own test is ``tested`` (negated for an ``else``),
    inside the condition ``outer`` (None at the top) translated as ``outer_when``: the test,
    or, in a branch of a test on the same parameter (an ``elif``, an ``if`` in an ``if``),
    both tests in one; None when it cannot be a ``when``."""
    if outer is None or tested is None:
        return tested if outer is None else None
    if outer_when is None or outer_when[0] != tested[0]:
        return None
    return tested[0], both(outer_when[1], tested[1])


_MAX_READS = 4  # variables assigned from variables assigned from a read


def parameter_read(node: ast.AST, scope: Scope, depth: int = 0) -> str | None:
    """The parameter whose value ``node`` is: ``x.get_parameter('a').value`` (or
    ``.get_parameter_value().string_array_value``, or the value a ``declare_parameter``
    returns, or a variable holding what it returns: ``read_call``), or a variable (``v``,
    ``self.v``) the function assigns once, from one, before this use."""
    call = read_call(node, scope)
    if call is not None:
        try:
            name = Evaluator(scope).value(call.args[0])
        except UntranslatableError:
            return None
        return name if isinstance(name, str) else None
    if depth >= _MAX_READS:
        return None
    statement = assigned_once_before(node, scope)
    if statement is None:
        return None
    return parameter_read(statement.value, scope, depth + 1)


def calls_in(node: ast.AST, nested: str | None) -> Iterator[tuple[ast.Call, str | None]]:
    """Calls under ``node`` in evaluation order (inner calls first), with the nested
    construct holding them."""
    for child in ast.iter_child_nodes(node):
        if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            continue
        inner = nested
        if isinstance(child, _NESTED) and nested is None:
            inner = "a lambda" if isinstance(child, ast.Lambda) else "a comprehension"
        yield from calls_in(child, inner)
        if isinstance(child, ast.Call):
            yield child, inner


def is_main_guard(statement: ast.If) -> bool:
    """``if __name__ == "__main__":``."""
    test = statement.test
    return (
        isinstance(test, ast.Compare)
        and len(test.ops) == 1
        and isinstance(test.ops[0], ast.Eq)
        and {ast.dump(test.left), ast.dump(test.comparators[0])}
        == {ast.dump(ast.Name("__name__", ast.Load())), ast.dump(ast.Constant("__main__"))}
    )


def locals_of(function: ast.AST) -> dict[str, list[ast.stmt]]:
    """Assignments to the function's variables (``x = ...``), and to attributes of them
    (``descriptor.read_only = ...`` under the keys ``descriptor.*`` and
    ``descriptor.read_only``, ``self.rate = ...`` under ``self.rate``), in source order."""
    out: dict[str, list[ast.stmt]] = {}
    for node in ast.walk(function):
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    out.setdefault(target.id, []).append(node)
                elif isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name):
                    out.setdefault(f"{target.value.id}.*", []).append(node)
                    out.setdefault(f"{target.value.id}.{target.attr}", []).append(node)
                elif isinstance(target, (ast.Tuple, ast.List)):  # unpacking: not followed
                    for name in ast.walk(target):
                        if isinstance(name, ast.Name):
                            out.setdefault(name.id, []).append(ast.Pass(**_position(node)))
        elif isinstance(node, (ast.AnnAssign, ast.AugAssign)) and isinstance(node.target, ast.Name):
            kept: ast.stmt = (
                node if isinstance(node, ast.AnnAssign) else ast.Pass(**_position(node))
            )
            out.setdefault(node.target.id, []).append(kept)
        elif isinstance(node, (ast.For, ast.AsyncFor, ast.With, ast.comprehension)):
            targets = (
                [node.target]
                if isinstance(node, (ast.For, ast.AsyncFor, ast.comprehension))
                else [i.optional_vars for i in node.items if i.optional_vars is not None]
            )
            for target in targets:
                for name in ast.walk(target):
                    if isinstance(name, ast.Name) and hasattr(node, "lineno"):
                        out.setdefault(name.id, []).append(ast.Pass(**_position(node)))
    for statements in out.values():
        statements.sort(key=lambda s: (s.lineno, s.col_offset))
    return out


def _position(node: ast.AST) -> dict[str, int]:
    """A placeholder's place: where the binding starts (a loop variable is bound there)."""
    line, column = getattr(node, "lineno", 0), getattr(node, "col_offset", 0)
    return {"lineno": line, "col_offset": column, "end_lineno": line, "end_col_offset": column}


_ACCESSORS = {
    "bool_value": "bool",
    "integer_value": "int",
    "double_value": "double",
    "string_value": "string",
    "byte_array_value": "byte_array",
    "bool_array_value": "bool_array",
    "integer_array_value": "int_array",
    "double_array_value": "double_array",
    "string_array_value": "string_array",
}


def reads_one(call: ast.Call) -> bool:
    """``self.get_parameter(name)``."""
    func = call.func
    return (
        isinstance(func, ast.Attribute)
        and func.attr == "get_parameter"
        and isinstance(func.value, ast.Name)
        and func.value.id == "self"
        and len(call.args) == 1
        and not call.keywords
    )


def accessor(call: ast.Call, parents: dict[ast.AST, ast.AST]) -> str:
    """The schema type ``<call>.get_parameter_value().string_value`` names; "" for any
    other use (``.value``)."""
    method = parents.get(call)
    value_call = parents.get(method) if method is not None else None
    outer = parents.get(value_call) if value_call is not None else None
    if (
        isinstance(method, ast.Attribute)
        and method.attr == "get_parameter_value"
        and isinstance(value_call, ast.Call)
        and isinstance(outer, ast.Attribute)
    ):
        return _ACCESSORS.get(outer.attr, "")
    return ""


def bind(target: ast.expr, item: Any) -> dict[str, Any] | None:
    if isinstance(target, ast.Name):
        return {target.id: item}
    if isinstance(target, (ast.Tuple, ast.List)) and isinstance(item, (list, tuple)):
        if len(target.elts) != len(item):
            return None
        out: dict[str, Any] = {}
        for sub, value in zip(target.elts, item, strict=False):
            bound = bind(sub, value)
            if bound is None:
                return None
            out.update(bound)
        return out
    return None
