"""genparams tune [--host H] [--port N] [--read-only] [NODE...]: tune live nodes in a browser."""

from __future__ import annotations

import argparse

from genparams.errors import CommandError
from genparams.paramsfile.ros_yaml import absolute, node_name_problem

# The page's web stack comes with the tune extra; a plain `pip install genparams` leaves it out.
WEB_STACK = ("starlette", "uvicorn")
INSTALL_HINT = "pip install 'genparams[tune]'"


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = subparsers.add_parser(
        "tune",
        help="serve a web page to tune the parameters of running nodes; prints its URL",
    )
    parser.add_argument("nodes", nargs="*", metavar="NODE", help="list only these nodes")
    parser.add_argument(
        "--host",
        default="127.0.0.1",
        help="address to bind (default 127.0.0.1); any other needs the token in the URL",
    )
    parser.add_argument("--port", type=int, default=8765, help="port (default 8765; 0: any)")
    parser.add_argument("--read-only", action="store_true", help="serve a view-only page")
    parser.add_argument(
        "--trust-validators",
        action="append",
        default=[],
        metavar="MODULE",
        help="run the custom validators of MODULE (and its submodules) in the page's checks; "
        "others are checked by the node on apply (repeatable)",
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
    for node in args.nodes:
        problem = node_name_problem(absolute(node))
        if problem is not None:
            raise CommandError(f"genparams tune: invalid node {node!r}: {problem}")
    server = TuneServer(
        args.host,
        args.port,
        nodes=tuple(absolute(n) for n in args.nodes),
        read_only=args.read_only,
        trusted_validators=tuple(args.trust_validators),
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
