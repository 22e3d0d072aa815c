"""genparams defaults SCHEMA [--node NAME] [-o FILE]"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from genparams.commands._common import emit, schema_or_none
from genparams.outputs.params_file import NodeNameError, default_params_file
from genparams.outputs.render import render_params_file


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "defaults", help="write a params file holding every default of a schema"
    )
    parser.add_argument("schema", metavar="SCHEMA", type=Path)
    parser.add_argument(
        "--node",
        metavar="NAME",
        help="node section name, e.g. /robot/camera_driver (default: /**, every node)",
    )
    parser.add_argument("-o", "--output", type=Path, metavar="FILE", help="default: stdout")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    schema = schema_or_none(args.schema)
    if schema is None:
        return 2
    try:
        params_file = default_params_file(schema, args.node)
    except NodeNameError as exc:
        print(f"genparams defaults: {exc}", file=sys.stderr)
        return 2
    emit(render_params_file(params_file), args.output)
    return 0
