"""Find a node's parameter declarations in its syntax tree, and in its package.

A *unit* is one class whose methods declare parameters, or the module's own functions
when no class does it (``node.declare_parameter`` in ``main()``). The class's base
classes found in the package are read with it; so are helpers it calls that declare on
it (``self.get_param(name, default)``, ``declare_all(self)``) and objects it builds and
hands itself to (``NmeaDriver(self)``) whose methods declare. Each ``declare_parameter``
call, and each item of a ``declare_parameters`` list, becomes one ``Found``
(declarations.py).
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field, replace
from typing import Any

from genparams.rclpy_import.arguments import bound_arguments, class_scope
from genparams.rclpy_import.declarations import Context, declare_many, declare_one, read
from genparams.rclpy_import.found import Found, NodeOption, Unit
from genparams.rclpy_import.loops import (
    literal_bindings,
    reads_own_parameter,
    runtime_loop_context,
)
from genparams.rclpy_import.overrides import (
    BY_PREFIX,
    OVERRIDES,
)
from genparams.rclpy_import.reads import (
    DECLARE_MANY,
    DECLARE_ONE,
    accessor,
    branch_condition,
    calls_in,
    condition_on,
    is_main_guard,
    locals_of,
    reads_one,
)
from genparams.rclpy_import.resolve import ClassFound, ModuleView, Resolver, lookup_class
from genparams.rclpy_import.scope import Scope, UntranslatableError, unparsed
from genparams.rclpy_import.shapes import (
    OPEN_OPTIONS,
    called,
    called_once_under_if,
    calls_to,
    declares,
    defines,
    guards_redeclaring,
    hands_node,
    is_helper,
    is_node_class,
    known_truth,
    super_called,
    super_init_call,
    uncalled,
)
from genparams.rclpy_import.values import Evaluator
from genparams.runtime.core.conditions import negated

# Calls that change declared parameters after the fact: the schema cannot follow them.
AFTERWARDS = {
    "set_descriptor": "set_descriptor() changes a descriptor after its declaration",
    "undeclare_parameter": "undeclare_parameter() removes a parameter after its declaration",
}
_MAX_FOLLOWED = 6  # helpers and objects followed inside one another


def units(view: ModuleView, resolver: Resolver) -> list[Unit]:
    """Every class that declares parameters (itself, through its bases, helpers or the
    objects it builds), then the module's own functions if they do."""
    followed: set[str] = set()  # classes and functions read as part of another unit
    out: list[tuple[Unit, str]] = []
    for found in [c for name, c in view.classes.items() if c.module is view and "." not in name]:
        scanner = _Scanner(resolver, followed)
        unit = scanner.scan_class(found)
        if unit.found or unit.options:
            out.append((unit, found.definition.name))
    module = view.tree
    own = [
        s
        for s in module.body
        if not isinstance(s, ast.ClassDef)
        and not (isinstance(s, ast.FunctionDef) and (s.name in followed or is_helper(s)))
    ]
    kept = [u for u, name in out if name not in followed]
    if any(declares(s) for s in own):
        scanner = _Scanner(resolver, followed)
        kept.append(scanner.scan_module(view, own))
    return kept


@dataclass
class _Collected:
    found: list[Found] = field(default_factory=list)
    options: list[NodeOption] = field(default_factory=list)
    afterwards: list[NodeOption] = field(default_factory=list)
    reads: list[Found] = field(default_factory=list)
    defaults: dict[str, Any] = field(default_factory=dict)  # values declared so far


