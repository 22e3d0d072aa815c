"""The ``[tool.genparams]`` table of a pyproject.toml: which schema generates which module.

```toml
[[tool.genparams.modules]]
schema = "config/camera_driver.yaml"
output = "camera_node/camera_driver_params.py"
```

Paths are relative to the folder holding pyproject.toml. The command line
(``genparams generate`` with no SCHEMA) and the setuptools build step
(``genparams.setuptools``) both read this table, so one list of modules serves
every kind of build.
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from genparams.errors import GenparamsError
from genparams.schema.errors import SchemaError
from genparams.schema.input_file import read_input_file

PYPROJECT = "pyproject.toml"
_MODULE_KEYS = ("schema", "output")


class ProjectConfigError(GenparamsError):
    """A missing or malformed ``[tool.genparams]`` table; the message names file and key."""


@dataclass(frozen=True)
class ModuleTarget:
    """One generated module: ``schema`` and ``output`` as written, resolved against ``root``."""

    root: Path
    schema_text: str
    output_text: str

    @property
    def schema(self) -> Path:
        return self.root / self.schema_text

    @property
    def output(self) -> Path:
        return self.root / self.output_text


@dataclass(frozen=True)
class ProjectConfig:
    file: Path
    modules: tuple[ModuleTarget, ...]

    @property
    def root(self) -> Path:
        return self.file.parent


def find_pyproject(start: Path) -> Path | None:
    """The nearest pyproject.toml in ``start`` or one of its parents."""
    start = start.resolve()
    for folder in (start, *start.parents):
        candidate = folder / PYPROJECT
        if candidate.is_file():
            return candidate
    return None


def load_project_config(pyproject: Path) -> ProjectConfig:
    """Read ``[tool.genparams]`` from ``pyproject``. Raises ProjectConfigError on any problem."""
    try:
        document = tomllib.loads(read_input_file(pyproject, "pyproject.toml"))
    except SchemaError as exc:
        raise ProjectConfigError(str(exc)) from None
    except tomllib.TOMLDecodeError as exc:
        raise ProjectConfigError(f"{pyproject}: cannot read: {exc}") from None
    table = document.get("tool", {}).get("genparams")
    if table is None:
        raise ProjectConfigError(f"{pyproject}: no [tool.genparams] table")
    return ProjectConfig(pyproject, _modules(pyproject, table))


def _modules(pyproject: Path, table: Any) -> tuple[ModuleTarget, ...]:
    where = f"{pyproject}: tool.genparams"
    if not isinstance(table, Mapping):
        raise ProjectConfigError(f"{where}: must be a table")
    unknown = sorted(set(table) - {"modules"})
    if unknown:
        raise ProjectConfigError(f"{where}: unknown key {unknown[0]!r} (expected 'modules')")
    entries = table.get("modules")
    if not isinstance(entries, list) or not entries:
        raise ProjectConfigError(
            f"{where}.modules: must be a non-empty array of tables "
            '([[tool.genparams.modules]] with schema = "..." and output = "...")'
        )
    problems: list[str] = []
    modules: list[ModuleTarget] = []
    written_by: dict[Path, int] = {}
    for index, entry in enumerate(entries):
        key = f"{where}.modules[{index}]"
        target = _module(pyproject.parent, key, entry, problems)
        if target is None:
            continue
        output = target.output.resolve()
        if output in written_by:
            problems.append(
                f"{key}.output: {target.output_text!r} is also the output of "
                f"modules[{written_by[output]}]"
            )
            continue
        written_by[output] = index
        modules.append(target)
    if problems:
        raise ProjectConfigError("\n".join(problems))
    return tuple(modules)


def _module(root: Path, key: str, entry: Any, problems: list[str]) -> ModuleTarget | None:
    """One ``[[tool.genparams.modules]]`` entry; its problems go to ``problems``."""
    if not isinstance(entry, Mapping):
        problems.append(f"{key}: must be a table with 'schema' and 'output'")
        return None
    found = len(problems)
    problems.extend(f"{key}: unknown key {name!r}" for name in entry if name not in _MODULE_KEYS)
    values: dict[str, str] = {}
    for name in _MODULE_KEYS:
        value = entry.get(name)
        if not isinstance(value, str) or not value.strip():
            problems.append(f"{key}.{name}: must be a path string, relative to {PYPROJECT}")
        elif Path(value).is_absolute():
            problems.append(f"{key}.{name}: must be relative to {PYPROJECT}, got {value!r}")
        else:
            values[name] = value
    if "output" in values and not values["output"].endswith(".py"):
        problems.append(f"{key}.output: must name a .py file, got {values['output']!r}")
    if len(problems) > found:
        return None
    return ModuleTarget(root, values["schema"], values["output"])
