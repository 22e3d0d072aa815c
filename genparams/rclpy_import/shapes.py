"""Shapes of a node's source the scan recognises: what declares, what lets params files
name parameters, helpers that declare what they are asked, guards against declaring twice,
objects handed the node, base classes reached through ``super()``."""

from __future__ import annotations

import ast

from genparams.rclpy_import.overrides import BY_PREFIX, OVERRIDES
from genparams.rclpy_import.reads import DECLARE_MANY, DECLARE_ONE
from genparams.rclpy_import.resolve import ClassFound
from genparams.rclpy_import.scope import Scope

# Node(...) options and calls that make parameters whose names come from params files.
OPEN_OPTIONS = ("automatically_declare_parameters_from_overrides", "allow_undeclared_parameters")


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


def is_helper(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """A function that declares (or reads) a parameter named by one of its arguments
    (``def get_param(self, name, default)``): it is read where it is called."""
    names = {a.arg for a in [*function.args.args, *function.args.kwonlyargs]} - {"self"}
    if function.name == "__init__":
        return False  # a constructor is read where its object is built
    for node in ast.walk(function):
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr in (DECLARE_ONE, "get_parameter")
        ):
            first = node.args[0] if node.args else None
            first = next((k.value for k in node.keywords if k.arg == "name"), first)
            if first is not None and any(
                isinstance(n, ast.Name) and n.id in names for n in ast.walk(first)
            ):
                return True
    return False


def called(call: ast.Call) -> str | None:
    func = call.func
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name):
        return f"{func.value.id}.{func.attr}"
    return None


def calls_to(name: str, body: list[ast.stmt]) -> bool:
    """Whether ``body`` calls the function ``name`` (``name(...)``)."""
    return any(
        isinstance(n, ast.Call) and isinstance(n.func, ast.Name) and n.func.id == name
        for statement in body
        for n in ast.walk(statement)
    )


def hands_node(call: ast.Call, in_class: bool) -> bool:
    """The node is given to the call: ``Driver(self)``, ``Driver(node=self)`` in a node
    class; a variable (``Updater(node)``) in the module's functions."""
    values = [*call.args, *(k.value for k in call.keywords)]
    return any(isinstance(v, ast.Name) and (v.id == "self" or not in_class) for v in values)


def is_node_class(cls: ast.ClassDef) -> bool:
    """A class deriving from a Node is a node of its own, not an object of this one."""
    return any("Node" in ast.unparse(base) for base in cls.bases)


def defines(cls: ClassFound, name: str) -> bool:
    return any(
        isinstance(s, (ast.FunctionDef, ast.AsyncFunctionDef)) and s.name == name
        for s in cls.definition.body
    )


def super_called(classes: list[ClassFound], name: str) -> bool:
    """Whether one of ``classes`` calls ``super().name(...)``."""
    for cls in classes:
        for node in ast.walk(cls.definition):
            if (
                isinstance(node, ast.Call)
                and isinstance(node.func, ast.Attribute)
                and node.func.attr == name
                and isinstance(node.func.value, ast.Call)
                and isinstance(node.func.value.func, ast.Name)
                and node.func.value.func.id == "super"
            ):
                return True
    return False


def guards_redeclaring(statement: ast.If) -> bool:
    """``if not self.has_parameter(name): <declare>``, or ``if self.has_parameter(name):
    <read> else: <declare>``: it declares once, whatever the test, as a schema does."""
    test = statement.test
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        if statement.orelse:
            return False
        test = test.operand
    elif not statement.orelse or declares(ast.Module(statement.body, [])):
        return False
    return (
        isinstance(test, ast.Call)
        and isinstance(test.func, ast.Attribute)
        and test.func.attr == "has_parameter"
    )


def called_once_under_if(classes: list[ClassFound]) -> set[str]:
    """The methods the classes call on ``self`` exactly once, and under an ``if``
    (``if load_params: self.parameter_ros2()``): read where they are called, under its
    test, rather than as if they always ran."""
    calls: dict[str, list[ast.Call]] = {}
    under_if: set[ast.Call] = set()
    for cls in classes:
        for node in ast.walk(cls.definition):
            if (
                isinstance(node, ast.Call)
                and isinstance(node.func, ast.Attribute)
                and isinstance(node.func.value, ast.Name)
                and node.func.value.id == "self"
            ):
                calls.setdefault(node.func.attr, []).append(node)
            elif isinstance(node, ast.If):
                for branch in [*node.body, *node.orelse]:
                    under_if.update(n for n in ast.walk(branch) if isinstance(n, ast.Call))
    return {name for name, found in calls.items() if len(found) == 1 and found[0] in under_if}


def super_init_call(cls: ClassFound) -> ast.Call | None:
    """The ``super().__init__(...)`` call of the class's constructor, if it has one."""
    for statement in cls.definition.body:
        if isinstance(statement, ast.FunctionDef) and statement.name == "__init__":
            for node in ast.walk(statement):
                if (
                    isinstance(node, ast.Call)
                    and isinstance(node.func, ast.Attribute)
                    and node.func.attr == "__init__"
                    and isinstance(node.func.value, ast.Call)
                    and getattr(node.func.value.func, "id", "") == "super"
                ):
                    return node
    return None


def known_truth(test: ast.expr, scope: Scope) -> bool | None:
    """The truth of ``name`` or ``not name`` where ``name`` is an argument (or a literal
    loop's item) bound to a bool: ``if load_params:`` under ``super().__init__(name,
    load_params=False)``; None when it is not known."""
    negated = isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not)
    name = test.operand if isinstance(test, ast.UnaryOp) and negated else test
    if not isinstance(name, ast.Name) or not isinstance(scope.loop.get(name.id), bool):
        return None
    return scope.loop[name.id] is not negated


# What rclpy's lifecycle node calls on each transition: a declaration there is made when
# the node is configured, as a lifecycle node declares its class.
LIFECYCLE_CALLBACKS = frozenset(
    {"on_configure", "on_activate", "on_deactivate", "on_cleanup", "on_shutdown", "on_error"}
)


def uncalled(method: ast.FunctionDef | ast.AsyncFunctionDef, called: frozenset[str]) -> str | None:
    """``name()`` for a method that nothing read calls (``get_frame_id``, called by
    scripts outside the files read; a callback handed to a timer); None for the
    constructor, one that is called, a decorated one (a property) and rclpy's
    lifecycle callbacks."""
    name = method.name
    if name.startswith("__") or name in LIFECYCLE_CALLBACKS or method.decorator_list:
        return None
    return None if name in called else f"{name}()"
