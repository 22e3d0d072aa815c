"""Find a node's parameter declarations in its syntax tree.

A *unit* is one class whose methods declare parameters, or the module's own
functions when no class does it (``node.declare_parameter`` in ``main()``).
Each ``declare_parameter`` call, and each item of a ``declare_parameters``
list, becomes one ``Found``: its name, value and descriptor as far as they
could be read, with the reason where they could not, and the context that
decides whether it can be translated (a condition, a loop over values read at
run time, a nested function).
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from dataclasses import dataclass, field, replace
from typing import Any

from genparams.rclpy_import.overrides import BY_PREFIX, OVERRIDES, keys_under
from genparams.rclpy_import.values import (
    DescriptorValue,
    Evaluator,
    Scope,
    UntranslatableError,
    assigned_once_before,
    unparsed,
)

DECLARE_ONE = "declare_parameter"
DECLARE_MANY = "declare_parameters"
# Node(...) options and calls that make parameters whose names come from params files.
OPEN_OPTIONS = ("automatically_declare_parameters_from_overrides", "allow_undeclared_parameters")
# Calls that change declared parameters after the fact: the schema cannot follow them.
AFTERWARDS = {
    "set_descriptor": "set_descriptor() changes a descriptor after its declaration",
    "undeclare_parameter": "undeclare_parameter() removes a parameter after its declaration",
}
_NESTED = (ast.Lambda, ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)


@dataclass
class Piece:
    """One argument of a declaration: its value, or why it could not be read."""

    given: bool = False
    value: Any = None
    problem: UntranslatableError | None = None


@dataclass
class Found:
    call: ast.Call  # the declare_parameter(s) call
    at: ast.AST  # where messages point: the name argument or the list item
    statement: ast.stmt  # the innermost statement holding the call
    name: Piece
    value: Piece
    descriptor: Piece
    ignore_override: Piece
    condition: str | None = None  # "if use_gpu" when declared under a condition
    runtime_loop: str | None = None  # the iterable of an enclosing loop read at run time
    name_is_item: bool = False  # the name is that loop's item itself
    nested: str | None = None  # "a lambda" when declared inside one
    literal_loop: ast.For | None = None  # the outermost loop over literal items expanding it
    in_list: bool = False  # an item of a declare_parameters list
    name_node: ast.AST | None = None  # the name argument, as written
    namespace_node: ast.AST | None = None  # a declare_parameters namespace, as written
    # The loop read at run time, when it is the only one and runs over one parameter's
    # value (``for joint in self.get_parameter('joints').value``): that parameter, and
    # the loop variable.
    loop_parameter: str | None = None
    loop_variable: str | None = None
    # The condition, when it is one ``if`` comparing one parameter's value with a literal
    # (``==`` or ``in``) and the declaration sits in its body: the parameter and the
    # values that declare it.
    when: tuple[str, list[Any]] | None = None
    # The loop read at run time, when it is the only one and runs over the keys found under
    # a prefix in the overrides (see overrides.py): that prefix, and the by-prefix call or
    # ``_parameter_overrides`` attribute the keys come from.
    loop_prefix: str | None = None
    loop_source: ast.AST | None = None
    # A value computed from the loop's item (``sensor + "_link"``), worked out for a sample
    # item: its type is the parameter's.
    item_value: Piece | None = None
    value_node: ast.expr | None = None  # the value, as written
    # A read (``self.get_parameter(name)``) rather than a declaration: the schema type its
    # accessor names (``.get_parameter_value().string_value``: "string"), "" for ``.value``.
    read: str | None = None

    @property
    def receiver_is_self(self) -> bool:
        func = self.call.func
        return (
            isinstance(func, ast.Attribute)
            and isinstance(func.value, ast.Name)
            and func.value.id == "self"
        )


@dataclass
class NodeOption:
    """A construct that lets parameters be named by params files."""

    at: ast.AST
    construct: str
    option: str = ""  # the Node() option (see OPEN_OPTIONS), or "" for a read of overrides


@dataclass
class Unit:
    name: str  # the class name, or "" for the module's own functions
    node: ast.ClassDef | ast.Module
    docstring: str | None
    found: list[Found] = field(default_factory=list)
    options: list[NodeOption] = field(default_factory=list)
    afterwards: list[NodeOption] = field(default_factory=list)  # see AFTERWARDS
    reads: list[Found] = field(default_factory=list)  # self.get_parameter(name) calls


def declares(node: ast.AST) -> bool:
    return any(
        isinstance(n, ast.Call)
        and isinstance(n.func, ast.Attribute)
        and n.func.attr in (DECLARE_ONE, DECLARE_MANY)
        for n in ast.walk(node)
    )


def opens(node: ast.AST) -> bool:
    """Whether ``node`` lets params files name parameters (see OPEN_OPTIONS, BY_PREFIX)."""
    return any(
        (isinstance(n, ast.keyword) and n.arg in OPEN_OPTIONS)
        or (isinstance(n, ast.Attribute) and n.attr in (BY_PREFIX, OVERRIDES))
        for n in ast.walk(node)
    )


def units(module: ast.Module) -> list[Unit]:
    """Every class that declares parameters, then the module's functions if they do."""
    out = []
    constants = _constants(module.body)
    functions = _functions(module.body, "")
    for statement in module.body:
        if isinstance(statement, ast.ClassDef) and (declares(statement) or opens(statement)):
            out.append(_scan_class(statement, constants, functions))
    own = [s for s in module.body if not isinstance(s, ast.ClassDef)]
    if any(declares(s) for s in own):
        unit = Unit("", module, ast.get_docstring(module))
        scanner = _Scanner(unit, Scope(module_constants=constants, functions=functions))
        for statement in own:
            if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)):
                scanner.function(statement)
        scanner.walk([s for s in own if not isinstance(s, ast.FunctionDef)], scanner.scope)
        out.append(unit)
    return out


