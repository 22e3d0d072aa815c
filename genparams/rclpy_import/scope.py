"""Where the names of a node's source resolve, and the kinds of values read from it.

A ``Scope`` is what the static evaluator (values.py) may look names up in: the loop
variables bound, the function's own assignments, the class's and the module's constants,
namespaces (an imported module, a class of the package) and helper functions. A name bound
in another module of the package is an ``Elsewhere``: its expression and the scope it is
read in there.
"""

from __future__ import annotations

import ast
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any

from genparams.errors import GenparamsError


class UntranslatableError(GenparamsError):
    """A construct the import cannot turn into a value; ``what`` names it for a warning."""

    def __init__(self, node: ast.AST, what: str) -> None:
        super().__init__(what)
        self.node = node
        self.what = what


class NotReadError(UntranslatableError):
    """A name imported from a module outside the files read (another package, or a module
    of the node's package when its file is read alone): its value is there, not here."""

    def __init__(self, node: ast.AST, name: str, origin: str) -> None:
        super().__init__(node, f"{name!r}, imported from {origin}, a module not read")
        self.origin = origin


def run_time_problem(problem: UntranslatableError, what: str) -> str:
    """The words of a warning about a ``what`` (value, name, descriptor) that could not be
    read: one computed at run time, or one defined in a module not read."""
    if isinstance(problem, NotReadError):
        return f"{what} defined outside the files read ({problem.what})"
    return f"{what} computed at run time ({problem.what})"


@dataclass(frozen=True)
class TypeMarker:
    """``Parameter.Type.DOUBLE``: a type given instead of a value."""

    schema_type: str


@dataclass(frozen=True)
class RangeValue:
    integer: bool
    from_value: float
    to_value: float
    step: float


@dataclass
class DescriptorValue:
    """A ParameterDescriptor(...) as the source builds it: fields read, and fields that
    could not be read with the reason (later ``descriptor.x = ...`` lines change it)."""

    fields: dict[str, Any] = field(default_factory=dict)
    failed: dict[str, UntranslatableError] = field(default_factory=dict)


class SharePath(str):
    """A path in a package's share directory, found at run time
    (``os.path.join(get_package_share_directory('pkg'), 'config', 'x.yaml')``): the text
    ``$(find-pkg-share pkg)/config/x.yaml``, as a launch file would write it."""

    __slots__ = ()


@dataclass(frozen=True)
class Elsewhere:
    """A name bound in another module of the package: its expression, read in ``scope``."""

    expression: ast.expr
    scope: Scope


Binding = ast.expr | Elsewhere


@dataclass(frozen=True)
class Scope:
    """Where names resolve: loop variables, the function's own variables, the class's
    constants, the module's constants and namespaces."""

    loop: Mapping[str, Any] = field(default_factory=dict)
    local: Mapping[str, list[ast.stmt]] = field(default_factory=dict)  # assignments
    class_name: str | None = None
    class_constants: Mapping[str, Binding] = field(default_factory=dict)
    module_constants: Mapping[str, Binding] = field(default_factory=dict)
    # ``ns.NAME`` where ``ns`` is an imported module or a class of the package
    # (``from .config import Limits``; ``from . import constants as c``).
    namespaces: Mapping[str, Mapping[str, Binding]] = field(default_factory=dict)
    # Helpers that build a value (``def ranged(lo, hi): return ParameterDescriptor(...)``):
    # the module's functions, the class's methods (as "self.name") and nested functions.
    functions: Mapping[str, ast.FunctionDef] = field(default_factory=dict)
    # Functions defined inside the function being read, called after their definition
    # (``def sub(part): self.declare_parameter(f"{name}.{part}", 0.0)`` in a loop): read
    # at each call, seeing the enclosing function's variables.
    closures: Mapping[str, ast.FunctionDef | ast.AsyncFunctionDef] = field(default_factory=dict)
    # Parameters declared before, with their values: a value read from one of them
    # (``[0.0] * len(self.get_parameter('joints').value)``) is computed from its default.
    parameters: Mapping[str, Any] = field(default_factory=dict)
    # Names imported from modules the import does not read (``from ntrip_client.nmea_parser
    # import NMEA_DEFAULT_MAX_LENGTH`` with the file read alone): where each comes from.
    outside: Mapping[str, str] = field(default_factory=dict)

    def with_loop(self, bindings: Mapping[str, Any]) -> Scope:
        return replace(self, loop={**self.loop, **bindings})


def unparsed(node: ast.AST, limit: int = 60) -> str:
    text = ast.unparse(node)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def dotted_name(node: ast.AST) -> str | None:
    """``a.b.c`` for a chain of attributes on a name, else None."""
    parts: list[str] = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name):
        parts.append(node.id)
        return ".".join(reversed(parts))
    return None


def assigned_once_before(node: ast.AST, scope: Scope) -> ast.Assign | None:
    """The one assignment of the variable ``node`` (``v`` or ``self.v``) in the function,
    when it ends before this use."""
    key = dotted_name(node)
    if key is None or key.count(".") > 1 or ("." in key and not key.startswith("self.")):
        return None
    assigned = scope.local.get(key, [])
    if len(assigned) != 1:
        return None
    statement = assigned[0]
    end = (statement.end_lineno or statement.lineno, statement.end_col_offset or 0)
    if end > (getattr(node, "lineno", 0), getattr(node, "col_offset", 0)):
        return None
    if not isinstance(statement, ast.Assign) or len(statement.targets) != 1:
        return None
    return statement


def before(statement: ast.stmt, use: ast.AST) -> bool:
    """Whether ``statement`` ends before ``use`` starts (``x = f(x)`` does not precede its
    own ``x``)."""
    end = (
        getattr(statement, "end_lineno", None) or statement.lineno,
        getattr(statement, "end_col_offset", None) or statement.col_offset,
    )
    return end <= (getattr(use, "lineno", 0), getattr(use, "col_offset", 0))


def last_before(statements: list[ast.stmt], use: ast.AST) -> ast.stmt | None:
    earlier = [s for s in statements if before(s, use)]
    return earlier[-1] if earlier else None


def constants(body: list[ast.stmt]) -> dict[str, ast.expr]:
    """Names assigned exactly once in ``body`` (``NAME = expr``), with the expression."""
    assigned: dict[str, list[ast.expr]] = {}
    for statement in body:
        for name, value in _assignments(statement):
            assigned.setdefault(name, []).append(value)
    return {name: values[0] for name, values in assigned.items() if len(values) == 1}


def _assignments(statement: ast.stmt) -> list[tuple[str, ast.expr]]:
    if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
        target = statement.targets[0]
        if isinstance(target, ast.Name):
            return [(target.id, statement.value)]
    elif isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name):
        if statement.value is not None:
            return [(statement.target.id, statement.value)]
    return []


_READ_CALLS = ("get_parameter", "declare_parameter")


def read_call(node: ast.AST, scope: Scope) -> ast.Call | None:
    """The ``get_parameter`` or ``declare_parameter`` call whose parameter's value ``node``
    is: ``x.get_parameter('a').value``, ``.get_parameter_value().double_value`` of one, or
    ``held.value`` where ``held`` (``v`` or ``self.v``) was last given one before."""
    call: ast.AST | None = None
    if isinstance(node, ast.Attribute) and node.attr == "value":
        call = node.value
        held = dotted_name(call)
        assigned = last_before(scope.local.get(held, []), node) if held else None
        if isinstance(assigned, (ast.Assign, ast.AnnAssign)):
            call = assigned.value
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
        and call.func.attr in _READ_CALLS
        and call.args
    ):
        return call
    return None
