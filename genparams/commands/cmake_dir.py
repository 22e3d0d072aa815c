"""genparams cmake-dir: where genparamsConfig.cmake is, for find_package(genparams)."""

from __future__ import annotations

import argparse

from genparams.cmake import cmake_dir


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "cmake-dir",
        help="print the folder of genparamsConfig.cmake (for genparams_DIR or CMAKE_PREFIX_PATH)",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    print(cmake_dir())
    return 0