def _scan_class(
    cls: ast.ClassDef,
    module_constants: dict[str, ast.expr],
    module_functions: dict[str, ast.FunctionDef],
) -> Unit:
    unit = Unit(cls.name, cls, ast.get_docstring(cls))
    scope = Scope(
        class_name=cls.name,
        class_constants=_constants(cls.body),
        module_constants=module_constants,
        functions={**module_functions, **_functions(cls.body, "self.")},
    )
    scanner = _Scanner(unit, scope)
    for statement in cls.body:
        if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)):
            scanner.function(statement)
    return unit


def _functions(body: list[ast.stmt], prefix: str) -> dict[str, ast.FunctionDef]:
    return {f"{prefix}{s.name}": s for s in body if isinstance(s, ast.FunctionDef)}


def _constants(body: list[ast.stmt]) -> dict[str, ast.expr]:
    """Names assigned exactly once in ``body`` (``NAME = expr``), with the expression."""
    assigned: dict[str, list[ast.expr]] = {}
    for statement in body:
        for name, value in _assignments(statement):
            assigned.setdefault(name, []).append(value)
    return {name: values[0] for name, values in assigned.items() if len(values) == 1}


def _assignments(statement: ast.stmt) -> Iterator[tuple[str, ast.expr]]:
    if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
        target = statement.targets[0]
        if isinstance(target, ast.Name):
            yield target.id, statement.value
    elif isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name):
        if statement.value is not None:
            yield statement.target.id, statement.value


@dataclass(frozen=True)
class _Context:
    condition: str | None = None
    runtime_loop: str | None = None
    loop_targets: frozenset[str] = frozenset()
    nested: str | None = None
    literal_loop: ast.For | None = None
    loop_parameter: str | None = None
    loop_variable: str | None = None
    when: tuple[str, list[Any]] | None = None
    loop_prefix: str | None = None
    loop_source: ast.AST | None = None


