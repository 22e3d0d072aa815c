"""genparams import-gpl GPL_YAML [-o FILE | --out-dir DIR] [--checks-module NAME]"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from genparams.api import load_schema
from genparams.commands._common import report
from genparams.errors import CommandError
from genparams.gpl.convert import GplError, Imported, import_gpl
from genparams.gpl.emit import schema_text, stub_text
from genparams.integration.writing import write_all
from genparams.schema.errors import SchemaError
from genparams.schema.input_file import read_input_file
from genparams.schema.loader import load_yaml


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "import-gpl",
        help="convert a generate_parameter_library YAML file into a genparams schema",
    )
    parser.add_argument("gpl_file", metavar="GPL_YAML", type=Path)
    where = parser.add_mutually_exclusive_group()
    where.add_argument("-o", "--output", type=Path, metavar="FILE", help="default: stdout")
    where.add_argument(
        "--out-dir",
        type=Path,
        metavar="DIR",
        help="write DIR/<name>.yaml (and DIR/<checks module>.py when custom validators are used)",
    )
    parser.add_argument(
        "--checks-module",
        metavar="NAME",
        help="Python module of the custom validators (default: <name>_checks)",
    )
    parser.add_argument(
        "--adopt",
        action="append",
        default=[],
        metavar="NAME",
        help="a parameter the node's own code declares before the generated class "
        "(dotted name; repeatable): marked adopt: true",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    file = str(args.gpl_file)
    try:
        document = load_yaml(
            read_input_file(args.gpl_file, "generate_parameter_library file"), file
        )
        imported = import_gpl(document, args.checks_module, args.adopt)
    except SchemaError as exc:
        raise CommandError(exc) from None
    except GplError as exc:
        raise CommandError(f"{file}:1:1: {exc}") from None
    module = args.checks_module or f"{imported.name}_checks"
    if imported.errors:
        raise CommandError(*map(str, sorted([*imported.errors, *imported.warnings])))
    text = schema_text(imported, args.gpl_file.name)
    target = args.output
    if args.out_dir is not None:
        target = args.out_dir / f"{imported.name}.yaml"
    try:  # the result must be a schema genparams accepts, or nothing is written
        # Lines of its errors are lines of the schema text, which is not written.
        load_schema(f"<schema imported from {args.gpl_file.name}, not written>", text)
    except SchemaError as exc:
        raise CommandError(
            *map(str, sorted(imported.warnings)),
            exc,
            f"genparams import-gpl: {file}: the imported schema is not valid",
        ) from None
    outputs: dict[Path, str] = {}
    if target is not None:
        outputs[target] = text
        if imported.customs:
            outputs[target.parent / f"{module.rpartition('.')[2]}.py"] = stub_text(imported, module)
    _report(imported, module, outputs)
    if target is None:
        sys.stdout.write(text)
    else:
        write_all(outputs)
    return 1 if imported.warnings else 0


def _report(imported: Imported, module: str, outputs: dict[Path, str]) -> None:
    report(*sorted([*imported.warnings, *imported.notes]))
    if imported.customs:
        stub = next((p for p in outputs if p.suffix == ".py"), None)
        where = f"stubs in {stub}" if stub else "write them in Python"
        names = ", ".join(sorted(imported.customs))
        report(f"custom validators to implement in {module} ({where}): {names}")
    lost = imported.parameters - imported.imported
    report(
        f"imported {imported.imported} of {imported.parameters} parameters"
        + (f"; {lost} left out (see warnings)" if lost else "")
    )
