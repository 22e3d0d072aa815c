"""genparams json-schema SCHEMA [--partial] [-o FILE]"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from genparams.commands._common import emit, schema_or_none
from genparams.outputs.json_schema import params_file_schema


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "json-schema", help="write a JSON Schema of params files for a schema's node"
    )
    parser.add_argument("schema", metavar="SCHEMA", type=Path)
    parser.add_argument(
        "--partial",
        action="store_true",
        help="for files holding part of a configuration: required parameters may be missing",
    )
    parser.add_argument("-o", "--output", type=Path, metavar="FILE", help="default: stdout")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    schema = schema_or_none(args.schema)
    if schema is None:
        return 2
    document = params_file_schema(schema, partial=args.partial)
    emit(json.dumps(document, indent=2, ensure_ascii=False) + "\n", args.output)
    return 0
