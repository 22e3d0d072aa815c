"""The real generate_parameter_library corpus: its schemas, params files and node sections.

The files are read from the corpus's gpl folder (tests/corpus.py): a test module that
uses them first calls ``corpus.folder("gpl")``, which skips it where the corpus is absent.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from tests import corpus

CORPUS = corpus.location() / "gpl"
PARAMS_KEY = "ros__parameters"


def schemas() -> list[Path]:
    return sorted(CORPUS.glob("**/schema/*.yaml"))


@dataclass(frozen=True)
class Section:
    """One node section of a params file, to be loaded on a node of that name."""

    schema: Path
    params_file: Path
    node: str  # the node name the section is written for ("/**/x" -> "x")

    @property
    def id(self) -> str:
        return f"{self.params_file.relative_to(CORPUS)}:{self.node}"


def _node_sections(data: Any, prefix: str = "") -> Iterator[tuple[str, Any]]:
    if not isinstance(data, dict):
        return
    for key, value in data.items():
        if isinstance(value, dict) and PARAMS_KEY in value:
            yield prefix + str(key), value[PARAMS_KEY]
        elif isinstance(value, dict):
            yield from _node_sections(value, f"{prefix}{key}/")


def _schema_for(node: str, candidates: list[Path]) -> Path:
    """The package's schema a section configures: the one whose name the node name shares most."""
    stem = node.removeprefix("test_")

    def shared(path: Path) -> int:
        name = path.stem
        return next((i for i, (a, b) in enumerate(zip(stem, name, strict=False)) if a != b), 0)

    return max(candidates, key=shared)


def sections() -> list[Section]:
    """Every named node section of every params file of a package that has a schema."""
    found = []
    for params_file in sorted(CORPUS.glob("**/params/*.yaml")):
        package = params_file.parent.parent
        candidates = sorted((package / "schema").glob("*.yaml"))
        if not candidates:
            continue  # a package without a schema of its own (test nodes, demos' launch files)
        data = yaml.safe_load(params_file.read_text(encoding="utf-8"))
        for written, parameters in _node_sections(data):
            node = written.rsplit("/", 1)[-1]
            if node in ("**", "*"):
                continue  # settings for every node: loaded with each named section
            schema = _schema_for(node, candidates)
            if _configures(node, parameters or {}, schema, package):
                found.append(Section(schema, params_file, node))
    return found


def _configures(node: str, parameters: dict[str, Any], schema: Path, package: Path) -> bool:
    """Whether a section is for a node of this schema, not for another node of the system.

    Params files of a controller manager hold the manager's section and sections of
    the controllers it loads; a controller's ``type`` names its plugin package.
    """
    if node == "controller_manager" or package.name == "controller_manager":
        return node == "controller_manager" and schema.stem.startswith("controller_manager")
    plugin = parameters.get("type")
    if isinstance(plugin, str):
        return schema.stem.startswith(plugin.split("/")[0])
    return True


def flatten(tree: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    """A ros__parameters tree as dotted names -> values (dotted keys kept as written)."""
    out: dict[str, Any] = {}
    for key, value in tree.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(flatten(value, name + "."))
        else:
            out[name] = value
    return out


def values_for(section: Section) -> dict[str, Any]:
    """The values the file sets for the section's node, wildcard sections first (as rcl)."""
    data = yaml.safe_load(section.params_file.read_text(encoding="utf-8"))
    values: dict[str, Any] = {}

    def walk(tree: Any, prefix: str) -> None:
        if not isinstance(tree, dict):
            return
        for key, value in tree.items():
            if not isinstance(value, dict):
                continue
            if PARAMS_KEY in value:
                name = f"{prefix}{key}".rsplit("/", 1)[-1]
                if name in ("**", "*", section.node):
                    values.update(flatten(value[PARAMS_KEY] or {}))
            else:
                walk(value, f"{prefix}{key}/")

    walk(data, "")
    return values


def same(a: Any, b: Any) -> bool:
    """Equal as ROS values: NaN equals NaN, lists equal tuples, ints equal floats of the file."""
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    if isinstance(a, bytes) or isinstance(b, bytes):
        return bytes(a) == bytes(b)
    return bool(a == b)


def gpl_declared(gpl_file: Path, keys: Any) -> dict[str, dict[str, Any]]:
    """The parameters GPL declares for a file: dotted name -> its GPL leaf.

    ``__map_X`` expands over the items of the parameter ``X`` found from the
    innermost namespace outward, read with ``keys(dotted_name)``; ``type: none``
    declares nothing.
    """
    data = yaml.safe_load(gpl_file.read_text(encoding="utf-8"))
    ((_, tree),) = data.items()
    out: dict[str, dict[str, Any]] = {}

    def walk(node: dict[str, Any], prefix: list[str], scopes: list[tuple[list[str], Any]]) -> None:
        for key, value in node.items():
            if key.startswith("__map_"):
                wanted = key[len("__map_") :]
                key_name = wanted
                for scope_prefix, scope in reversed(scopes):
                    if isinstance(scope.get(wanted), dict) and "type" in scope[wanted]:
                        key_name = ".".join([*scope_prefix, wanted])
                        break
                for item in keys(key_name) or ():
                    walk(value, [*prefix, item], [*scopes, ([*prefix, item], value)])
            elif isinstance(value, dict) and "type" in value:
                if value["type"] != "none":
                    out[".".join([*prefix, key])] = value
            elif isinstance(value, dict):
                walk(value, [*prefix, key], [*scopes, ([*prefix, key], value)])

    walk(tree, [], [([], tree)])
    return out
