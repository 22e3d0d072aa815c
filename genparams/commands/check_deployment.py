"""genparams check-deployment PARAMS.yaml... (--manifest FILE | --map NODE=SCHEMA...)"""

from __future__ import annotations

import argparse
from pathlib import Path

from genparams.commands._common import schema_from
from genparams.commands._launch import (
    add_launch_arguments,
    check_launched,
    launched_nodes,
    load_launch,
    packages,
)
from genparams.commands.check_params import add_known_argument
from genparams.errors import CommandError
from genparams.launch.reader import is_launch_file
from genparams.paramsfile.check_params import Bound
from genparams.paramsfile.deployment import Deployed, check_deployment
from genparams.paramsfile.manifest import Manifest, NodeEntry, parse_map, read_manifest
from genparams.paramsfile.node_rules import NodeRule
from genparams.paramsfile.params_reader import read_params_file
from genparams.runtime.core.visible import visible
from genparams.schema.errors import SchemaError
from genparams.schema.input_file import read_input_file
from genparams.schema.model import Schema


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "check-deployment",
        help="check every node section of bringup params files against its node's schemas",
    )
    parser.add_argument(
        "params",
        nargs="+",
        metavar="PARAMS.yaml|LAUNCH",
        type=Path,
        help="bringup params files, or launch files (.launch.py, .launch.xml, .launch.yaml)",
    )
    parser.add_argument("--manifest", type=Path, metavar="FILE", help="nodes -> schemas, known")
    parser.add_argument(
        "--map",
        action="append",
        default=[],
        metavar="NODE=SCHEMA[@PREFIX][,...]",
        help="a node (or pattern) and its schemas, beside or instead of a manifest (repeatable)",
    )
    add_known_argument(parser)
    add_launch_arguments(parser)
    parser.add_argument(
        "-v", "--verbose", action="store_true", help="say which node got which check"
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    manifest = _manifest(args)
    deployed = deployed_schemas(manifest)
    code = 0
    unreadable: list[SchemaError] = []  # the other files are still checked
    for params in args.params:
        if is_launch_file(params):
            code = max(code, _check_launch(params, args, deployed, manifest))
            continue
        try:
            text = read_input_file(params, "params file")
        except SchemaError as exc:
            unreadable.append(exc)
            continue
        document = read_params_file(text, str(params))
        report, checked = check_deployment(
            deployed, document, (*manifest.known, *args.known), manifest.rules
        )
        for line in (*report.problems, *report.warnings):
            print(line)
        if args.verbose:
            for note in checked:
                print(visible(f"{params}: {note}"))
        if report.problems:
            code = 1
    if unreadable:
        raise CommandError(*unreadable)
    return code


def _check_launch(
    path: Path, args: argparse.Namespace, deployed: list[Deployed], manifest: Manifest
) -> int:
    result = load_launch(path, args)
    known = (*manifest.known, *args.known)
    nodes, problems = launched_nodes(result, deployed, known, packages(args))
    found, warnings, notes = check_launched(nodes, manifest.rules)
    for line in sorted({*problems, *found}):
        print(line)
    for line in sorted(set(warnings)):
        print(line)
    for unknown in result.unknowns:
        print(visible(str(unknown)))
    if args.verbose:
        for note in notes:
            print(visible(f"{path}: {note}"))
    return 1 if problems or found else 0


def _manifest(args: argparse.Namespace) -> Manifest:
    entries: list[NodeEntry] = []
    known: tuple[str, ...] = ()
    rules: tuple[NodeRule, ...] = ()
    if args.manifest is not None:
        try:
            manifest = read_manifest(args.manifest)
        except SchemaError as exc:
            raise CommandError(exc) from None
        entries.extend(manifest.nodes)
        known = manifest.known
        rules = manifest.rules
    for text in args.map:
        try:
            entries.append(parse_map(text))
        except ValueError as exc:
            raise CommandError(f"genparams check-deployment: --map: {exc}") from None
    if not entries and not any(is_launch_file(p) for p in args.params):
        raise CommandError("genparams check-deployment: give --manifest FILE or --map NODE=SCHEMA")
    return Manifest(tuple(entries), known, rules)


def deployed_schemas(manifest: Manifest) -> list[Deployed]:
    cache: dict[Path, Schema] = {}
    deployed = []
    for entry in manifest.nodes:
        bounds = []
        for ref in entry.schemas:
            if ref.path not in cache:
                cache[ref.path] = schema_from(ref.path)
            bounds.append(Bound(cache[ref.path], ref.prefix))
        deployed.append(Deployed(entry, tuple(bounds)))
    return deployed
