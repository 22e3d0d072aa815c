"""genparams check-params SCHEMA PARAMS.yaml... [--node /ns/name]..."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from genparams.commands._common import schema_or_none
from genparams.paramsfile.check_params import check_params
from genparams.paramsfile.params_reader import read_params_file
from genparams.paramsfile.ros_yaml import absolute, node_name_problem


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "check-params",
        help="check params files against a schema; exit 1 listing every problem",
    )
    parser.add_argument("schema", metavar="SCHEMA", type=Path)
    # Several files at once: pre-commit passes every matching file in one call.
    parser.add_argument("params", nargs="+", metavar="PARAMS.yaml", type=Path)
    parser.add_argument(
        "--node",
        action="append",
        default=[],
        metavar="/NS/NAME",
        help="a node that runs this schema (repeatable); sections matching none are errors",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    for node in args.node:
        problem = node_name_problem(node)
        if problem is not None:
            print(f"genparams check-params: invalid --node {node!r}: {problem}", file=sys.stderr)
            return 2
    schema = schema_or_none(args.schema)
    if schema is None:
        return 2
    code = 0
    for params in args.params:
        try:
            text = params.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            print(f"genparams check-params: cannot read {params}: {exc}", file=sys.stderr)
            code = 2
            continue
        document = read_params_file(text, str(params))
        report = check_params(schema, document, [absolute(n) for n in args.node])
        for line in (*report.problems, *report.warnings):
            print(line)
        if report.problems:
            code = max(code, 1)
    return code
