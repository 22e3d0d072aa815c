"""genparams check-params SCHEMA[@PREFIX] PARAMS.yaml... [--node /ns/name]... [--schema S@P]..."""

from __future__ import annotations

import argparse
from pathlib import Path

from genparams.commands._common import node_arguments
from genparams.commands._schemas import add_schema_arguments, bound_spec, load_bounds
from genparams.errors import CommandError
from genparams.paramsfile.check_params import check_files
from genparams.paramsfile.params_reader import read_params_file
from genparams.schema.errors import SchemaError
from genparams.schema.input_file import read_input_file


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "check-params",
        help="check params files against a schema; exit 1 listing every problem",
    )
    parser.add_argument("schema", metavar="SCHEMA[@PREFIX]", type=bound_spec)
    # Several files at once: pre-commit passes every matching file in one call.
    parser.add_argument("params", nargs="+", metavar="PARAMS.yaml", type=Path)
    parser.add_argument(
        "--node",
        action="append",
        default=[],
        metavar="/NS/NAME",
        help="check the sections rcl applies to this node (repeatable); other sections are "
        "skipped. Without it, every section is read as this node's",
    )
    add_schema_arguments(parser)
    add_known_argument(parser)
    parser.add_argument(
        "-v", "--verbose", action="store_true", help="also list skipped sections, with the reason"
    )
    parser.set_defaults(run=run)


def add_known_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--known",
        action="append",
        default=[],
        metavar="NAME",
        help="a parameter other code declares on the node (a glob such as '*.type' too); "
        "accepted with any value (repeatable)",
    )


def run(args: argparse.Namespace) -> int:
    nodes = list(node_arguments("check-params", args.node, "--node"))
    bounds = load_bounds([args.schema, *args.also])
    code = 0
    unreadable: list[SchemaError] = []  # the other files are still checked
    for params in args.params:
        try:
            text = read_input_file(params, "params file")
        except SchemaError as exc:
            unreadable.append(exc)
            continue
        document = read_params_file(text, str(params))
        report = check_files(bounds, [document], nodes, args.known)
        for line in (*report.problems, *report.warnings):
            print(line)
        if args.verbose:
            for line in report.skipped:
                print(line)
        if report.problems:
            code = 1
    if unreadable:
        raise CommandError(*unreadable)
    return code
