"""What a launch file starts, as records: nodes with their parameters, and what only the
launch itself can know ("set at launch time"), each with its place."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from genparams.schema.errors import Location

LAUNCH_TIME = "set at launch time"


@dataclass(frozen=True)
class Unknown:
    """A value only the launch can know (an OpaqueFunction, an unset environment variable,
    an argument without a value): never guessed."""

    what: str
    location: Location

    def __str__(self) -> str:
        return f"{self.location}: {self.what}: {LAUNCH_TIME}"


@dataclass(frozen=True)
class InlineParameters:
    """``parameters=[{...}]`` or ``<param name= value=/>``: dotted names, values as launch
    hands them to the node, each with its place."""

    values: tuple[tuple[str, Any, Location], ...]


@dataclass(frozen=True)
class ParamsFileRef:
    path: str
    location: Location


ParameterSource = InlineParameters | ParamsFileRef


@dataclass(frozen=True)
class LaunchNode:
    kind: str  # "node", "lifecycle_node", "composable_node", "container"
    package: str
    executable: str  # the plugin of a composable node
    name: str  # "" when the launch file does not name the node (its executable does)
    namespace: str  # absolute
    parameters: tuple[ParameterSource, ...]
    location: Location
    container: str = ""  # the full name of a composable node's container

    @property
    def full_name(self) -> str:
        if not self.name:
            return ""
        return f"{self.namespace.rstrip('/')}/{self.name}"


@dataclass
class LaunchResult:
    nodes: list[LaunchNode] = field(default_factory=list)
    unknowns: list[Unknown] = field(default_factory=list)
    files: list[str] = field(default_factory=list)  # every launch file read, includes too
    arguments: dict[str, str] = field(default_factory=dict)  # of the top file, final values
