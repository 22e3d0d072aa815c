"""The node's own package, read as files: where it starts, and which file an import names.

The package's root is the nearest folder above the node file holding ``package.xml``,
``setup.py``, ``setup.cfg`` or ``pyproject.toml``; without one, the folder above the
Python package the file is in (its folders holding ``__init__.py``). Relative imports
(``from .driver import Driver``) and the package's own absolute ones (``from
my_pkg.config import RATE``) are followed to files under that root, and so are imports
of a ROS package beside it (``package.xml`` in both: another package of the same
workspace or repository); anything else (rclpy, numpy) is not. Files are parsed, never
run, and at most ``MAX_FILES`` of them are read.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from pathlib import Path

from genparams.rclpy_import.found import SourceFile

MAX_FILES = 32  # files of the package read besides the node file
MAX_BYTES = 1_000_000  # a larger file is not read
_ROS_MARKER = "package.xml"
_MARKERS = (_ROS_MARKER, "setup.py", "setup.cfg", "pyproject.toml")
_MAX_UP = 6  # folders above the node file searched for the root
_MAX_SIBLINGS = 64  # folders beside the root looked at for other packages


@dataclass(frozen=True)
class ModuleFile:
    path: Path
    tree: ast.Module
    source: SourceFile


@dataclass
class Package:
    """The files of a node's package, read on demand and kept; ``read`` in reading order."""

    node_file: Path
    root: Path | None
    read: list[Path] = field(default_factory=list)
    skipped: list[str] = field(default_factory=list)  # files not read, with the reason
    _modules: dict[Path, ModuleFile | None] = field(default_factory=dict)
    _beside: list[Path] | None = None  # the packages beside the root, once looked up

    @classmethod
    def of(cls, node_file: Path) -> Package:
        here = node_file.resolve().parent
        for folder in [here, *list(here.parents)[:_MAX_UP]]:
            if any((folder / marker).is_file() for marker in _MARKERS):
                return cls(node_file.resolve(), folder)
        top = here  # else the Python package the file is in: above its last __init__.py
        while (top / "__init__.py").is_file() and top.parent != top:
            top = top.parent
        return cls(node_file.resolve(), top if top != here else None)

    def module(self, path: Path) -> ModuleFile | None:
        """The parsed file, or None (outside the package, too many files, unreadable)."""
        path = path.resolve()
        if path in self._modules:
            return self._modules[path]
        self._modules[path] = None
        if path == self.node_file or not self._reachable(path):
            return None
        if len(self.read) >= MAX_FILES:
            self.skipped.append(f"{self.shown(path)}: more than {MAX_FILES} files read")
            return None
        try:
            if path.stat().st_size > MAX_BYTES:
                self.skipped.append(f"{self.shown(path)}: larger than {MAX_BYTES} bytes")
                return None
            text = path.read_text(encoding="utf-8")
            tree = ast.parse(text, filename=str(path))
        except (OSError, UnicodeDecodeError, SyntaxError, ValueError, RecursionError) as exc:
            self.skipped.append(f"{self.shown(path)}: cannot be read ({type(exc).__name__})")
            return None
        self.read.append(path)
        found = ModuleFile(path, tree, SourceFile(_named(path), tuple(text.splitlines())))
        self._modules[path] = found
        return found

    def resolve(self, importer: Path, module: str | None, level: int) -> Path | None:
        """The file ``from <level dots><module> import ...`` names, from ``importer``; None
        when it is not a file of the package."""
        if self.root is None:
            return None
        parts = module.split(".") if module else []
        if level > 0:
            base = importer.resolve().parent
            for _ in range(level - 1):
                base = base.parent
            return _file(base, parts)
        if not parts:
            return None
        bases = [self.root, self.root / "src", *self._ancestors(importer), *self._siblings()]
        for base in bases:
            found = _file(base, parts)
            if found is not None:
                return found
        return None

    def submodule(self, package_file: Path, name: str) -> Path | None:
        """``from . import name`` where ``name`` is a module of the package folder."""
        if package_file.name != "__init__.py":
            return None
        return _file(package_file.parent, [name])

    def shown(self, path: Path) -> str:
        """A file read, as a note names it: from the package's root."""
        if self.root is not None and path.is_relative_to(self.root):
            return str(path.relative_to(self.root))
        return str(path)

    def _siblings(self) -> list[Path]:
        """The other ROS packages beside the root's (``package.xml`` in each: a workspace
        or repository of packages), for an absolute import of one of them
        (``from diagnostic_updater import Updater``)."""
        if self._beside is not None:
            return self._beside
        self._beside = []
        if self.root is None or not (self.root / _ROS_MARKER).is_file():
            return self._beside
        try:
            folders = sorted(self.root.parent.iterdir())[:_MAX_SIBLINGS]
        except OSError:
            return self._beside
        for folder in folders:
            if folder != self.root and (folder / _ROS_MARKER).is_file():
                self._beside += [folder, folder / "src"]
        return self._beside

    def _ancestors(self, importer: Path) -> list[Path]:
        out = []
        for folder in importer.resolve().parents:
            if self.root is None or not self._inside(folder):
                break
            out.append(folder)
        return out

    def _reachable(self, path: Path) -> bool:
        """In the package, or in a package beside it."""
        if self.root is None:
            return False
        return path.resolve().is_relative_to(self.root.parent) and any(
            path.resolve().is_relative_to(base) for base in [self.root, *self._siblings()]
        )

    def _inside(self, path: Path) -> bool:
        return self.root is not None and path.resolve().is_relative_to(self.root)


def _named(path: Path) -> str:
    """A file as messages name it: from the working folder when it is below it."""
    return str(path.relative_to(Path.cwd())) if path.is_relative_to(Path.cwd()) else str(path)


def _file(base: Path, parts: list[str]) -> Path | None:
    folder = base.joinpath(*parts)
    if (folder / "__init__.py").is_file():
        return folder / "__init__.py"
    if parts and folder.with_suffix(".py").is_file():
        return folder.with_suffix(".py")
    return None
