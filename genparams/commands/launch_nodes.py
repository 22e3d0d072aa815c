"""genparams launch-nodes LAUNCH [--arg NAME:=VALUE]... [--package-path PKG=DIR]... [--format]"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from genparams.commands._launch import add_launch_arguments, load_launch
from genparams.launch.model import InlineParameters, LaunchResult, ParamsFileRef
from genparams.runtime.core.json_codec import dumps
from genparams.runtime.core.visible import visible


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "launch-nodes",
        help="list the nodes a launch file starts, read and never run, with their parameters",
    )
    parser.add_argument("launch", type=Path, metavar="LAUNCH")
    add_launch_arguments(parser)
    parser.add_argument("--format", choices=("text", "json"), default="text")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    result = load_launch(args.launch, args)
    sys.stdout.write(
        dumps(as_data(result), indent=2) + "\n" if args.format == "json" else as_text(result)
    )
    return 0


def as_data(result: LaunchResult) -> dict[str, Any]:
    return {
        "files": result.files,
        "arguments": result.arguments,
        "nodes": [
            {
                "full_name": node.full_name,
                "name": node.name,
                "namespace": node.namespace,
                "kind": node.kind,
                "package": node.package,
                "executable": node.executable,
                "container": node.container,
                "location": str(node.location),
                "parameters": [
                    {"file": s.path, "location": str(s.location)}
                    if isinstance(s, ParamsFileRef)
                    else {
                        "values": {n: v for n, v, _ in s.values},
                        "location": str(s.values[0][2]) if s.values else "",
                    }
                    for s in node.parameters
                ],
            }
            for node in result.nodes
        ],
        "set_at_launch_time": [
            {"what": u.what, "location": str(u.location)} for u in result.unknowns
        ],
    }


def as_text(result: LaunchResult) -> str:
    lines = []
    for node in result.nodes:
        where = f" in {node.container}" if node.container else ""
        lines.append(
            f"{node.full_name or '(unnamed)'}: {node.kind} {node.package}/{node.executable}"
            f"{where} ({node.location})"
        )
        for source in node.parameters:
            if isinstance(source, ParamsFileRef):
                lines.append(f"  params file {source.path}")
            elif isinstance(source, InlineParameters):
                for name, value, _ in source.values:
                    lines.append(f"  {name}: {dumps(value)}")
    lines.extend(str(unknown) for unknown in result.unknowns)
    return "".join(visible(line) + "\n" for line in lines)