class _Scanner:
    def __init__(self, unit: Unit, scope: Scope) -> None:
        self.unit = unit
        self.scope = scope

    def function(self, function: ast.FunctionDef | ast.AsyncFunctionDef) -> None:
        nested = _functions(function.body, "")
        scope = replace(
            self.scope,
            loop={},
            local=_locals(function),
            functions={**self.scope.functions, **nested},
        )
        self.walk(function.body, scope)

    def walk(self, body: list[ast.stmt], scope: Scope, context: _Context = _Context()) -> None:
        for statement in body:
            self.statement(statement, scope, context)

    def statement(self, statement: ast.stmt, scope: Scope, context: _Context) -> None:
        if isinstance(statement, (ast.For, ast.AsyncFor)):
            self.loop(statement, scope, context)
        elif isinstance(statement, ast.While):
            inner = _replace(
                context,
                runtime_loop=context.runtime_loop or "a while loop",
                loop_parameter=None,
                loop_prefix=None,
            )
            self.walk(statement.body, scope, inner)
            self.walk(statement.orelse, scope, context)
        elif isinstance(statement, ast.If) and is_main_guard(statement):
            # the script's entry point: it runs whenever the file is run as the node
            main_scope = replace(scope, local={**scope.local, **_locals(statement)})
            self.walk(statement.body, main_scope, context)
            self.walk(statement.orelse, scope, context)
        elif isinstance(statement, ast.If):
            inner = _replace(
                context,
                condition=context.condition or f"if {unparsed(statement.test)}",
                when=_when(statement.test, scope) if context.condition is None else None,
            )
            self.expressions(statement.test, statement, scope, context)
            self.walk(statement.body, scope, inner)
            self.walk(statement.orelse, scope, _replace(inner, when=None))
        elif isinstance(statement, (ast.Try, ast.TryStar)):
            self.walk(statement.body, scope, context)
            for handler in statement.handlers:
                inner = _replace(
                    context, condition=context.condition or "an except handler", when=None
                )
                self.walk(handler.body, scope, inner)
            self.walk(statement.orelse, scope, context)
            self.walk(statement.finalbody, scope, context)
        elif isinstance(statement, (ast.With, ast.AsyncWith)):
            for item in statement.items:
                self.expressions(item.context_expr, statement, scope, context)
            self.walk(statement.body, scope, context)
        elif isinstance(statement, ast.Match):
            self.expressions(statement.subject, statement, scope, context)
            for case in statement.cases:
                inner = _replace(context, condition=context.condition or "a match case", when=None)
                self.walk(case.body, scope, inner)
        elif isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            inner = _replace(context, nested=f"the nested definition {statement.name}")
            for child in statement.body:
                self.statement(child, scope, inner)
        else:
            self.expressions(statement, statement, scope, context)

    def loop(self, loop: ast.For | ast.AsyncFor, scope: Scope, context: _Context) -> None:
        items: Any = None
        if isinstance(loop, ast.For) and context.runtime_loop is None:
            try:
                items = Evaluator(scope).value(loop.iter)
            except UntranslatableError:
                items = None
        bindings = None
        if isinstance(items, (list, tuple)):
            bindings = [_bind(loop.target, item) for item in items]
        if bindings is not None and all(b is not None for b in bindings):
            assert isinstance(loop, ast.For)
            inner = _replace(context, literal_loop=context.literal_loop or loop)
            for binding in bindings:
                assert binding is not None
                self.walk(loop.body, scope.with_loop(binding), inner)
        else:
            self.reads_of_overrides(loop.iter)
            targets = frozenset(n.id for n in ast.walk(loop.target) if isinstance(n, ast.Name))
            first = context.runtime_loop is None and isinstance(loop.target, ast.Name)
            keys = keys_under(loop.iter, scope) if first else None
            inner = _replace(
                context,
                runtime_loop=context.runtime_loop or unparsed(loop.iter),
                loop_targets=context.loop_targets | targets,
                loop_parameter=parameter_read(loop.iter, scope) if first else None,
                loop_variable=loop.target.id
                if first and isinstance(loop.target, ast.Name)
                else None,
                loop_prefix=keys.prefix if keys is not None else None,
                loop_source=keys.source if keys is not None else None,
            )
            self.walk(loop.body, scope, inner)
        self.walk(loop.orelse, scope, context)

    def expressions(
        self, root: ast.AST, statement: ast.stmt, scope: Scope, context: _Context
    ) -> None:
        self.reads_of_overrides(root, calls=False)
        parents: dict[ast.AST, ast.AST] | None = None
        for call, nested in _calls(root, None):
            inner = _replace(context, nested=context.nested or nested)
            self.call(call, statement, scope, inner)
            if _reads_one(call):
                if parents is None:
                    parents = {c: p for p in ast.walk(root) for c in ast.iter_child_nodes(p)}
                self.read(call, statement, scope, inner, _accessor(call, parents))

    def read(
        self, call: ast.Call, statement: ast.stmt, scope: Scope, context: _Context, kind: str
    ) -> None:
        """``self.get_parameter(name)``: a parameter the node needs, on a node declaring
        what the overrides name."""
        name = call.args[0]
        pieces = [_piece(name, scope), Piece(), Piece()]
        found = self.add(call, name, statement, pieces, Piece(), context, name, self.unit.reads)
        found.read = kind

    def call(self, call: ast.Call, statement: ast.stmt, scope: Scope, context: _Context) -> None:
        for keyword in call.keywords:
            if keyword.arg in OPEN_OPTIONS:
                try:
                    on = Evaluator(scope).value(keyword.value)
                except UntranslatableError:
                    on = True
                if on:
                    option = NodeOption(keyword, f"{keyword.arg}=True", keyword.arg)
                    self.unit.options.append(option)
        if not isinstance(call.func, ast.Attribute):
            return
        if call.func.attr == BY_PREFIX:
            self.unit.options.append(NodeOption(call, f"{BY_PREFIX}()"))
        elif call.func.attr in AFTERWARDS:
            self.unit.afterwards.append(NodeOption(call, AFTERWARDS[call.func.attr]))
        elif call.func.attr == DECLARE_ONE:
            self.declare_one(call, statement, scope, context)
        elif call.func.attr == DECLARE_MANY:
            self.declare_many(call, statement, scope, context)

    def reads_of_overrides(self, root: ast.AST, calls: bool = True) -> None:
        """``self._parameter_overrides`` (and, with ``calls``, by-prefix calls) under
        ``root``, outside the calls ``expressions`` visits."""
        for node in ast.walk(root):
            if isinstance(node, ast.Attribute) and node.attr == OVERRIDES:
                self.unit.options.append(NodeOption(node, f"{unparsed(node)}"))
            elif (
                calls
                and isinstance(node, ast.Call)
                and isinstance(node.func, ast.Attribute)
                and node.func.attr == BY_PREFIX
            ):
                self.unit.options.append(NodeOption(node, f"{BY_PREFIX}()"))

    def declare_one(
        self, call: ast.Call, statement: ast.stmt, scope: Scope, context: _Context
    ) -> None:
        args = _arguments(call, ("name", "value", "descriptor", "ignore_override"))
        name_node = args.get("name")
        pieces = [_piece(args.get(key), scope) for key in ("name", "value", "descriptor")]
        found = self.add(
            call,
            name_node if name_node is not None else call,
            statement,
            pieces,
            _piece(args.get("ignore_override"), scope),
            context,
            name_node,
        )
        found.value_node = args.get("value")
        found.item_value = _item_value(found, scope)

    def declare_many(
        self, call: ast.Call, statement: ast.stmt, scope: Scope, context: _Context
    ) -> None:
        args = _arguments(call, ("namespace", "parameters", "ignore_override"))
        namespace = _piece(args.get("namespace"), scope)
        ignore = _piece(args.get("ignore_override"), scope)
        listed = args.get("parameters")
        items: list[tuple[ast.AST, list[Piece], ast.AST | None]] = []
        values: dict[int, ast.expr] = {}  # each item's value, as written
        if isinstance(listed, (ast.List, ast.Tuple)):
            for element in listed.elts:
                if isinstance(element, ast.Tuple):
                    pieces = [_piece(node, scope) for node in element.elts[:3]]
                    first = element.elts[0] if element.elts else None
                    items.append((element, pieces, first))
                    if len(element.elts) > 1:
                        values[id(element)] = element.elts[1]
                else:
                    items.append((element, _value_pieces(element, scope), None))
        elif listed is not None:
            whole = _piece(listed, scope)
            if whole.problem is None and isinstance(whole.value, (list, tuple)):
                for item in whole.value:
                    pieces = [Piece(True, v) for v in item] if isinstance(item, tuple) else []
                    items.append((listed, pieces or [Piece(True, None, _bad(listed))], None))
            else:
                problem = whole.problem or UntranslatableError(listed, unparsed(listed))
                items.append((listed, [Piece(True, None, problem)], None))
        for at, pieces, name_node in items:
            pieces = pieces + [Piece() for _ in range(3 - len(pieces))]
            pieces[0] = _joined(namespace, pieces[0])
            found = self.add(call, at, statement, pieces, ignore, context, name_node)
            found.in_list = True
            found.namespace_node = args.get("namespace")
            found.value_node = values.get(id(at))
            found.item_value = _item_value(found, scope)

    def add(
        self,
        call: ast.Call,
        at: ast.AST,
        statement: ast.stmt,
        pieces: list[Piece],
        ignore: Piece,
        context: _Context,
        name_node: ast.AST | None,
        into: list[Found] | None = None,
    ) -> Found:
        """A declaration (or a read) found, in ``into`` (the unit's declarations)."""
        name, value, descriptor = pieces[:3]
        found = Found(
            call,
            at,
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
        )
        (self.unit.found if into is None else into).append(found)
        return found


