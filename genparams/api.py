"""The public pipeline: schema file -> model -> generated text. No file is written here."""

from __future__ import annotations

from pathlib import Path

from genparams.builder import build_schema, model_problems
from genparams.errors import Location, SchemaError, SchemaProblem
from genparams.loader import MAX_BYTES, load_yaml
from genparams.model import Schema
from genparams.schema_check import check_document


def load_schema(path: str | Path, text: str | None = None) -> Schema:
    """Load, check and build one schema. Raises SchemaError listing every problem."""
    file = str(path)
    if text is None:
        try:
            if Path(path).stat().st_size > MAX_BYTES:  # refuse before reading it into memory
                raise SchemaError(
                    [
                        SchemaProblem(
                            Location(file, 1, 1), "", f"file is larger than {MAX_BYTES} bytes"
                        )
                    ]
                )
            text = Path(path).read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise SchemaError(
                [SchemaProblem(Location(file, 1, 1), "", f"cannot read schema: {exc}")]
            ) from None
    document = load_yaml(text, file)
    problems = check_document(document)
    if problems:
        raise SchemaError([*problems, *model_problems(document, problems)])
    return build_schema(document)


def generate(path: str | Path, text: str | None = None) -> str:
    """Generate the Python module for one schema and return its text."""
    from genparams.render import render_module

    return render_module(load_schema(path, text))
