"""genparams docs SCHEMA --format markdown|rst [-o FILE]"""

from __future__ import annotations

import argparse
from pathlib import Path

from genparams.commands._common import emit, schema_from
from genparams.outputs.docs_model import FORMATS, docs_page
from genparams.outputs.render import render_docs


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser("docs", help="write a documentation page for a schema")
    parser.add_argument("schema", metavar="SCHEMA", type=Path)
    parser.add_argument("--format", choices=FORMATS, default="markdown")
    parser.add_argument("-o", "--output", type=Path, metavar="FILE", help="default: stdout")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    schema = schema_from(args.schema)
    emit(render_docs(docs_page(schema), args.format), args.output)
    return 0
