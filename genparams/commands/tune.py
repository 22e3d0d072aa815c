"""genparams tune [--host H] [--port N] [--token T] [--read-only] [--trust-package P] [NODE...]."""

from __future__ import annotations

import argparse
import os
from pathlib import Path

from genparams.commands._common import node_arguments
from genparams.errors import CommandError

# The page's web stack comes with the tune extra; a plain `pip install genparams` leaves it out.
WEB_STACK = ("starlette", "uvicorn")
INSTALL_HINT = "pip install 'genparams[tune]'"
TOKEN_VARIABLE = "GENPARAMS_TUNE_TOKEN"


def port_number(text: str) -> int:
    """A TCP port, 0 to 65535 (0: any free port)."""
    try:
        port = int(text, 10)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a port number") from None
    if not 0 <= port <= 65535:
        raise argparse.ArgumentTypeError(f"{port} is not a port: use 0 to 65535")
    return port


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "tune",
        help="serve a web page to tune the parameters of running nodes; prints its URL",
    )
    parser.add_argument(
        "nodes", nargs="*", metavar="NODE", help="serve only these nodes (reads and sets)"
    )
    parser.add_argument("--host", default="127.0.0.1", help="address to bind (default 127.0.0.1)")
    parser.add_argument(
        "--port", type=port_number, default=8765, help="port, 0 to 65535 (default 8765; 0: any)"
    )
    parser.add_argument(
        "--token",
        help=f"the access token (default: ${TOKEN_VARIABLE}, else a new random one per run)",
    )
    parser.add_argument("--read-only", action="store_true", help="serve a view-only page")
    parser.add_argument(
        "--include-hidden",
        action="store_true",
        help="list hidden nodes too (names starting with _, such as the ROS CLI's daemon)",
    )
    parser.add_argument(
        "--trust-package",
        action="append",
        default=[],
        metavar="PACKAGE",
        help="run the custom validators of PACKAGE (or module, and its submodules) that schema"
        " messages name in the page's checks; others are checked by the node on apply"
        " (repeatable)",
    )
    parser.add_argument(
        "--params-file",
        action="append",
        default=[],
        type=Path,
        metavar="FILE",
        help='where "Keep these values" writes each value back, at its place (repeatable)',
    )
    parser.add_argument(
        "--new-values",
        type=Path,
        metavar="FILE",
        help='where "Keep these values" writes values no --params-file gave',
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    try:
        from genparams.tune.server import TuneServer
    except ModuleNotFoundError as exc:
        if (exc.name or "").partition(".")[0] not in WEB_STACK:
            raise
        raise CommandError(
            f"genparams tune: the tuning page needs the tune extra ({' and '.join(WEB_STACK)}):"
            f" {INSTALL_HINT}"
        ) from None
    nodes = node_arguments("tune", args.nodes)
    from genparams.tune.security import token_problem

    token = args.token or os.environ.get(TOKEN_VARIABLE) or None
    if token is not None and (problem := token_problem(token)) is not None:
        raise CommandError(f"genparams tune: invalid token: {problem}")
    server = TuneServer(
        args.host,
        args.port,
        nodes=nodes,
        read_only=args.read_only,
        token=token,
        trusted_packages=tuple(args.trust_package),
        include_hidden=args.include_hidden,
        keep=(tuple(args.params_file), args.new_values),
    )
    try:
        print(f"genparams tune: serving {server.start()}", flush=True)
        if server.thread is not None:
            server.thread.join()
    except KeyboardInterrupt:
        pass
    except (OSError, RuntimeError) as exc:
        raise CommandError(f"genparams tune: {exc}") from None
    finally:
        server.stop()
    return 0
