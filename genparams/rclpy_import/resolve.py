"""What the names of a module of the node's package stand for: its constants, and those
it imports from other modules of the package, its classes and functions, and the
namespaces (an imported module, a class) whose attributes it reads.

Nothing is run: each module is a syntax tree (package.py reads it), and a name bound in
another module keeps that module's scope (an ``Elsewhere``), so its expression is read
where it was written.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from dataclasses import dataclass, field, replace
from pathlib import Path

from genparams.rclpy_import.found import SourceFile
from genparams.rclpy_import.package import Package
from genparams.rclpy_import.scope import Binding, Elsewhere, Scope, constants, dotted_name

_MAX_DEPTH = 4  # modules imported through modules
_MAX_BASES = 8  # classes in a node's chain of base classes


@dataclass(frozen=True, eq=False)
class ClassFound:
    definition: ast.ClassDef
    module: ModuleView


@dataclass(frozen=True, eq=False)
class FunctionFound:
    definition: ast.FunctionDef
    module: ModuleView


@dataclass(frozen=True, eq=False)
class ModuleView:
    """One module: the names it binds, its own or imported from the package."""

    path: Path
    tree: ast.Module
    source: SourceFile
    constants: dict[str, Binding] = field(default_factory=dict)
    namespaces: dict[str, dict[str, Binding]] = field(default_factory=dict)
    classes: dict[str, ClassFound] = field(default_factory=dict)
    functions: dict[str, FunctionFound] = field(default_factory=dict)
    outside: dict[str, str] = field(default_factory=dict)  # names from modules not read

    def scope(self) -> Scope:
        return Scope(
            module_constants=self.constants,
            namespaces=self.namespaces,
            functions={n: f.definition for n, f in self.functions.items()},
            outside=self.outside,
        )

    def class_constants(self, cls: ast.ClassDef) -> dict[str, Binding]:
        """A class's attributes (``RATE = 10.0`` in its body), read in this module."""
        own = constants(cls.body)
        scope = self.scope()  # an attribute may use those assigned before it in the class
        scope = replace(scope, module_constants={**scope.module_constants, **own})
        return {n: Elsewhere(e, scope) for n, e in own.items()}


class Resolver:
    def __init__(self, package: Package) -> None:
        self.package = package
        self._views: dict[Path, ModuleView | None] = {}
        self._called: tuple[int, frozenset[str]] | None = None  # (modules read, names)

    def methods_called(self) -> frozenset[str]:
        """The names called as ``x.name(...)`` in the modules read so far."""
        if self._called is None or self._called[0] != len(self._views):
            trees = [v.tree for v in self._views.values() if v is not None]
            names = {
                node.func.attr
                for tree in trees
                for node in ast.walk(tree)
                if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            }
            self._called = (len(self._views), frozenset(names))
        return self._called[1]

    def node_view(self, path: Path, tree: ast.Module, source: SourceFile) -> ModuleView:
        view = self._build(path.resolve(), tree, source, 0)
        self._views.setdefault(path.resolve(), view)
        return view

    def chain(self, cls: ClassFound) -> list[ClassFound]:
        """The class and its base classes found in the package, nearest first."""
        out = [cls]
        index = 0
        while index < len(out) and len(out) < _MAX_BASES:
            current = out[index]
            for base in current.definition.bases:
                found = lookup_class(current.module, base)
                if found is not None and all(found.definition is not c.definition for c in out):
                    out.append(found)
            index += 1
        return out

    def _view(self, path: Path, depth: int) -> ModuleView | None:
        path = path.resolve()
        if path in self._views:
            return self._views[path]
        self._views[path] = None  # an import cycle reads the module once
        if depth > _MAX_DEPTH:
            return None
        module = self.package.module(path)
        if module is None:
            return None
        view = self._build(path, module.tree, module.source, depth)
        self._views[path] = view
        return view

    def _build(self, path: Path, tree: ast.Module, source: SourceFile, depth: int) -> ModuleView:
        view = ModuleView(path, tree, source, dict(constants(tree.body)))
        statements = list(module_level(tree.body))
        for statement in statements:
            if isinstance(statement, ast.ClassDef):
                view.classes[statement.name] = ClassFound(statement, view)
            elif isinstance(statement, ast.FunctionDef):
                view.functions[statement.name] = FunctionFound(statement, view)
        for statement in statements:
            if isinstance(statement, ast.ImportFrom):
                self._import_from(view, statement, depth)
            elif isinstance(statement, ast.Import):
                self._import(view, statement, depth)
        for name, found in view.classes.items():
            if found.module is view:
                view.namespaces.setdefault(name, view.class_constants(found.definition))
        return view

    def _import_from(self, view: ModuleView, statement: ast.ImportFrom, depth: int) -> None:
        target = self.package.resolve(view.path, statement.module, statement.level)
        other = self._view(target, depth + 1) if target is not None else None
        origin = "." * statement.level + (statement.module or "")
        for alias in statement.names:
            local = alias.asname or alias.name
            if alias.name == "*" and other is not None:
                _take_all(view, other)
                continue
            if other is not None and _take(view, local, other, alias.name):
                continue
            sub = self.package.submodule(target, alias.name) if target is not None else None
            inner = self._view(sub, depth + 1) if sub is not None else None
            if inner is not None:
                _namespace(view, local, inner)
            elif alias.name != "*":
                view.outside[local] = origin

    def _import(self, view: ModuleView, statement: ast.Import, depth: int) -> None:
        for alias in statement.names:
            target = self.package.resolve(view.path, alias.name, 0)
            other = self._view(target, depth + 1) if target is not None else None
            if other is not None:
                _namespace(view, alias.asname or alias.name, other)
            else:
                local = alias.asname or alias.name.partition(".")[0]
                view.outside[local] = alias.name if alias.asname else local


