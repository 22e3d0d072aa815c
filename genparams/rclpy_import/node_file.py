"""One node file -> the unit to import and its schema: parsing, reading its package,
picking the class, naming."""

from __future__ import annotations

import ast
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from genparams.errors import GenparamsError
from genparams.rclpy_import.convert import RclpyImported, convert, node_schema_name
from genparams.rclpy_import.features import AUTOMATIC, what_it_needs
from genparams.rclpy_import.found import SourceFile, Unit
from genparams.rclpy_import.package import Package
from genparams.rclpy_import.resolve import Resolver
from genparams.rclpy_import.scan import units


class NodeFileError(GenparamsError):
    """The file cannot be imported at all (message: FILE:LINE:COL: what)."""


@dataclass(frozen=True)
class ImportedNode:
    source: str  # the file's text
    tree: ast.Module
    unit: Unit
    imported: RclpyImported

    @property
    def unit_name(self) -> str:
        return self.unit.name


def parse(source: str, file: str) -> ast.Module:
    try:
        return ast.parse(source, filename=file)
    except SyntaxError as exc:
        line, column = exc.lineno or 1, exc.offset or 1
        raise NodeFileError(f"{file}:{line}:{column}: cannot parse as Python: {exc.msg}") from None
    except (ValueError, RecursionError, MemoryError) as exc:  # NUL bytes, nesting
        why = str(exc) or "nested too deeply"
        raise NodeFileError(f"{file}:1:1: cannot parse as Python: {why}") from None


def scanned(source: str, file: str, class_name: str | None = None) -> tuple[ast.Module, Unit]:
    """The node's syntax tree and the unit chosen (read with its package)."""
    tree = parse(source, file)
    path = Path(file)
    resolver = Resolver(Package.of(path))
    try:
        view = resolver.node_view(path, tree, SourceFile(file, tuple(source.splitlines())))
        found = units(view, resolver)
    except RecursionError:
        raise NodeFileError(f"{file}:1:1: nested too deeply to read") from None
    return tree, _chosen(found, file, class_name)


def import_node(
    source: str,
    file: str,
    class_name: str | None = None,
    overrides: Mapping[str, Any] | None = None,
    given_by: str = "",
) -> ImportedNode:
    """Scan, resolve and convert the node in ``file`` (its text ``source``): the unit
    chosen and its schema. ``overrides`` are the node's parameters from its params files
    (``given_by`` names them)."""
    tree, unit = scanned(source, file, class_name)
    automatic = any(o.option == AUTOMATIC for o in unit.options)
    if not unit.found and not (automatic and (unit.reads or overrides)):
        first = unit.options[0] if unit.options else None
        where = f"{first.where.line}:{first.where.column}" if first else "1:1"
        why = f": {what_it_needs(first)}" if first else ""
        raise NodeFileError(f"{file}:{where}: no parameter declaration found{why}")
    name = node_schema_name(unit.name, Path(file).stem)
    return ImportedNode(source, tree, unit, convert(unit, name, overrides, given_by))


def node_name(unit: Unit) -> str | None:
    """The name the node gives itself: ``super().__init__("camera")``, ``Node("camera")``
    or ``node_name="camera"``; None when it is not a literal."""
    for node in ast.walk(unit.node):
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        called = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
        super_init = (
            called == "__init__"
            and isinstance(func, ast.Attribute)
            and isinstance(func.value, ast.Call)
            and getattr(func.value.func, "id", "") == "super"
        )
        if not (super_init or called == "Node"):
            continue
        written = [k.value for k in node.keywords if k.arg == "node_name"] + node.args[:1]
        for value in written:
            if isinstance(value, ast.Constant) and isinstance(value.value, str):
                return value.value
    return None


def _chosen(found: list[Unit], file: str, class_name: str | None) -> Unit:
    classes = [u.name for u in found if u.name]
    if class_name is not None:
        chosen = [u for u in found if u.name == class_name]
        if not chosen:
            which = f"classes that do: {', '.join(classes)}" if classes else "none does"
            raise NodeFileError(f"{file}:1:1: no class {class_name} declaring parameters ({which})")
        return chosen[0]
    if not found:
        raise NodeFileError(
            f"{file}:1:1: no parameter declaration (declare_parameter or declare_parameters) found"
        )
    if len(found) > 1:
        names = ", ".join(u.name or "the module's functions" for u in found)
        raise NodeFileError(
            f"{file}:1:1: several parts declare parameters ({names}): pick a class with --class"
        )
    return found[0]
