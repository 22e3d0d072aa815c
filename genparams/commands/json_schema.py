"""genparams json-schema SCHEMA[@PREFIX] [--schema S[@P]]... [--partial] [-o FILE]"""

from __future__ import annotations

import argparse
from pathlib import Path

from genparams.commands._common import emit
from genparams.commands._schemas import add_schema_arguments, bound_spec, load_bounds
from genparams.outputs.json_schema import params_file_schema
from genparams.runtime.core.json_codec import dumps
from genparams.schema.combine import combined_schema


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "json-schema", help="write a JSON Schema of params files for a schema's node"
    )
    parser.add_argument("schema", metavar="SCHEMA[@PREFIX]", type=bound_spec)
    add_schema_arguments(parser)
    parser.add_argument(
        "--partial",
        action="store_true",
        help="for files holding part of a configuration: required parameters may be missing",
    )
    parser.add_argument("-o", "--output", type=Path, metavar="FILE", help="default: stdout")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    bounds = load_bounds([args.schema, *args.also])
    schema = combined_schema([(b.schema, b.prefix) for b in bounds])
    document = params_file_schema(schema, partial=args.partial)
    emit(dumps(document, indent=2, ensure_ascii=False) + "\n", args.output)
    return 0
