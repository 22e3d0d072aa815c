"""Schemas bound to one node, from the command line: ``SCHEMA`` or ``SCHEMA@PREFIX``."""

from __future__ import annotations

import argparse
from pathlib import Path

from genparams.commands._common import schema_from
from genparams.errors import CommandError
from genparams.paramsfile.check_params import Bound
from genparams.runtime.core.naming import NAME_RULE, is_ros_token, join_prefix


def bound_spec(text: str) -> tuple[Path, str]:
    """``camera.yaml@front`` -> (camera.yaml, "front"); argparse type, so bad input exits 2."""
    path, _, prefix = text.rpartition("@") if "@" in text else (text, "", "")
    if prefix and not all(is_ros_token(part) for part in prefix.split(".")):
        raise argparse.ArgumentTypeError(
            f"invalid prefix {prefix!r} in {text!r}: dot-separated names of {NAME_RULE}"
        )
    return Path(path), prefix


def add_schema_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--schema",
        dest="also",
        action="append",
        default=[],
        type=bound_spec,
        metavar="SCHEMA[@PREFIX]",
        help="another class declared on the same node, under PREFIX (repeatable)",
    )


def load_bounds(specs: list[tuple[Path, str]]) -> list[Bound]:
    """The schemas; a ``CommandError`` (exit 2) saying what is wrong."""
    bounds = [Bound(schema_from(path), prefix) for path, prefix in specs]
    prefixes = [b.prefix for b in bounds]
    for bound in bounds:
        for other in bounds:
            if other is not bound and _overlap(bound, other):
                raise CommandError(
                    f"genparams: {bound.schema.source_name} and {other.schema.source_name} "
                    f"both declare {_overlap(bound, other)} (prefixes {prefixes})"
                )
    return bounds


def _overlap(one: Bound, other: Bound) -> str:
    """A parameter both classes would declare, or ""."""
    mine = {join_prefix(one.prefix, p.ros_name) for p in one.schema.parameters}
    theirs = {join_prefix(other.prefix, p.ros_name) for p in other.schema.parameters}
    return min(mine & theirs, default="")
