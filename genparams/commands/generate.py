"""genparams generate [SCHEMA...] [-o FILE | --out-dir DIR] [--check]

With no SCHEMA, the modules listed in ``[tool.genparams]`` of the nearest
pyproject.toml are generated (see genparams.integration.project_config).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from genparams.api import load_schema
from genparams.errors import CommandError
from genparams.integration.project_config import (
    ProjectConfigError,
    find_pyproject,
    load_project_config,
)
from genparams.integration.writing import stale_diffs, write_all
from genparams.outputs.render import render_module
from genparams.schema.errors import SchemaError, SchemaProblem

STDOUT = Path("-")


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "generate",
        help="generate the typed Python module of each schema",
        description="Generate the typed Python module of each SCHEMA. With no SCHEMA, generate "
        "the modules listed in [tool.genparams] of the nearest pyproject.toml.",
    )
    parser.add_argument("schemas", nargs="*", metavar="SCHEMA", type=Path)
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
    if args.schemas:
        jobs = _jobs_from_arguments(args)
    else:
        jobs = _jobs_from_pyproject(args)
    problems: list[SchemaProblem] = []
    texts: dict[Path, str] = {}
    for schema_path, target in jobs:
        try:
            schema = load_schema(schema_path)
        except SchemaError as exc:
            problems.extend(exc.problems)
            continue
        texts[target or (args.out_dir / f"{schema.module_name}.py")] = render_module(schema)
    if problems:
        raise CommandError(SchemaError(problems))
    if STDOUT in texts:
        if args.check:
            raise CommandError("genparams generate --check needs -o or --out-dir")
        sys.stdout.write(texts[STDOUT])
        return 0
    if args.check:
        diffs = stale_diffs(texts)
        for diff in diffs:
            sys.stdout.write(diff)
        return 1 if diffs else 0
    write_all(texts)
    return 0


Job = tuple[Path, Path | None]  # schema, output (None: <out-dir>/<module name>.py)


def _jobs_from_arguments(args: argparse.Namespace) -> list[Job]:
    if args.output is not None and len(args.schemas) > 1:
        raise CommandError("genparams generate: -o takes one schema; use --out-dir for several")
    if args.output is not None:
        return [(args.schemas[0], args.output)]
    if args.out_dir is not None:
        return [(schema, None) for schema in args.schemas]
    return [(schema, STDOUT) for schema in args.schemas]


def _jobs_from_pyproject(args: argparse.Namespace) -> list[Job]:
    if args.output is not None or args.out_dir is not None:
        raise CommandError(
            "genparams generate: -o and --out-dir need SCHEMA arguments; "
            "without them, outputs come from [tool.genparams] in pyproject.toml"
        )
    pyproject = find_pyproject(Path.cwd())
    if pyproject is None:
        raise CommandError(
            "genparams generate: no SCHEMA given and no pyproject.toml in this folder "
            "or its parents to read [tool.genparams] from"
        )
    try:
        config = load_project_config(pyproject)
    except ProjectConfigError as exc:
        raise CommandError(exc) from None
    return [(_shown(m.schema), _shown(m.output)) for m in config.modules]


def _shown(path: Path) -> Path:
    """``path`` relative to the working folder, so messages and diffs stay short."""
    return Path(os.path.relpath(path))
