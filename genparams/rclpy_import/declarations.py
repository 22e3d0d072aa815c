"""One ``declare_parameter`` call, or one item of a ``declare_parameters`` list (or one
``self.get_parameter`` read) -> a ``Found``: its name, value and descriptor as far as they
could be read, and the context (condition, loop, helper) it sits in."""

from __future__ import annotations

import ast
from dataclasses import dataclass, replace
from typing import Any

from genparams.rclpy_import.found import Found, Piece, SourceFile
from genparams.rclpy_import.item_names import folded
from genparams.rclpy_import.scope import Scope, UntranslatableError, unparsed
from genparams.rclpy_import.values import Evaluator
from genparams.runtime.core.conditions import KeyTest
from genparams.schema.errors import Location

SAMPLE_ITEM = "item"  # a loop's item, to type a value computed from it


@dataclass(frozen=True)
class Context:
    """Where a statement sits: the file, and the conditions, loops and helpers around it."""

    source: SourceFile
    condition: str | None = None
    runtime_loop: str | None = None
    loop_targets: frozenset[str] = frozenset()
    nested: str | None = None
    literal_loop: ast.For | None = None
    loop_parameter: str | None = None
    loop_variable: str | None = None
    when: tuple[str, KeyTest] | None = None
    loop_prefix: str | None = None
    loop_source: ast.AST | None = None
    via: str | None = None  # the helper, base class or object declaring for the node
    call_site: Location | None = None  # where a helper declaring for the node is called
    reads: tuple[str, ...] = ()  # parameters the helper's arguments were computed from
    # The variable of a loop over the node's own parameter names (``for name in
    # self._parameters``): a read of it reads a parameter declared already.
    own_name: str | None = None
    late: str | None = None  # the method, when nothing read calls it

    def changed(self, **changes: Any) -> Context:
        return replace(self, **changes)


def declare_one(call: ast.Call, statement: ast.stmt, scope: Scope, context: Context) -> Found:
    args = arguments(call, ("name", "value", "descriptor", "ignore_override"))
    name_node = args.get("name")
    pieces = [piece(args.get(key), scope) for key in ("name", "value", "descriptor")]
    at = name_node if name_node is not None else call
    return _found(
        call, at, statement, pieces, piece(args.get("ignore_override"), scope), context,
        name_node, scope, value_node=args.get("value"),
    )  # fmt: skip


def declare_many(
    call: ast.Call, statement: ast.stmt, scope: Scope, context: Context
) -> list[Found]:
    args = arguments(call, ("namespace", "parameters", "ignore_override"))
    namespace = piece(args.get("namespace"), scope)
    ignore = piece(args.get("ignore_override"), scope)
    listed = args.get("parameters")
    # each item: where it is, its pieces, its name and its value as written
    items: list[tuple[ast.AST, list[Piece], ast.AST | None, ast.expr | None]] = []
    if isinstance(listed, (ast.List, ast.Tuple)):
        for element in listed.elts:
            if isinstance(element, ast.Tuple):
                pieces = [piece(node, scope) for node in element.elts[:3]]
                first = element.elts[0] if element.elts else None
                written = element.elts[1] if len(element.elts) > 1 else None
                items.append((element, pieces, first, written))
            else:
                items.append((element, _value_pieces(element, scope), None, None))
    elif listed is not None:
        whole = piece(listed, scope)
        if whole.problem is None and isinstance(whole.value, (list, tuple)):
            for item in whole.value:
                pieces = [Piece(True, v) for v in item] if isinstance(item, tuple) else []
                items.append((listed, pieces or [Piece(True, None, _bad(listed))], None, None))
        else:
            problem = whole.problem or UntranslatableError(listed, unparsed(listed))
            items.append((listed, [Piece(True, None, problem)], None, None))
    out = []
    for at, pieces, name_node, written in items:
        pieces = pieces + [Piece() for _ in range(3 - len(pieces))]
        pieces[0] = _joined(namespace, pieces[0])
        out.append(
            _found(
                call,
                at,
                statement,
                pieces,
                ignore,
                context,
                name_node,
                scope,
                value_node=written,
                in_list=True,
                namespace_node=args.get("namespace"),
            )
        )
    return out


