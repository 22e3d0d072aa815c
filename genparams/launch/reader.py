"""Read a launch file of any format, and the files it includes, into what it starts."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

from genparams.launch.frontend import follow
from genparams.launch.model import LaunchResult, Unknown
from genparams.launch.packages import Packages
from genparams.launch.python_reader import read_python_launch
from genparams.launch.scope import MAX_INCLUDES, Scope, Value
from genparams.launch.xml_reader import xml_entities
from genparams.launch.yaml_reader import yaml_entities
from genparams.schema.errors import Location

SUFFIXES = (".launch.py", ".launch.xml", ".launch.yaml", ".launch.yml")


def is_launch_file(path: Path) -> bool:
    return path.name.endswith(SUFFIXES) or path.suffix in (".py", ".xml")


def read_launch(
    path: Path, arguments: Mapping[str, str] = {}, packages: Packages | None = None
) -> LaunchResult:
    """The nodes ``path`` starts, given ``name:=value`` launch arguments; raises OSError
    when the top file cannot be read."""
    result = LaunchResult()
    scope = Scope(path, dict(arguments), "/", packages or Packages(), result, include=_include)
    _read(path, path.read_text(encoding="utf-8"), scope)
    result.arguments = {k: str(v) for k, v in scope.arguments.items() if isinstance(v, str)}
    return result


def _read(path: Path, source: str, scope: Scope) -> None:
    scope.result.files.append(str(path))
    name = path.name
    if name.endswith(".py"):
        read_python_launch(source, scope)
    elif name.endswith(".xml"):
        follow(xml_entities(source, scope), scope)
    elif name.endswith((".yaml", ".yml")):
        follow(yaml_entities(source, scope), scope)
    else:
        scope.unknown(f"the launch file {name} (not .py, .xml or .yaml)", scope.at(1, 1))


def _include(path: Path, arguments: dict[str, Value], parent: Scope, where: Location) -> None:
    if parent.depth >= MAX_INCLUDES:
        parent.unknown(f"the include of {path} (includes nested too deep)", where)
        return
    try:
        source = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        parent.unknown(f"the included launch file {path} ({exc.__class__.__name__})", where)
        return
    scope = Scope(
        path, arguments, parent.namespace, parent.packages, parent.result, _include,
        parent.depth + 1,
    )  # fmt: skip
    _read(path, source, scope)


__all__ = ["LaunchResult", "Unknown", "is_launch_file", "read_launch"]
