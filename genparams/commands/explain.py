"""genparams explain /NS/NODE [--schema S[@P]]... [--params-file F | -p RULE]... [--format yaml]"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from genparams.commands._common import emit, node_arguments
from genparams.commands._launch import add_launch_arguments, launched_node, packages
from genparams.commands._schemas import add_schema_arguments, load_bounds
from genparams.commands.check_params import add_known_argument
from genparams.errors import CommandError
from genparams.launch.deployment import node_documents, package_schema
from genparams.outputs.explain_text import text_report, yaml_report
from genparams.paramsfile.explain import RuleError, explain, overrides_document
from genparams.paramsfile.manifest import read_manifest
from genparams.paramsfile.params_reader import ParamsDocument, read_params_file
from genparams.paramsfile.ros_yaml import node_matches
from genparams.schema.errors import SchemaError
from genparams.schema.input_file import read_input_file


class _InOrder(argparse.Action):
    """Keep --params-file and -p in one list, in command-line order, as rcl reads them."""

    def __call__(
        self, parser: argparse.ArgumentParser, ns: argparse.Namespace, value: Any, opt: Any = None
    ) -> None:
        getattr(ns, self.dest).append((self.const, value))


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "explain",
        help="a node's effective parameters, and where each came from",
    )
    parser.add_argument("node", metavar="/NS/NODE")
    parser.add_argument(
        "--params-file", dest="inputs", action=_InOrder, const="file", default=[], metavar="FILE"
    )
    parser.add_argument("-p", dest="inputs", action=_InOrder, const="rule", metavar="NAME:=VALUE")
    add_schema_arguments(parser)
    parser.add_argument(
        "--manifest", type=Path, metavar="FILE", help="take the node's schemas here"
    )
    parser.add_argument(
        "--launch",
        type=Path,
        metavar="LAUNCH",
        help="the launch file that starts the node: its parameters come first, its package's "
        "schema is used when no other is given",
    )
    add_launch_arguments(parser)
    add_known_argument(parser)
    parser.add_argument("--format", choices=("text", "yaml"), default="text")
    parser.add_argument("-o", "--output", type=Path, metavar="FILE")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    (node,) = node_arguments("explain", [args.node])
    specs, known = list(args.also), list(args.known)
    if args.manifest is not None:
        try:
            manifest = read_manifest(args.manifest)
        except SchemaError as exc:
            raise CommandError(exc) from None
        known += manifest.known
        for entry in manifest.nodes:
            if node_matches(entry.node, node):
                specs += [(ref.path, ref.prefix) for ref in entry.schemas]
                known += entry.known
                break
    documents = _documents(args.inputs)
    if args.launch is not None:
        launched = launched_node(args.launch, args, node)
        from_launch, unreadable = node_documents(launched)
        if unreadable:
            raise CommandError(*map(str, unreadable))
        documents = [*from_launch, *documents]
        schema = package_schema(launched, packages(args))
        if not specs and schema is not None:
            specs.append((schema, ""))
    bounds = load_bounds(specs)
    explanation = explain(bounds, documents, node, known)
    text = yaml_report(explanation) if args.format == "yaml" else text_report(explanation)
    emit(text, args.output)
    return 1 if explanation.report.problems else 0


def _documents(inputs: list[tuple[str, str]]) -> list[ParamsDocument]:
    documents: list[ParamsDocument] = []
    rules = 0
    for kind, value in inputs:
        if kind == "rule":
            rules += 1
            try:
                documents.append(overrides_document([value], start=rules))
            except RuleError as exc:
                raise CommandError(f"genparams explain: {exc}") from None
            continue
        try:
            text = read_input_file(value, "params file")
        except SchemaError as exc:
            raise CommandError(exc) from None
        documents.append(read_params_file(text, value))
    return documents
