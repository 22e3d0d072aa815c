"""What generated modules import. Imports rclpy only when a class is declared on a node."""

from genparams.runtime.changes import Change, Changes
from genparams.runtime.errors import (
    DetachedSnapshotError,
    ParameterDeclarationError,
    RemoteParameterError,
    RemoteSetError,
)
from genparams.runtime.params import Params
from genparams.runtime.spec import ParamSpec, RuleSpec, SchemaSpec
from genparams.runtime.tree import Group, GroupMap

__all__ = [
    "Change",
    "Changes",
    "DetachedSnapshotError",
    "Group",
    "GroupMap",
    "ParamSpec",
    "ParameterDeclarationError",
    "Params",
    "RemoteParameterError",
    "RemoteSetError",
    "RuleSpec",
    "SchemaSpec",
]
