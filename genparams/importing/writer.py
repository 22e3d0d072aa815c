"""An imported schema's text, checked before anything is written, then written whole.

The text is the schema's YAML under comment lines saying where it came from. It must be a
schema genparams accepts, or nothing is written; the schema and any file written beside it
(the custom validators' stubs of a GPL import) reach the disk together, each replaced
atomically, after every one of them was written out in full.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

from genparams.api import load_schema
from genparams.importing.record import Imported
from genparams.integration.writing import write_all
from genparams.outputs.schema_yaml import schema_yaml


def schema_text(imported: Imported, header: Sequence[str]) -> str:
    """The schema as YAML, each line of ``header`` a comment above it."""
    comments = "".join(f"# {line}\n" if line else "#\n" for line in header)
    return comments + schema_yaml(dict(imported.data))


def unwritten_label(source: str) -> str:
    """How errors name the schema text imported from ``source``: its lines are lines of a
    text that was not written."""
    return f"<schema imported from {source}, not written>"


def validated(text: str, source: str) -> None:
    """Raises ``SchemaError`` when genparams refuses the schema ``text``."""
    load_schema(unwritten_label(source), text)


def write_outputs(outputs: Mapping[Path, str]) -> None:
    """Write every file of one import, or none: all are written out before any replaces
    the file at its path."""
    write_all(outputs)
