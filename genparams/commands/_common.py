"""What the commands share: loading one schema, writing one output."""

from __future__ import annotations

import sys
from pathlib import Path

from genparams.api import load_schema
from genparams.errors import CommandError
from genparams.integration.writing import write_all
from genparams.runtime.core.naming import absolute, node_name_problem
from genparams.runtime.core.visible import visible
from genparams.schema.errors import SchemaError
from genparams.schema.model import Schema


def schema_from(path: Path) -> Schema:
    """The schema; a ``CommandError`` (exit 2) listing every problem with it."""
    try:
        return load_schema(path)
    except SchemaError as exc:
        raise CommandError(exc) from None


def report(*lines: object) -> None:
    """Lines of a command's report that are not its output (warnings, notes, a summary) on
    stderr, every character shown: the one place genparams writes to stderr. A problem
    (``genparams.errors.Problem``) is a line ``render_problem`` wrote. Errors are raised as
    ``CommandError`` instead, and ``genparams.cli.main`` reports them here."""
    for line in lines:
        print(visible(str(line)), file=sys.stderr)


def node_arguments(command: str, nodes: list[str], what: str = "node") -> tuple[str, ...]:
    """The node names given on the command line, each made absolute; a ``CommandError``
    (exit 2) naming the first that is not a node name, and why."""
    for node in nodes:
        problem = node_name_problem(node)
        if problem is not None:
            raise CommandError(f"genparams {command}: invalid {what} {node!r}: {problem}")
    return tuple(absolute(node) for node in nodes)


def emit(text: str, output: Path | None) -> None:
    """Write to ``output`` atomically, or to stdout."""
    if output is None:
        sys.stdout.write(text)
    else:
        write_all({output: text})