def module_level(body: list[ast.stmt]) -> Iterator[ast.stmt]:
    """A module's statements, with those of its top-level ``if``/``else`` and ``try``
    blocks (``if ROS_VERSION == 2: class CompatibleNode(Node): ...``, ``try: from x
    import y``) read as if each ran, in source order: a later definition of a name
    stands."""
    for statement in body:
        if isinstance(statement, ast.If):
            yield from module_level([*statement.body, *statement.orelse])
        elif isinstance(statement, ast.Try):
            handlers = [s for h in statement.handlers for s in h.body]
            yield from module_level([*statement.body, *handlers, *statement.orelse,
                                     *statement.finalbody])  # fmt: skip
        else:
            yield statement


def _take(view: ModuleView, local: str, other: ModuleView, name: str) -> bool:
    """Bind ``local`` in ``view`` to what ``name`` is in ``other``; False if nothing."""
    if name in other.constants:
        binding = other.constants[name]
        if not isinstance(binding, Elsewhere):
            binding = Elsewhere(binding, other.scope())
        view.constants[local] = binding
        return True
    if name in other.classes:
        found = other.classes[name]
        view.classes[local] = found
        view.namespaces[local] = found.module.class_constants(found.definition)
        return True
    if name in other.functions:
        view.functions[local] = other.functions[name]
        return True
    return False


def _take_all(view: ModuleView, other: ModuleView) -> None:
    """``from .module import *``: every name ``other`` binds, unless ``view`` binds it."""
    for name in [*other.constants, *other.classes, *other.functions]:
        if not name.startswith("_") and "." not in name:
            known = name in view.constants or name in view.classes or name in view.functions
            if not known:
                _take(view, name, other, name)


def _namespace(view: ModuleView, local: str, other: ModuleView) -> None:
    scope = other.scope()
    view.namespaces[local] = {
        n: b if isinstance(b, Elsewhere) else Elsewhere(b, scope)
        for n, b in other.constants.items()
    }
    for name, found in other.classes.items():
        view.namespaces[f"{local}.{name}"] = found.module.class_constants(found.definition)
        view.classes[f"{local}.{name}"] = found


def lookup_class(view: ModuleView, node: ast.AST) -> ClassFound | None:
    """The class of the package ``node`` (``Base``, ``mod.Base``) names in ``view``."""
    name = dotted_name(node)
    return view.classes.get(name) if name is not None else None
