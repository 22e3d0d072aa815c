"""What the commands share: loading one schema, writing one output."""

from __future__ import annotations

import sys
from pathlib import Path

from genparams.api import load_schema
from genparams.integration.writing import write_all
from genparams.runtime.visible import visible
from genparams.schema.errors import SchemaError
from genparams.schema.model import Schema


def schema_or_none(path: Path) -> Schema | None:
    """The schema, or None after printing every problem with it (the caller exits 2)."""
    try:
        return load_schema(path)
    except SchemaError as exc:
        print(exc, file=sys.stderr)
        return None


def complain(message: str) -> None:
    """Print an error on stderr; text from the user in it shows every character (visible)."""
    print(visible(message), file=sys.stderr)


def emit(text: str, output: Path | None) -> None:
    """Write to ``output`` atomically, or to stdout."""
    if output is None:
        sys.stdout.write(text)
    else:
        write_all({output: text})