class _Scanner:
    def __init__(self, resolver: Resolver, followed: set[str]) -> None:
        self.resolver = resolver
        self.followed = followed
        self.collected = _Collected()
        self.view: ModuleView | None = None
        self.stack: list[ast.AST] = []  # helpers and classes being followed
        self.in_class = False  # the module's own functions are read as they are, not followed
        self.read_where_called: set[ast.AST] = set()  # methods read at their calls

    def unit(self, name: str, node: ast.ClassDef | ast.Module) -> Unit:
        c = self.collected
        package = self.resolver.package
        files = tuple(package.shown(p) for p in package.read)
        file = self.view.source.name if self.view is not None else ""
        return Unit(
            name, node, ast.get_docstring(node), tuple(c.found), tuple(c.options),
            tuple(c.afterwards), tuple(c.reads), files, file, tuple(package.skipped),
        )  # fmt: skip

    def scan_module(self, view: ModuleView, own: list[ast.stmt]) -> Unit:
        self.view = view
        scope = view.scope()
        context = Context(view.source)
        for statement in own:
            if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)):
                self.function(statement, scope, context)
        rest = [s for s in own if not isinstance(s, (ast.FunctionDef, ast.AsyncFunctionDef))]
        self.walk(rest, scope, context)
        return self.unit("", view.tree)

    def scan_class(self, cls: ClassFound) -> Unit:
        self.view = cls.module
        self.in_class = True
        self.object_methods(cls, None)
        return self.unit(cls.definition.name, cls.definition)

    def object_methods(
        self,
        cls: ClassFound,
        via: str | None,
        site: Any = None,
        built: ast.Call | None = None,
        caller: Scope | None = None,
    ) -> None:
        """Scan the methods of ``cls`` and of its base classes in the package (farthest
        first; a method overridden is read where ``super()`` reaches it)."""
        chain = self.resolver.chain(cls)
        guarded = called_once_under_if(chain)
        self.read_where_called.update(
            s for c in chain for s in c.definition.body
            if isinstance(s, ast.FunctionDef) and s.name in guarded
        )  # fmt: skip
        for depth, current in reversed(list(enumerate(chain))):
            scope = class_scope(chain[depth:])
            nearer = chain[:depth]
            for statement in current.definition.body:
                if not isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    continue
                if is_helper(statement) or statement in self.read_where_called:
                    continue  # read where it is called
                if any(defines(c, statement.name) for c in nearer) and not super_called(
                    nearer, statement.name
                ):
                    continue
                inner_via = via
                if depth > 0 and via is None:
                    inner_via = f"the base class {current.definition.name}"
                context = Context(
                    current.module.source,
                    via=inner_via,
                    call_site=site,
                    late=uncalled(statement, self.resolver.methods_called()),
                )
                bound: dict[str, Any] = {}
                if statement.name == "__init__" and built is not None and caller is not None:
                    bound = bound_arguments(
                        statement, built, caller, scope, self.collected.defaults
                    )
                elif statement.name == "__init__" and depth > 0:  # super().__init__(...)
                    reached = super_init_call(chain[depth - 1])
                    caller_scope = class_scope(chain[depth - 1 :])
                    if reached is not None:
                        bound = bound_arguments(
                            statement, reached, caller_scope, scope, self.collected.defaults
                        )
                self.function(statement, scope, context, bound)

    def function(
        self,
        function: ast.FunctionDef | ast.AsyncFunctionDef,
        scope: Scope,
        context: Context,
        bound: dict[str, Any] | None = None,
    ) -> None:
        nested = {s.name: s for s in function.body if isinstance(s, ast.FunctionDef)}
        inner = replace(
            scope,
            loop=bound or {},
            local=locals_of(function),
            functions={**scope.functions, **nested},
        )
        self.walk(function.body, inner, context)

    def walk(self, body: list[ast.stmt], scope: Scope, context: Context) -> None:
        for index, statement in enumerate(body):
            if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)) and calls_to(
                statement.name, body[index + 1 :]
            ):
                # a nested function called after its definition: read at each call
                closures = {**scope.closures, statement.name: statement}
                scope = replace(scope, closures=closures)
                continue
            self.statement(statement, scope, context)

    def statement(self, statement: ast.stmt, scope: Scope, context: Context) -> None:
        if isinstance(statement, (ast.For, ast.AsyncFor)):
            self.loop(statement, scope, context)
        elif isinstance(statement, ast.While):
            self.expressions(statement.test, statement, scope, context)
            inner = context.changed(
                runtime_loop=context.runtime_loop or "a while loop",
                loop_parameter=None,
                loop_prefix=None,
            )
            self.walk(statement.body, scope, inner)
            self.walk(statement.orelse, scope, context)
        elif isinstance(statement, ast.If) and is_main_guard(statement):
            # the script's entry point: it runs whenever the file is run as the node
            main_scope = replace(scope, local={**scope.local, **locals_of(statement)})
            self.walk(statement.body, main_scope, context)
            self.walk(statement.orelse, scope, context)
        elif isinstance(statement, ast.If) and guards_redeclaring(statement):
            self.expressions(statement.test, statement, scope, context)
            self.walk(statement.body, scope, context)  # declares once, whatever the test
            self.walk(statement.orelse, scope, context)
        elif isinstance(statement, ast.If) and known_truth(statement.test, scope) is not None:
            taken = known_truth(statement.test, scope)  # an argument given a bool
            self.walk(statement.body if taken else statement.orelse, scope, context)
        elif isinstance(statement, ast.If):
            tested = condition_on(statement.test, scope)
            inner = context.changed(
                condition=context.condition or f"if {unparsed(statement.test)}",
                when=branch_condition(context.condition, context.when, tested),
            )
            otherwise = tested and (tested[0], negated(tested[1]))
            otherwise = branch_condition(context.condition, context.when, otherwise)
            self.expressions(statement.test, statement, scope, context)
            self.walk(statement.body, scope, inner)
            self.walk(statement.orelse, scope, inner.changed(when=otherwise))
        elif isinstance(statement, (ast.Try, ast.TryStar)):
            self.walk(statement.body, scope, context)
            for handler in statement.handlers:
                inner = context.changed(
                    condition=context.condition or "an except handler", when=None
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
                inner = context.changed(condition=context.condition or "a match case", when=None)
                self.walk(case.body, scope, inner)
        elif isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            inner = context.changed(nested=f"the nested definition {statement.name}")
            for child in statement.body:
                self.statement(child, scope, inner)
        else:
            self.expressions(statement, statement, scope, context)

    def loop(self, loop: ast.For | ast.AsyncFor, scope: Scope, context: Context) -> None:
        bindings = literal_bindings(loop, scope, context)
        if isinstance(loop, ast.For) and bindings is not None:
            inner = context.changed(literal_loop=context.literal_loop or loop)
            for binding in bindings:
                if binding is not None:
                    self.walk(loop.body, scope.with_loop(binding), inner)
        else:
            self.reads_of_overrides(loop.iter, context)
            self.walk(loop.body, scope, runtime_loop_context(loop, scope, context))
        self.walk(loop.orelse, scope, context)

    def expressions(
        self, root: ast.AST, statement: ast.stmt, scope: Scope, context: Context
    ) -> None:
        self.reads_of_overrides(root, context, calls=False)
        parents: dict[ast.AST, ast.AST] | None = None
        for call, nested in calls_in(root, None):
            inner = context.changed(nested=context.nested or nested)
            self.call(call, statement, scope, inner)
            if reads_one(call) and not reads_own_parameter(call, inner):
                if parents is None:
                    parents = {c: p for p in ast.walk(root) for c in ast.iter_child_nodes(p)}
                kind = accessor(call, parents)
                self.collected.reads.append(read(call, statement, scope, inner, kind))

    def option(self, at: ast.AST, context: Context, construct: str, option: str = "") -> None:
        where = context.call_site or context.source.location(at)
        self.collected.options.append(NodeOption(at, where, construct, option))

    def call(self, call: ast.Call, statement: ast.stmt, scope: Scope, context: Context) -> None:
        for keyword in call.keywords:
            if keyword.arg in OPEN_OPTIONS:
                try:
                    on = Evaluator(scope).value(keyword.value)
                except UntranslatableError:
                    on = True
                if on:
                    self.option(keyword, context, f"{keyword.arg}=True", keyword.arg)
        if not isinstance(call.func, ast.Attribute):
            self.follow(call, scope, context)
            return
        attribute = call.func.attr
        if attribute == BY_PREFIX:
            self.option(call, context, f"{BY_PREFIX}()")
        elif attribute in AFTERWARDS:
            where = context.call_site or context.source.location(call)
            self.collected.afterwards.append(NodeOption(call, where, AFTERWARDS[attribute]))
        elif attribute in (DECLARE_ONE, DECLARE_MANY):
            known = replace(scope, parameters=dict(self.collected.defaults))
            if attribute == DECLARE_ONE:
                self.add(declare_one(call, statement, known, context))
            else:
                for found in declare_many(call, statement, known, context):
                    self.add(found)
        else:
            self.follow(call, scope, context)

    def add(self, found: Found) -> None:
        self.collected.found.append(found)
        name, value = found.name, found.value
        if name.problem is None and isinstance(name.value, str) and value.problem is None:
            self.collected.defaults.setdefault(name.value, value.value)

    def follow(self, call: ast.Call, scope: Scope, context: Context) -> None:
        """A helper that declares what it is asked (``self.get_param('rate', 10.0)``,
        ``declare_all(self)``), or an object built with the node that declares on it
        (``NmeaDriver(self)``): read as part of the node, where it is called."""
        if len(self.stack) >= _MAX_FOLLOWED or self.view is None:
            return
        name = called(call)
        if name is None:
            return
        site = context.call_site or context.source.location(call)
        closure = scope.closures.get(name)
        if closure is not None:
            self.closure(closure, call, scope, context.changed(
                via=context.via or f"the nested function {name}()", call_site=site,
            ))  # fmt: skip
            return
        helper = scope.functions.get(name)
        module_function = self.view.functions.get(name)
        if helper is not None and (
            helper in self.stack or not (declares(helper) or is_helper(helper))
        ):
            return
        inlined = helper in self.read_where_called or (module_function and self.in_class)
        if helper is not None and (is_helper(helper) or inlined):
            source = module_function.module.source if module_function else context.source
            helper_scope = module_function.module.scope() if module_function else scope
            self.inline(helper, call, scope, helper_scope, context.changed(
                source=source, via=context.via or f"the helper {name}()", call_site=site,
            ))  # fmt: skip
            if module_function is not None:
                self.followed.add(name)
            return
        cls = lookup_class(self.view, call.func)
        if cls is None or cls.definition in self.stack or not declares(cls.definition):
            return
        if self.in_class and (not hands_node(call, True) or is_node_class(cls.definition)):
            return  # a node class builds an object, and hands it itself
        if not self.in_class and not (hands_node(call, False) or is_node_class(cls.definition)):
            return  # the module's functions build a node, or hand one to an object
        self.followed.add(cls.definition.name)
        self.stack.append(cls.definition)
        try:
            via = context.via or f"the object {unparsed(call, 40)}"
            self.object_methods(cls, via, site, call, scope)
        finally:
            self.stack.pop()

    def inline(
        self,
        helper: ast.FunctionDef,
        call: ast.Call,
        caller: Scope,
        scope: Scope,
        context: Context,
    ) -> None:
        """Read ``helper``'s body with its arguments bound to the call's values."""
        reads: list[str] = []
        bound = bound_arguments(helper, call, caller, scope, self.collected.defaults, reads)
        if reads:
            context = context.changed(reads=tuple(dict.fromkeys([*context.reads, *reads])))
        inner = replace(scope, loop={}, local=locals_of(helper))
        inner = inner.with_loop(bound)
        self.stack.append(helper)
        try:
            self.walk(helper.body, inner, context.changed(condition=context.condition))
        finally:
            self.stack.pop()

    def closure(
        self,
        function: ast.FunctionDef | ast.AsyncFunctionDef,
        call: ast.Call,
        scope: Scope,
        context: Context,
    ) -> None:
        """Read a nested function's body at one of its calls: its arguments bound to the
        call's values, the enclosing function's variables (and loop) seen as they are."""
        if function in self.stack:
            return
        reads: list[str] = []
        bound = bound_arguments(function, call, scope, scope, self.collected.defaults, reads)
        if reads:
            context = context.changed(reads=tuple(dict.fromkeys([*context.reads, *reads])))
        own = set(bound) | {a.arg for a in function.args.args}
        loop = {k: v for k, v in scope.loop.items() if k not in own}
        local = {k: v for k, v in scope.local.items() if k not in own}
        inner = replace(scope, loop=loop, local={**local, **locals_of(function)})
        inner = inner.with_loop(bound)
        self.stack.append(function)
        try:
            self.walk(function.body, inner, context)
        finally:
            self.stack.pop()

    def reads_of_overrides(self, root: ast.AST, context: Context, calls: bool = True) -> None:
        """``self._parameter_overrides`` (and, with ``calls``, by-prefix calls) under
        ``root``, outside the calls ``expressions`` visits."""
        for node in ast.walk(root):
            if isinstance(node, ast.Attribute) and node.attr == OVERRIDES:
                self.option(node, context, f"{unparsed(node)}")
            elif (
                calls
                and isinstance(node, ast.Call)
                and isinstance(node.func, ast.Attribute)
                and node.func.attr == BY_PREFIX
            ):
                self.option(node, context, f"{BY_PREFIX}()")
