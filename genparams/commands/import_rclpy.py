"""genparams import-rclpy FILE.py [--class NAME] [-o SCHEMA] [--patch]"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from genparams.api import load_schema
from genparams.commands._common import report
from genparams.errors import CommandError
from genparams.integration.writing import write_all
from genparams.outputs.schema_yaml import schema_yaml
from genparams.rclpy_import.convert import APPROXIMATE, LEFT_OUT, Imported
from genparams.rclpy_import.node_file import NodeFileError, import_node
from genparams.rclpy_import.patch import patch_diff
from genparams.schema.errors import SchemaError
from genparams.schema.input_file import read_input_file


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "import-rclpy",
        help="read a hand-written rclpy node's declare_parameter calls into a genparams schema",
    )
    parser.add_argument("source", metavar="FILE.py", type=Path)
    parser.add_argument(
        "--class",
        dest="class_name",
        metavar="NAME",
        help="the node class to import, when the file holds several",
    )
    parser.add_argument(
        "-o", "--output", type=Path, metavar="SCHEMA", help="default: stdout (without --patch)"
    )
    parser.add_argument(
        "--patch",
        action="store_true",
        help="print a unified diff that makes the node use the generated class",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    file = str(args.source)
    try:
        text = read_input_file(args.source, "rclpy source")
    except SchemaError as exc:
        raise CommandError(exc) from None
    try:
        node = import_node(text, file, args.class_name)
    except NodeFileError as exc:
        raise CommandError(exc) from None
    imported = node.imported
    if not imported.imported_names:
        _report(imported)
        raise CommandError(
            f"genparams import-rclpy: {file}: no parameter could be imported: nothing written",
            exit_code=1,
        )
    schema = _header(args.source.name, node.unit_name) + schema_yaml(imported.data)
    try:  # the result must be a schema genparams accepts, or nothing is written
        load_schema(args.output or f"<{imported.name}>", schema)
    except SchemaError as exc:
        _report(imported)
        raise CommandError(
            exc, f"genparams import-rclpy: {file}: the imported schema is not valid"
        ) from None
    diff = patch_diff(node, file) if args.patch else None
    _report(imported)
    if args.output is not None:
        write_all({args.output: schema})
    elif diff is None:
        sys.stdout.write(schema)
    else:
        report("the schema is not written without -o SCHEMA")
    if diff is not None:
        if not diff:
            report("the patch changes nothing: only declarations on self in a class are rewritten")
        sys.stdout.write(diff)
    return 1 if imported.warnings else 0


def _header(source: str, unit_name: str) -> str:
    what = f"the class {unit_name} in {source}" if unit_name else source
    return (
        f"# genparams schema imported from the rclpy node {what}\n"
        "# by `genparams import-rclpy`. Edit freely: this file is now the source.\n"
    )


def _report(imported: Imported) -> None:
    report(*sorted([*imported.warnings, *imported.notes]))
    total = len(imported.outcome)
    lost = imported.count(LEFT_OUT)
    approximate = imported.count(APPROXIMATE)
    report(
        f"imported {total - lost} of {total} parameters"
        + (f" ({approximate} approximately)" if approximate else "")
        + (f"; {lost} left out (see warnings)" if lost else "")
    )
