"""Generate parameter modules as a step of a setuptools build (colcon, pip, ``setup.py``).

In setup.py::

    from genparams.setuptools import build_py, develop

    setup(..., cmdclass={"build_py": build_py, "develop": develop})

The modules to generate are listed in ``[tool.genparams]`` of the pyproject.toml
next to setup.py (see genparams.integration.project_config); each ``output`` is the path the
module has in the source tree and must lie inside a package that setup() builds.

Where the generated file goes depends on what Python will import:

- a regular build (``colcon build``, ``--merge-install``, ``pip install .``, a wheel)
  writes it into the build folder only; the source tree is never touched;
- an editable build (``colcon build --symlink-install`` and ``setup.py develop``, or
  ``pip install -e``) imports the package straight from the source folder, so the
  module is generated there, in place, like ``build_ext --inplace`` does for
  extensions. Such a file is a build product: ignore it in git, or commit it and
  keep it fresh with ``genparams generate --check``.

Nothing reads ``sys.argv``: setuptools decides which commands run, and each
command knows its own mode and folders.
"""

from __future__ import annotations

import importlib.util
import os
from collections.abc import Iterator
from pathlib import Path

from setuptools.command.build_py import build_py as _build_py
from setuptools.command.develop import develop as _develop
from setuptools.errors import SetupError

from genparams.api import generate
from genparams.integration.project_config import (
    PYPROJECT,
    ModuleTarget,
    ProjectConfigError,
    load_project_config,
)
from genparams.integration.writing import write_all
from genparams.schema.errors import SchemaError

__all__ = ["build_py", "develop"]


# Lower-case class names: setuptools names commands by the classes that replace them.
class build_py(_build_py):  # noqa: N801
    """``build_py`` that also generates the modules of ``[tool.genparams]``."""

    def run(self) -> None:
        if self.editable_mode:
            _generate_in_place(_project_root(self))
            super().run()
            return
        super().run()
        written = []
        for target, built in self._generated():
            _report(f"{target.schema_text} -> {built}")
            _write_if_changed(built, _render(target))
            written.append(str(built))
        self.byte_compile(written)

    def get_outputs(self, include_bytecode: bool = True) -> list[str]:
        outputs = super().get_outputs(include_bytecode)
        if self.editable_mode:
            return sorted({*outputs, *self.get_output_mapping()})
        for _, built in self._generated():
            outputs.append(str(built))
            if include_bytecode:
                outputs.extend(self._bytecode_names(str(built)))
        return sorted(set(outputs))

    def get_output_mapping(self) -> dict[str, str]:
        mapping = super().get_output_mapping()
        root = _project_root(self)
        for target, built in self._generated():
            mapping[str(built)] = os.path.relpath(target.output, root)
        return dict(sorted(mapping.items()))

    def get_source_files(self) -> list[str]:
        root = _project_root(self)
        schemas = [os.path.relpath(t.schema, root) for t in _targets(root)]
        sources: list[str] = super().get_source_files()  # type: ignore[no-untyped-call]
        return [*sources, *schemas]

    def _generated(self) -> Iterator[tuple[ModuleTarget, Path]]:
        """Each configured module with the path it gets under ``build_lib``."""
        package_dirs = {
            Path(self.get_package_dir(package)).resolve(): package
            for package in self.packages or ()
        }
        for target in _targets(_project_root(self)):
            package = package_dirs.get(target.output.parent.resolve())
            if package is None:
                packages = sorted(package_dirs.values())
                raise SetupError(
                    f"genparams: output {target.output_text!r} of {target.schema_text!r} is not "
                    f"inside a package this setup() builds (packages: {packages})"
                )
            yield target, Path(self.build_lib, *package.split("."), target.output.name)

    def _bytecode_names(self, path: str) -> list[str]:
        names = []
        if self.compile:
            names.append(importlib.util.cache_from_source(path, optimization=""))
        if self.optimize > 0:
            names.append(importlib.util.cache_from_source(path, optimization=self.optimize))
        return names


class develop(_develop):  # noqa: N801
    """``develop`` (used by ``colcon build --symlink-install``) that generates in place first."""

    def run(self) -> None:
        if not getattr(self, "uninstall", False):
            _generate_in_place(_project_root(self))
        super().run()


def _project_root(command: _build_py | _develop) -> Path:
    """The folder of the real setup.py: colcon's symlink install runs it through a symlink."""
    script = command.distribution.script_name or "setup.py"
    return Path(script).resolve().parent


def _targets(root: Path) -> tuple[ModuleTarget, ...]:
    try:
        return load_project_config(root / PYPROJECT).modules
    except ProjectConfigError as exc:
        raise SetupError(f"genparams: {exc}") from None


def _generate_in_place(root: Path) -> None:
    for target in _targets(root):
        _report(f"{target.schema_text} -> {target.output} (in place: editable build)")
        _write_if_changed(target.output, _render(target))


def _report(message: str) -> None:
    # Plain print: the log API of setuptools' distutils changed levels between releases.
    print(f"genparams: {message}", flush=True)


def _render(target: ModuleTarget) -> str:
    try:
        return generate(target.schema)
    except SchemaError as exc:
        raise SetupError(f"genparams: invalid schema\n{exc}") from None


def _write_if_changed(path: Path, text: str) -> None:
    """Rewrite only on a change, so an unchanged module keeps its mtime and bytecode."""
    try:
        if path.read_text(encoding="utf-8") == text:
            return
    except FileNotFoundError:
        pass
    write_all({path: text})
