"""genparams defaults SCHEMA[@PREFIX] [--schema S[@P]]... [--node NAME] [-o FILE]"""

from __future__ import annotations

import argparse
from pathlib import Path

from genparams.commands._common import emit
from genparams.commands._schemas import add_schema_arguments, bound_spec, load_bounds
from genparams.errors import CommandError
from genparams.outputs.params_file import NodeNameError, default_params_file
from genparams.outputs.render import render_params_file
from genparams.schema.combine import combined_schema


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "defaults", help="write a params file holding every default of a schema"
    )
    parser.add_argument("schema", metavar="SCHEMA[@PREFIX]", type=bound_spec)
    add_schema_arguments(parser)
    parser.add_argument(
        "--node",
        metavar="NAME",
        help="node section name, e.g. /robot/camera_driver (default: /**, every node)",
    )
    parser.add_argument("-o", "--output", type=Path, metavar="FILE", help="default: stdout")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    bounds = load_bounds([args.schema, *args.also])
    schema = combined_schema([(b.schema, b.prefix) for b in bounds])
    try:
        params_file = default_params_file(schema, args.node)
    except NodeNameError as exc:
        raise CommandError(f"genparams defaults: {exc}") from None
    emit(render_params_file(params_file), args.output)
    return 0
