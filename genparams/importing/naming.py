"""The name of an imported schema, from what the source calls the parameters' owner."""

from __future__ import annotations

import re

from genparams.runtime.core.naming import SCHEMA_NAME

_WORD_START = re.compile(r"(?<=[a-z0-9])([A-Z])|(?<=[A-Z])([A-Z])(?=[a-z])")
_NOT_NAME = re.compile(r"[^a-z0-9_]+")


def schema_name(owner: str, prefix: str) -> str:
    """``owner`` (a GPL namespace key, a class, a node's base name) as a schema name:
    snake_case (``JointTrajectoryController`` -> ``joint_trajectory_controller``,
    ``HTTPServer`` -> ``http_server``), every run of other characters one ``_``. One not
    starting with a letter takes ``prefix``: ``2d_lidar`` -> ``node_2d_lidar``."""
    name = _WORD_START.sub(r"_\1\2", owner).lower()
    name = _NOT_NAME.sub("_", name).strip("_")
    return name if SCHEMA_NAME.fullmatch(name) else f"{prefix}_{name}".rstrip("_")
