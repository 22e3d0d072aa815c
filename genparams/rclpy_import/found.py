"""The records the scan gives: each declaration (or read) found, each construct that lets
params files name parameters, and the unit that holds them. All frozen: later passes
(convert, patch) read them and build their own records.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from typing import Any

from genparams.rclpy_import.scope import DescriptorValue, UntranslatableError
from genparams.runtime.core.conditions import KeyTest
from genparams.schema.errors import Location


@dataclass(frozen=True)
class SourceFile:
    """A file the scan reads: its name as messages give it, and its lines."""

    name: str
    lines: tuple[str, ...]

    def location(self, node: ast.AST) -> Location:
        line = getattr(node, "lineno", 1)
        offset = getattr(node, "col_offset", 0)
        text = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        column = len(text.encode("utf-8")[:offset].decode("utf-8", errors="replace")) + 1
        return Location(self.name, line, column)


@dataclass(frozen=True)
class Piece:
    """One argument of a declaration: its value, or why it could not be read;
    ``reads`` names the parameters declared before that the value was computed from."""

    given: bool = False
    value: Any = None
    problem: UntranslatableError | None = None
    reads: tuple[str, ...] = ()


@dataclass(frozen=True, eq=False)
class Found:
    call: ast.Call  # the declare_parameter(s) call
    at: ast.AST  # the name argument or the list item
    where: Location  # where messages point: ``at`` in its file
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
    # The condition, when the ``if`` (and ``elif``) tests around the declaration compare one
    # parameter's value with literals (``==``, ``!=``, ``in``, ``not in``, a truth test),
    # the declaration in a body or an ``else``: the parameter and the test it must pass.
    when: tuple[str, KeyTest] | None = None
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
    # Declared outside the node file's own statements: through a helper, a base class or
    # an object the node builds ("the helper self.get_param at node.py:12:9"); the patch
    # leaves it as written.
    via: str | None = None
    # Declared by a method that nothing read calls (a callback, or one called from outside
    # the files read, ``driver.get_frame_id()``): rclpy declares it when that runs.
    late: str | None = None

    @property
    def receiver_is_self(self) -> bool:
        func = self.call.func
        return (
            isinstance(func, ast.Attribute)
            and isinstance(func.value, ast.Name)
            and func.value.id == "self"
        )

    @property
    def patchable(self) -> bool:
        """Whether the patch may rewrite it: on ``self``, in the node's own statements."""
        return self.via is None and self.receiver_is_self


@dataclass(frozen=True, eq=False)
class NodeOption:
    """A construct that lets parameters be named by params files."""

    at: ast.AST
    where: Location
    construct: str
    option: str = ""  # the Node() option (see OPEN_OPTIONS), or "" for a read of overrides


@dataclass(frozen=True)
class Unit:
    name: str  # the class name, or "" for the module's own functions
    node: ast.ClassDef | ast.Module
    docstring: str | None
    found: tuple[Found, ...] = ()
    options: tuple[NodeOption, ...] = ()
    afterwards: tuple[NodeOption, ...] = ()  # see scan.AFTERWARDS
    reads: tuple[Found, ...] = ()  # self.get_parameter(name) calls
    files: tuple[str, ...] = ()  # every other file of the package the scan read
    file: str = ""  # the node file, as given
    skipped: tuple[str, ...] = ()  # files of the package not read, each with the reason


def descriptor_of(found: Found) -> DescriptorValue | None:
    value = found.descriptor.value
    return value if isinstance(value, DescriptorValue) else None