def _replace(context: _Context, **changes: Any) -> _Context:
    return _Context(**{**context.__dict__, **changes})


def _when(test: ast.expr, scope: Scope) -> tuple[str, list[Any]] | None:
    """``read == literal``, ``literal == read`` or ``read in (literals)``: the parameter
    read and the values that make the test true; None for any other test."""
    if not isinstance(test, ast.Compare) or len(test.ops) != 1:
        return None
    left, right, op = test.left, test.comparators[0], test.ops[0]
    if isinstance(op, ast.Eq) and parameter_read(left, scope) is None:
        left, right = right, left
    name = parameter_read(left, scope)
    if name is None or not isinstance(op, (ast.Eq, ast.In)):
        return None
    try:
        value = Evaluator(scope).value(right)
    except UntranslatableError:
        return None
    if isinstance(op, ast.Eq):
        return name, [value]
    return (name, list(value)) if isinstance(value, (list, tuple)) and value else None


_READS = ("get_parameter", DECLARE_ONE)
_MAX_READS = 4  # variables assigned from variables assigned from a read


def parameter_read(node: ast.AST, scope: Scope, depth: int = 0) -> str | None:
    """The parameter whose value ``node`` is: ``x.get_parameter('a').value`` (or
    ``.get_parameter_value().string_array_value``, or the value a ``declare_parameter``
    returns), or a variable (``v``, ``self.v``) the function assigns once, from one,
    before this use."""
    call: ast.AST | None = None
    if isinstance(node, ast.Attribute) and node.attr == "value":
        call = node.value
    elif isinstance(node, ast.Attribute) and node.attr.endswith("_value"):
        inner = node.value
        if (
            isinstance(inner, ast.Call)
            and isinstance(inner.func, ast.Attribute)
            and inner.func.attr == "get_parameter_value"
            and not inner.args
        ):
            call = inner.func.value
    if (
        isinstance(call, ast.Call)
        and isinstance(call.func, ast.Attribute)
        and call.func.attr in _READS
        and call.args
    ):
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


