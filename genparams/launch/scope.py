"""What reading a launch file carries along: its arguments, the namespace pushed so far,
where packages are, and what was found; and the rules all three formats share."""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from genparams.launch.model import LaunchNode, LaunchResult, Unknown
from genparams.launch.packages import Packages
from genparams.schema.errors import Location

MAX_INCLUDES = 32  # includes within includes: a launch file that includes itself stops here

Value = Any  # str, bool, int, float, list, dict, or Unknown


@dataclass(frozen=True)
class Scope:
    file: Path
    arguments: dict[str, Value]  # launch configurations: name -> text or Unknown
    namespace: str  # absolute; "/" at the top
    packages: Packages
    result: LaunchResult
    include: Callable[[Path, dict[str, Value], Scope, Location], None]
    depth: int = 0
    # SetParameter / <set_parameter>: given to every node after it in its group, first.
    set_parameters: tuple[tuple[str, Any, Location], ...] = ()

    def at(self, line: int, column: int) -> Location:
        return Location(str(self.file), line, column)

    def unknown(self, what: str, location: Location) -> Unknown:
        unknown = Unknown(what, location)
        if unknown not in self.result.unknowns:
            self.result.unknowns.append(unknown)
        return unknown

    def pushed(self, namespace: Value, location: Location) -> Scope:
        if isinstance(namespace, Unknown):
            return replace(self, namespace="/" + "<launch-time>")
        return replace(self, namespace=join_namespace(self.namespace, str(namespace)))

    def with_parameter(self, name: str, value: Any, location: Location) -> Scope:
        return replace(self, set_parameters=(*self.set_parameters, (name, value, location)))

    def add(self, node: LaunchNode) -> None:
        self.result.nodes.append(node)


def join_namespace(outer: str, inner: str) -> str:
    """A namespace inside ``outer``: an absolute one replaces it, as rcl resolves names."""
    inner = inner.strip()
    if inner.startswith("/"):
        joined = inner
    elif not inner:
        joined = outer
    else:
        joined = outer.rstrip("/") + "/" + inner
    return "/" + "/".join(part for part in joined.split("/") if part)


def text(value: Value) -> str | Unknown:
    """A substitution's text: a list of parts is their concatenation (launch's rule)."""
    if isinstance(value, Unknown):
        return value
    if isinstance(value, list | tuple):
        parts = [text(item) for item in value]
        for part in parts:
            if isinstance(part, Unknown):
                return part
        return "".join(str(p) for p in parts)
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def condition_holds(value: Value, unless: bool) -> bool | Unknown:
    """``IfCondition``/``if=`` (or Unless): launch takes true/false/1/0, any case."""
    written = text(value)
    if isinstance(written, Unknown):
        return written
    lowered = written.strip().lower()
    if lowered in ("true", "1"):
        return not unless
    if lowered in ("false", "0"):
        return unless
    return Unknown(f"condition {written!r} (not true or false)", Location("-", 1, 1))


def environment(name: str, default: Value | None, scope: Scope, location: Location) -> Value:
    if name in os.environ:
        return os.environ[name]
    if default is not None:
        return default
    return scope.unknown(f"environment variable {name} (unset here)", location)


def package_share(package: Value, scope: Scope, location: Location) -> Value:
    name = text(package)
    if isinstance(name, Unknown):
        return name
    found = scope.packages.share(name)
    if found is None:
        return scope.unknown(
            f"package {name!r} (not in the ament index: give --package-path {name}=DIR)",
            location,
        )
    return str(found)


def path_join(parts: list[Value]) -> Value:
    texts = [text(p) for p in parts]
    for part in texts:
        if isinstance(part, Unknown):
            return part
    return os.path.join(*[str(t) for t in texts]) if texts else ""