def read(call: ast.Call, statement: ast.stmt, scope: Scope, context: Context, kind: str) -> Found:
    """``self.get_parameter(name)``: a parameter the node needs."""
    name = call.args[0]
    pieces = [piece(name, scope), Piece(), Piece()]
    return _found(call, name, statement, pieces, Piece(), context, name, scope, read=kind)


def _found(
    call: ast.Call,
    at: ast.AST,
    statement: ast.stmt,
    pieces: list[Piece],
    ignore: Piece,
    context: Context,
    name_node: ast.AST | None,
    scope: Scope,
    **more: Any,
) -> Found:
    name, value, descriptor = pieces[:3]
    variable = context.loop_variable
    if name.problem is not None and variable is not None and isinstance(name_node, ast.expr):
        # a name built in a variable, or from a nested function's argument
        name_node = folded(name_node, scope, variable) or name_node
    found = Found(
        call,
        at,
        context.call_site or context.source.location(at),
        statement,
        name,
        value,
        descriptor,
        ignore,
        condition=context.condition,
        runtime_loop=context.runtime_loop,
        name_is_item=isinstance(name_node, ast.Name) and name_node.id in context.loop_targets,
        nested=context.nested,
        literal_loop=context.literal_loop,
        name_node=name_node,
        loop_parameter=context.loop_parameter,
        loop_variable=context.loop_variable,
        when=context.when,
        loop_prefix=context.loop_prefix,
        loop_source=context.loop_source,
        via=context.via,
        late=context.late,
        **more,
    )
    if context.reads and found.value.problem is None:
        value = replace(
            found.value, reads=tuple(dict.fromkeys([*found.value.reads, *context.reads]))
        )
        found = replace(found, value=value)
    return replace(found, item_value=_item_value(found, scope))


def arguments(call: ast.Call, names: tuple[str, ...]) -> dict[str, ast.expr]:
    args: dict[str, ast.expr] = dict(zip(names, call.args, strict=False))
    for keyword in call.keywords:
        if keyword.arg in names:
            args[keyword.arg] = keyword.value
    return args


def piece(node: ast.expr | None, scope: Scope) -> Piece:
    if node is None:
        return Piece()
    evaluator = Evaluator(scope)
    try:
        value = evaluator.value(node)
    except UntranslatableError as exc:
        return Piece(True, None, exc)
    return Piece(True, value, reads=tuple(dict.fromkeys(evaluator.parameters_read)))


def _value_pieces(node: ast.expr, scope: Scope) -> list[Piece]:
    """A declare_parameters item that is not written as a tuple (a variable, a constant)."""
    whole = piece(node, scope)
    if whole.problem is None and isinstance(whole.value, tuple) and whole.value:
        return [Piece(True, v) for v in whole.value]
    return [Piece(True, None, whole.problem or _bad(node))]


def _bad(node: ast.AST) -> UntranslatableError:
    return UntranslatableError(node, f"the item {unparsed(node)!r}")


def _joined(namespace: Piece, name: Piece) -> Piece:
    if namespace.problem is not None:
        return Piece(True, None, namespace.problem)
    if name.problem is not None or not namespace.value:
        return name
    if not isinstance(namespace.value, str) or not isinstance(name.value, str):
        return name
    return Piece(True, f"{namespace.value}.{name.value}")


def _item_value(found: Found, scope: Scope) -> Piece | None:
    """A value computed from the loop's item (``sensor + "_link"``), for a sample item; None
    when the value is not computed, or not from the item."""
    node, variable = found.value_node, found.loop_variable
    if node is None or found.value.problem is None or variable is None:
        return None
    if not any(isinstance(n, ast.Name) and n.id == variable for n in ast.walk(node)):
        return None
    return piece(node, scope.with_loop({variable: SAMPLE_ITEM}))