def _calls(node: ast.AST, nested: str | None) -> Iterator[tuple[ast.Call, str | None]]:
    """Calls under ``node`` in evaluation order (inner calls first), with the nested
    construct holding them."""
    for child in ast.iter_child_nodes(node):
        if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            continue
        inner = nested
        if isinstance(child, _NESTED) and nested is None:
            inner = "a lambda" if isinstance(child, ast.Lambda) else "a comprehension"
        yield from _calls(child, inner)
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


def _locals(function: ast.AST) -> dict[str, list[ast.stmt]]:
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


def _arguments(call: ast.Call, names: tuple[str, ...]) -> dict[str, ast.expr]:
    args: dict[str, ast.expr] = dict(zip(names, call.args, strict=False))
    for keyword in call.keywords:
        if keyword.arg in names:
            args[keyword.arg] = keyword.value
    return args


def _piece(node: ast.AST | None, scope: Scope) -> Piece:
    if node is None:
        return Piece()
    assert isinstance(node, ast.expr)
    try:
        return Piece(True, Evaluator(scope).value(node))
    except UntranslatableError as exc:
        return Piece(True, None, exc)


def _value_pieces(node: ast.expr, scope: Scope) -> list[Piece]:
    """A declare_parameters item that is not written as a tuple (a variable, a constant)."""
    whole = _piece(node, scope)
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


def _reads_one(call: ast.Call) -> bool:
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


def _accessor(call: ast.Call, parents: dict[ast.AST, ast.AST]) -> str:
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


SAMPLE_ITEM = "item"  # a loop's item, to type a value computed from it


def _item_value(found: Found, scope: Scope) -> Piece | None:
    """A value computed from the loop's item (``sensor + "_link"``), for a sample item; None
    when the value is not computed, or not from the item."""
    node, variable = found.value_node, found.loop_variable
    if node is None or found.value.problem is None or variable is None:
        return None
    if not any(isinstance(n, ast.Name) and n.id == variable for n in ast.walk(node)):
        return None
    return _piece(node, scope.with_loop({variable: SAMPLE_ITEM}))


def _bind(target: ast.expr, item: Any) -> dict[str, Any] | None:
    if isinstance(target, ast.Name):
        return {target.id: item}
    if isinstance(target, (ast.Tuple, ast.List)) and isinstance(item, (list, tuple)):
        if len(target.elts) != len(item):
            return None
        out: dict[str, Any] = {}
        for sub, value in zip(target.elts, item, strict=False):
            bound = _bind(sub, value)
            if bound is None:
                return None
            out.update(bound)
        return out
    return None


def descriptor_of(found: Found) -> DescriptorValue | None:
    value = found.descriptor.value
    return value if isinstance(value, DescriptorValue) else None
