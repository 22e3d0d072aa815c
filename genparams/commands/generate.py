"""genparams generate SCHEMA... [-o FILE | --out-dir DIR] [--check]"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from genparams.api import load_schema
from genparams.errors import SchemaError, SchemaProblem
from genparams.outputs import stale_diffs, write_all
from genparams.render import render_module


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "generate", help="generate the typed Python module of each schema"
    )
    parser.add_argument("schemas", nargs="+", metavar="SCHEMA", type=Path)
    where = parser.add_mutually_exclusive_group()
    where.add_argument("-o", "--output", type=Path, metavar="FILE", help="output file (one schema)")
    where.add_argument(
        "--out-dir", type=Path, metavar="DIR", help="write <name>_params.py per schema here"
    )
    parser.add_argument(
        "--check",
        action="store_true",
        help="write nothing; exit 1 with a diff if an output is missing or stale",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    if args.output is not None and len(args.schemas) > 1:
        print("genparams generate: -o takes one schema; use --out-dir for several", file=sys.stderr)
        return 2
    problems: list[SchemaProblem] = []
    texts: dict[Path, str] = {}
    for schema_path in args.schemas:
        try:
            schema = load_schema(schema_path)
        except SchemaError as exc:
            problems.extend(exc.problems)
            continue
        if args.output is not None:
            target = args.output
        elif args.out_dir is not None:
            target = args.out_dir / f"{schema.module_name}.py"
        else:
            target = Path("-")
        texts[target] = render_module(schema)
    if problems:
        print(SchemaError(problems), file=sys.stderr)
        return 2
    if Path("-") in texts:
        if args.check:
            print("genparams generate --check needs -o or --out-dir", file=sys.stderr)
            return 2
        sys.stdout.write(texts[Path("-")])
        return 0
    if args.check:
        diffs = stale_diffs(texts)
        for diff in diffs:
            sys.stdout.write(diff)
        return 1 if diffs else 0
    write_all(texts)
    return 0
