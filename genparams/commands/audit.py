"""genparams audit [--params-file F ...] [--only K | --skip K] [--format F] [NODE...]."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from genparams.audit.findings import KINDS
from genparams.commands._common import node_arguments
from genparams.commands._launch import add_launch_arguments
from genparams.errors import CommandError
from genparams.paramsfile.node_rules import NodeRule
from genparams.paramsfile.params_reader import ParamsDocument


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "audit",
        help="check every running node that publishes a schema; exit 1 on any violation",
    )
    parser.add_argument("nodes", nargs="*", metavar="NODE", help="audit only these nodes")
    parser.add_argument(
        "--params-file",
        action="append",
        default=[],
        type=Path,
        metavar="FILE",
        help="a deployment params file to compare against (repeatable; later files win)",
    )
    parser.add_argument(
        "--trust-package",
        action="append",
        default=[],
        metavar="PACKAGE",
        help="run the custom validators of PACKAGE (or module, and its submodules) that schema"
        " messages name; others are reported not-checked (repeatable)",
    )
    parser.add_argument(
        "--manifest",
        type=Path,
        metavar="FILE",
        help="a deployment manifest: its rules across nodes are checked on the running graph",
    )
    kinds = parser.add_mutually_exclusive_group()
    kinds.add_argument(
        "--only",
        action="append",
        default=[],
        choices=KINDS,
        metavar="KIND",
        help=f"report only findings of KIND (repeatable; kinds: {', '.join(KINDS)})",
    )
    kinds.add_argument(
        "--skip",
        action="append",
        default=[],
        choices=KINDS,
        metavar="KIND",
        help="leave out findings of KIND (repeatable); the exit status follows what is reported",
    )
    parser.add_argument(
        "--include-hidden",
        action="store_true",
        help="audit hidden nodes too (names starting with _, such as the ROS CLI's daemon)",
    )
    parser.add_argument(
        "--launch",
        type=Path,
        metavar="LAUNCH",
        help="a launch file: each node it starts is compared with the parameters it gives it",
    )
    add_launch_arguments(parser)
    parser.add_argument(
        "--write",
        action="store_true",
        help="keep the nodes' values: write each that differs from the --params-file back at "
        "its place in that file",
    )
    parser.add_argument(
        "--new-values",
        type=Path,
        metavar="FILE",
        help="with --write: where values no file gave (off their default) go",
    )
    parser.add_argument("--format", choices=("text", "json"), default="text")
    parser.add_argument(
        "--settle",
        type=float,
        default=1.0,
        metavar="SECONDS",
        help="discovery is done when the node list is unchanged this long (default 1.0)",
    )
    parser.add_argument(
        "--timeout",
        type=float,
        default=5.0,
        metavar="SECONDS",
        help="longest wait for discovery, a schema or a service answer (default 5.0)",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    only = node_arguments("audit", args.nodes)
    from genparams.audit.deployment import DeploymentError, read_deployment
    from genparams.audit.report import json_report, text_report
    from genparams.audit.walk import audit
    from genparams.live.graph import Graph

    try:
        documents = read_deployment(args.params_file)
    except DeploymentError as exc:  # its problems name their file and place
        raise CommandError(exc) from None
    if args.write and not args.params_file and args.launch is None:
        raise CommandError("genparams audit: --write needs a --params-file (or --launch)")
    if args.launch is not None:
        documents = [*documents, *_launch_documents(args)]
    rules = _rules(args.manifest)
    graph = Graph("genparams_audit")
    try:
        result = audit(
            graph,
            documents,
            only=only,
            settle=args.settle,
            timeout=args.timeout,
            trusted_packages=tuple(args.trust_package),
            read_every=bool(rules),
            hidden=args.include_hidden,
        )
    finally:
        graph.close()
    if rules:
        from genparams.audit.node_rules import rule_findings

        result.findings.extend(rule_findings(rules, result.values))
    result.findings = [
        f
        for f in result.findings
        if (not args.only or f.kind in args.only) and f.kind not in args.skip
    ]
    sys.stdout.write(json_report(result) if args.format == "json" else text_report(result))
    if args.write:
        from genparams.commands._keep import keep_audited

        keep_audited(result, documents, args.new_values)
    return 1 if result.failing else 0


def _rules(manifest: Path | None) -> tuple[NodeRule, ...]:
    if manifest is None:
        return ()
    from genparams.paramsfile.manifest import read_manifest
    from genparams.schema.errors import SchemaError

    try:
        return read_manifest(manifest).rules
    except SchemaError as exc:
        raise CommandError(exc) from None


def _launch_documents(args: argparse.Namespace) -> list[ParamsDocument]:
    """What the launch file gives each node it starts, as sections named for that node."""
    from genparams.commands._launch import load_launch
    from genparams.launch.deployment import for_node, node_documents

    documents: list[ParamsDocument] = []
    for node in load_launch(args.launch, args).nodes:
        if node.full_name:
            given, unreadable = node_documents(node)
            if unreadable:
                raise CommandError(*map(str, unreadable))
            documents.extend(for_node(given, node.full_name))
    return documents
