"""The ``genparams`` command: a thin shell over the commands in genparams.commands."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from genparams._version import __version__
from genparams.commands import (
    audit,
    check_deployment,
    check_params,
    cmake_dir,
    defaults,
    docs,
    explain,
    generate,
    import_gpl,
    import_node,
    import_rclpy,
    json_schema,
    launch_nodes,
    tune,
    validate,
)
from genparams.commands._common import report
from genparams.errors import CommandError, GenparamsError

COMMANDS = (
    generate,
    validate,
    docs,
    defaults,
    json_schema,
    check_params,
    check_deployment,
    explain,
    launch_nodes,
    tune,
    audit,
    import_gpl,
    import_node,
    import_rclpy,
    cmake_dir,
)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="genparams",
        description="Typed, validated ROS 2 parameters from a YAML schema.",
    )
    parser.add_argument("--version", action="version", version=f"genparams {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for command in COMMANDS:
        command.add_parser(subparsers)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run one command; its exit code. A ``CommandError`` is reported here, only here, by the
    one writer of stderr (``commands._common.report``). Any other ``GenparamsError`` a
    command lets through is bad input all the same: its message, exit 2, no traceback."""
    args = build_parser().parse_args(argv)
    try:
        code: int = args.run(args)
    except GenparamsError as error:
        failed = error if isinstance(error, CommandError) else CommandError(error)
        report(*failed.lines)
        return failed.exit_code
    return code


if __name__ == "__main__":
    sys.exit(main())
