"""genparams import-gpl GPL_YAML [-o FILE | --out-dir DIR] [--checks-module NAME]"""

from __future__ import annotations

import argparse
from pathlib import Path

from genparams.commands._importing import finish, read_source
from genparams.errors import CommandError
from genparams.gpl.convert import GplError, GplImported, import_gpl
from genparams.gpl.emit import schema_text, stub_text
from genparams.schema.errors import SchemaError
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
    text = read_source(args.gpl_file, "generate_parameter_library file")
    try:
        imported = import_gpl(load_yaml(text, file), args.checks_module, args.adopt)
    except SchemaError as exc:
        raise CommandError(exc) from None
    except GplError as exc:
        raise CommandError(f"{file}:1:1: {exc}") from None
    module = args.checks_module or f"{imported.name}_checks"
    target: Path | None = args.output
    if args.out_dir is not None:
        target = args.out_dir / f"{imported.name}.yaml"
    stubs: dict[Path, str] = {}
    if target is not None and imported.customs:
        stubs[target.parent / f"{module.rpartition('.')[2]}.py"] = stub_text(imported, module)
    schema = schema_text(imported, args.gpl_file.name)
    customs = _customs(imported, module, stubs)
    return finish("import-gpl", file, imported, schema, target, stubs, customs)


def _customs(imported: GplImported, module: str, stubs: dict[Path, str]) -> list[str]:
    """The report's line on the custom validators to write, if any."""
    if not imported.customs:
        return []
    where = f"stubs in {next(iter(stubs))}" if stubs else "write them in Python"
    names = ", ".join(sorted(imported.customs))
    return [f"custom validators to implement in {module} ({where}): {names}"]
