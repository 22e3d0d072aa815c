"""What a real node gets from rcl: overrides parsed from command-line args by rcl itself.

Each load gets a fresh Context initialised with the args (as ``ros2 run ...
--ros-args --params-file F -p x:=1`` would), and a node that declares every
override it is given, so rcl's own file parsing, wildcard matching and order
decide. Nothing here re-implements them.
"""

from __future__ import annotations

import array
import os
from pathlib import Path
from typing import Any

import rclpy
from rclpy.context import Context
from rclpy.node import Node

from genparams.runtime import ParameterDeclarationError

# These nodes only read their arguments and talk to no one: a DDS domain of their own
# keeps them from discovering the other nodes of the test run. Creating and destroying
# a participant while others in its domain are discovered could hang Fast DDS in
# destroy_node (seen when the whole runtime suite ran first in one process).
QUIET_DOMAIN = (int(os.environ.get("ROS_DOMAIN_ID", "0")) + 116) % 232


class RclRefusedError(Exception):
    """rcl or rclpy refused the arguments or the node."""


def plain(value: Any) -> Any:
    """A parameter value as a comparable Python value (arrays as lists)."""
    if isinstance(value, (array.array, tuple, list)):
        return list(value)
    return value


def overrides(node: str, args: list[str]) -> dict[str, Any]:
    """The overrides node ``/ns/name`` receives from ``--ros-args *args``; raises Refused."""
    context = Context()
    try:
        rclpy.init(args=["--ros-args", *args], context=context, domain_id=QUIET_DOMAIN)
    except Exception as exc:  # rcl's parse errors come as RCLError / invalid-args errors
        raise RclRefusedError(str(exc)) from exc
    namespace, _, name = node.rpartition("/")
    try:
        ros_node = Node(
            name,
            namespace=namespace or "/",
            context=context,
            automatically_declare_parameters_from_overrides=True,
        )
    except Exception as exc:
        raise RclRefusedError(f"{type(exc).__name__}: {exc}") from exc
    else:
        values = {name: plain(p.value) for name, p in ros_node._parameter_overrides.items()}
        ros_node.destroy_node()
        return values
    finally:
        rclpy.shutdown(context=context)


def file_args(*files: Path) -> list[str]:
    return [arg for f in files for arg in ("--params-file", str(f))]


def started(node: str, args: list[str], classes: list[tuple[type, str]]) -> dict[str, Any] | None:
    """Values of a real node that declares ``classes`` (with prefixes); None if it refuses.

    The node does not declare overrides automatically: what no class declares is
    ignored, as on a robot.
    """
    context = Context()
    rclpy.init(args=["--ros-args", *args], context=context, domain_id=QUIET_DOMAIN)
    namespace, _, name = node.rpartition("/")
    ros_node = Node(name, namespace=namespace or "/", context=context)
    try:
        for params_class, prefix in classes:
            params_class.declare(ros_node, prefix=prefix)  # type: ignore[attr-defined]
    except ParameterDeclarationError:
        return None
    else:
        return {n: plain(p.value) for n, p in ros_node._parameters.items()}
    finally:
        ros_node.destroy_node()
        rclpy.shutdown(context=context)
