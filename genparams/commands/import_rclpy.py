"""genparams import-rclpy FILE.py [--class NAME] [--params-file FILE]... [-o SCHEMA] [--patch]"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from genparams.commands._common import report
from genparams.commands._importing import (
    WRITTEN,
    WRITTEN_WITH_WARNINGS,
    finish,
    read_source,
    refuse_unwritable,
)
from genparams.errors import CommandError
from genparams.importing import schema_text, write_outputs
from genparams.paramsfile.node_sections import entries_in_force, sections_for
from genparams.paramsfile.params_reader import read_params_file
from genparams.rclpy_import.node_file import NodeFileError, import_node, node_name, scanned
from genparams.rclpy_import.patch import patch_diff, unchanged_reason
from genparams.schema.errors import SchemaError


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
        "--params-file",
        dest="params_files",
        action="append",
        default=[],
        type=Path,
        metavar="FILE",
        help="a params file the node is launched with (repeatable): a node declaring what "
        "its overrides name takes its parameters from the node's section",
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
    text = read_source(args.source, "rclpy source")
    try:
        _, unit = scanned(text, file, args.class_name)
        overrides, given_by = _overrides(args.params_files, node_name(unit))
        node = import_node(text, file, args.class_name, overrides, given_by)
    except NodeFileError as exc:
        raise CommandError(exc) from None
    imported = node.imported
    schema = schema_text(imported, _header(args.source.name, node.unit_name))
    if not args.patch:
        return finish("import-rclpy", file, imported, schema, args.output)
    refuse_unwritable("import-rclpy", file, imported, schema)
    diff = patch_diff(node, file)
    report(*imported.findings(), imported.summary())
    if args.output is not None:
        write_outputs({args.output: schema})
    else:
        report("the schema is not written without -o SCHEMA")
    if not diff:
        report(f"the patch changes nothing: {unchanged_reason(node)}")
    sys.stdout.write(diff)
    return WRITTEN_WITH_WARNINGS if imported.warnings else WRITTEN


def _overrides(files: list[Path], node: str | None) -> tuple[dict[str, Any], str]:
    """The parameters ``files`` give the node named ``node`` (later files win), and the
    files' names; without a node name, only sections for every node (``/**``) apply."""
    documents = []
    for path in files:
        text = read_source(path, "params file")
        document = read_params_file(text, str(path))
        if document.problems:
            raise CommandError(SchemaError(list(document.problems)))
        documents.append(document.sections)
    applied, _ = sections_for(documents, f"/{node}" if node else "/_")
    values = {name: entry.value for name, (_, entry) in entries_in_force(applied).items()}
    return values, ", ".join(str(p) for p in files)


def _header(source: str, unit_name: str) -> list[str]:
    what = f"the class {unit_name} in {source}" if unit_name else source
    return [
        f"genparams schema imported from the rclpy node {what}",
        "by `genparams import-rclpy`. Edit freely: this file is now the source.",
    ]
