"""What the commands that take launch files share: their options, reading one, and
checking its nodes as check-deployment checks a params file's."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from genparams.commands._common import schema_from
from genparams.errors import CommandError
from genparams.launch.deployment import node_documents, package_schema
from genparams.launch.model import LaunchNode, LaunchResult
from genparams.launch.packages import Packages, parse_package_path
from genparams.launch.reader import read_launch
from genparams.paramsfile.check_params import Bound, check_files
from genparams.paramsfile.deployment import Deployed, effective_values
from genparams.paramsfile.node_rules import NodeRule, NodeValue, check_rules
from genparams.paramsfile.params_reader import ParamsDocument
from genparams.paramsfile.ros_yaml import node_matches
from genparams.runtime.core.suggest import closest
from genparams.schema.errors import SchemaProblem


def add_launch_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--arg",
        dest="launch_args",
        action="append",
        default=[],
        metavar="NAME:=VALUE",
        help="a launch argument, as `ros2 launch` takes it (repeatable)",
    )
    parser.add_argument(
        "--package-path",
        action="append",
        default=[],
        metavar="PKG=DIR",
        help="the share folder of a package, before the ament index (repeatable)",
    )


def load_launch(path: Path, args: argparse.Namespace) -> LaunchResult:
    arguments = {}
    for text in args.launch_args:
        name, sep, value = text.partition(":=")
        if not sep or not name:
            raise CommandError(f"genparams: --arg {text!r}: expected NAME:=VALUE")
        arguments[name] = value
    given = {}
    for text in args.package_path:
        try:
            package, folder = parse_package_path(text)
        except ValueError as exc:
            raise CommandError(f"genparams: --package-path: {exc}") from None
        given[package] = folder
    try:
        return read_launch(path, arguments, packages(args))
    except (OSError, UnicodeDecodeError) as exc:
        raise CommandError(
            f"{path}: cannot read the launch file ({exc.__class__.__name__})"
        ) from None


def packages(args: argparse.Namespace) -> Packages:
    given = dict(parse_package_path(text) for text in args.package_path)
    return Packages.from_environment(given)


@dataclass(frozen=True)
class LaunchedNode:
    node: LaunchNode
    bounds: tuple[Bound, ...]
    known: tuple[str, ...]
    documents: tuple[ParamsDocument, ...]
    origin: str  # where its schemas came from, for -v


def launched_nodes(
    result: LaunchResult, deployed: Sequence[Deployed], known: Sequence[str], found: Packages
) -> tuple[list[LaunchedNode], list[SchemaProblem]]:
    """Each named node with its schemas (manifest entry first, then its package's)."""
    nodes, problems = [], []
    for node in result.nodes:
        if not node.full_name:
            continue
        documents, unreadable = node_documents(node)
        problems.extend(unreadable)
        entry = next((d for d in deployed if node_matches(d.entry.node, node.full_name)), None)
        if entry is not None:
            bounds, extra = entry.bounds, entry.entry.known
            origin = f"manifest entry {entry.entry.node}"
        else:
            schema = package_schema(node, found)
            bounds = (Bound(schema_from(schema)),) if schema is not None else ()
            extra = ()
            origin = f"package schema {schema}" if schema is not None else "no schema"
        nodes.append(LaunchedNode(node, tuple(bounds), (*known, *extra), tuple(documents), origin))
    return nodes, problems


def check_launched(
    nodes: Sequence[LaunchedNode], rules: Sequence[NodeRule]
) -> tuple[list[SchemaProblem], list[SchemaProblem], list[str]]:
    """Problems, warnings and -v notes of every node of a launch, and of the rules."""
    problems: list[SchemaProblem] = []
    warnings: list[SchemaProblem] = []
    notes = []
    values: dict[str, dict[str, NodeValue]] = {}
    for item in nodes:
        name = item.node.full_name
        known = item.known if item.bounds else ("*",)  # no schema: only what rcl refuses
        report = check_files(item.bounds, item.documents, [name], known, sections_needed=False)
        problems.extend(report.problems)
        warnings.extend(report.warnings)
        notes.append(f"{name}: {item.node.package}/{item.node.executable}, {item.origin}")
        values[name] = effective_values(item.bounds, item.documents, name, known)
    results = check_rules(rules, values)
    problems.extend(results.problems)
    notes.extend(str(note) for note in results.notes)
    return problems, warnings, notes


def launched_node(path: Path, args: argparse.Namespace, name: str) -> LaunchNode:
    """The node ``name`` of a launch file; a CommandError naming the nodes it starts."""
    result = load_launch(path, args)
    for node in result.nodes:
        if node.full_name == name:
            return node
    names = [n.full_name for n in result.nodes if n.full_name]
    hint = closest(name, names)
    raise CommandError(
        f"genparams: {path} starts no node {name} (it starts: {', '.join(names) or 'none'})"
        + (f"; did you mean {hint}?" if hint else ""),
        exit_code=1,
    )
