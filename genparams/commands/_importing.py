"""The steps every import command ends with: refuse, check, report, write, exit code.

An import whose source its own tool refuses, that imports nothing of the parameters its
source holds, or whose schema genparams refuses, writes nothing and exits 2. Otherwise the
report (notes and warnings at their places, then a summary) goes to stderr, the schema to
its file (with any file beside it, all or none) or to stdout, and the command exits 1 when
a warning says something was lost, else 0.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path

from genparams.commands._common import report
from genparams.errors import CommandError
from genparams.importing import LEFT_OUT, Imported, in_order, validated, write_outputs
from genparams.schema.errors import SchemaError
from genparams.schema.input_file import read_input_file

WRITTEN = 0  # everything imported exactly
WRITTEN_WITH_WARNINGS = 1


def read_source(path: str | os.PathLike[str], what: str) -> str:
    """The text of the file to import; a ``CommandError`` (exit 2) naming it otherwise."""
    try:
        return read_input_file(path, what)
    except SchemaError as exc:
        raise CommandError(exc) from None


def finish(
    command: str,
    source: str,
    imported: Imported,
    text: str,
    target: Path | None,
    beside: Mapping[Path, str] | None = None,
    also_report: Sequence[str] = (),
) -> int:
    """Write ``text``, the schema of ``imported`` from ``source``, to ``target`` (stdout
    when None) and the files ``beside`` it, reporting ``also_report`` after the findings;
    returns the exit code. The steps one by one, for a command that writes more (a patch):
    ``refuse_unwritable``, ``report_import``, ``write_schema``, ``exit_code``."""
    refuse_unwritable(command, source, imported, text)
    report_import(imported, also_report)
    write_schema(text, target, beside)
    return exit_code(imported)


def report_import(imported: Imported, also_report: Sequence[str] = ()) -> None:
    """Notes and warnings at their places, then ``also_report``, then the summary."""
    report(*imported.findings(), *also_report, imported.summary())


def write_schema(text: str, target: Path | None, beside: Mapping[Path, str] | None = None) -> None:
    """The schema to ``target`` with the files ``beside`` it, all or none; or to stdout."""
    if target is None:
        sys.stdout.write(text)
    else:
        write_outputs({target: text, **(beside or {})})


def exit_code(imported: Imported) -> int:
    """1 when a warning says something was lost, else 0."""
    return WRITTEN_WITH_WARNINGS if imported.warnings else WRITTEN


def refuse_unwritable(command: str, source: str, imported: Imported, text: str) -> None:
    """Raises ``CommandError`` (exit 2) when nothing may be written, naming every reason."""
    if imported.errors:
        raise CommandError(*map(str, in_order([*imported.errors, *imported.warnings])))
    if imported.parameters and imported.count(LEFT_OUT) == imported.parameters:
        raise CommandError(
            *map(str, imported.findings()),
            imported.summary(),
            f"genparams {command}: {source}: no parameter could be imported: nothing written",
        )
    try:
        validated(text, source)
    except SchemaError as exc:
        raise CommandError(
            *map(str, in_order(imported.warnings)),
            exc,
            f"genparams {command}: {source}: the imported schema is not valid",
        ) from None
