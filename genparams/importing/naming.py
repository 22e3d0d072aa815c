"""Names of imported schemas: the schema's own, and which parameter names it can hold together."""

from __future__ import annotations

import re
from collections.abc import Iterable

from genparams.runtime.core.naming import SCHEMA_NAME, attribute_name

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


def attribute_clash(name: str, kept: Iterable[str]) -> str | None:
    """Why the dotted ``name`` cannot join the ``kept`` names of a schema: where the two
    part, their tokens give one Python attribute (``speed-max`` and ``speed_max`` are
    both ``speed_max``), which a schema refuses. None when it can."""
    parts = name.split(".")
    for other in kept:
        for depth, (mine, theirs) in enumerate(zip(parts, other.split("."), strict=False)):
            if mine == theirs:
                continue
            shared = attribute_name(mine, top_level=depth == 0)
            if shared == attribute_name(theirs, top_level=depth == 0):
                of = f" (of {other!r})" if other != theirs else ""
                return (
                    f"{mine!r} and {theirs!r}{of} of one namespace would share the Python "
                    f"attribute {shared!r}"
                )
            break
    return None
