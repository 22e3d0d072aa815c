"""genparams import-node NODE [-o SCHEMA] [--name NAME] [--timeout S]: a schema from a live node."""

from __future__ import annotations

import argparse
from pathlib import Path

from genparams.commands._common import node_arguments
from genparams.errors import CommandError


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "import-node",
        help="write a schema for a running node (any language) from its parameter services",
    )
    parser.add_argument("node", metavar="NODE", help="the node, e.g. /camera/driver")
    parser.add_argument("-o", "--output", type=Path, metavar="SCHEMA", help="default: stdout")
    parser.add_argument("--name", help="the schema's name (default: the node's base name)")
    parser.add_argument(
        "--timeout",
        type=float,
        default=10.0,
        metavar="SECONDS",
        help="longest wait for the node's services and each answer (default 10)",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    (node,) = node_arguments("import-node", [args.node])
    from genparams.commands._importing import finish
    from genparams.import_node.convert import import_node
    from genparams.import_node.read import read_node
    from genparams.importing import schema_text
    from genparams.live.answers import NodeAnswerError

    try:
        imported = import_node(node, read_node(node, args.timeout), args.name)
    except (TimeoutError, NodeAnswerError) as exc:
        raise CommandError(f"genparams import-node: {exc}") from None
    header = [
        f"genparams schema read from the running node {node} by `genparams import-node`.",
        "Its values at that moment are the defaults. Edit freely: this file is now the source.",
    ]
    return finish("import-node", node, imported, schema_text(imported, header), args.output)
