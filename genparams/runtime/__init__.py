"""What generated modules import. Imports rclpy only when a class is declared on a node."""

from genparams.runtime.core.changes import Change, Changes
from genparams.runtime.core.conditions import NoneOf
from genparams.runtime.core.errors import (
    DetachedSnapshotError,
    ParameterDeclarationError,
    RemoteParameterError,
    RemoteSetError,
)
from genparams.runtime.core.param_spec import ParamOptions, ParamSpec
from genparams.runtime.core.spec import RuleSpec, SchemaSpec
from genparams.runtime.core.tree import Group, GroupMap
from genparams.runtime.core.types import RosValue
from genparams.runtime.params import Params

# What a generated module may rely on: the names below and the fields of the specs.
# Raise it on any change a module generated before could not run with; every
# generated module checks it at import and asks to be regenerated on a mismatch.
RUNTIME_API = 2

__all__ = [
    "RUNTIME_API",
    "Change",
    "Changes",
    "DetachedSnapshotError",
    "Group",
    "GroupMap",
    "NoneOf",
    "ParamOptions",
    "ParamSpec",
    "ParameterDeclarationError",
    "Params",
    "RemoteParameterError",
    "RemoteSetError",
    "RosValue",
    "RuleSpec",
    "SchemaSpec",
]
