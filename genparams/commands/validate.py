"""genparams validate SCHEMA...: check schemas, write nothing."""

from __future__ import annotations

import argparse
from pathlib import Path

from genparams.api import load_schema
from genparams.errors import CommandError
from genparams.schema.errors import SchemaError, SchemaProblem


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser("validate", help="check schemas for errors; write nothing")
    parser.add_argument("schemas", nargs="+", metavar="SCHEMA", type=Path)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    problems: list[SchemaProblem] = []
    for schema_path in args.schemas:
        try:
            load_schema(schema_path)
        except SchemaError as exc:
            problems.extend(exc.problems)
    if problems:
        raise CommandError(SchemaError(problems))
    return 0
