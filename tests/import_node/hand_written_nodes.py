"""Nodes that declare their parameters by hand, as most rclpy nodes do, in a process of their own.

``python -m tests.import_node.hand_written_nodes NAME:KIND ...`` starts one node per
argument (KIND: driver, dynamic, lossy) and prints "ready" once every node is declared.
"""

from __future__ import annotations

import sys

import rclpy
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter

from tests.node_process import serve


def driver(name: str) -> Node:
    """Every type, ranges with and without a step, read-only, text fields, nesting."""
    node = Node(name)
    node.declare_parameter("port", "/dev/ttyUSB0", ParameterDescriptor(description="Serial port."))
    node.declare_parameter(
        "baud_rate",
        115200,
        ParameterDescriptor(
            description="Line speed.",
            read_only=True,
            integer_range=[IntegerRange(from_value=9600, to_value=921600, step=0)],
        ),
    )
    node.declare_parameter(
        "rate",
        30.0,
        ParameterDescriptor(
            description="Publish rate [Hz].",
            additional_constraints="Keep below the sensor's own rate.",
            floating_point_range=[FloatingPointRange(from_value=1.0, to_value=100.0, step=0.5)],
        ),
    )
    node.declare_parameter(
        "ticks",
        10,
        ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=100, step=5)]),
    )
    node.declare_parameter("verbose", False)
    node.declare_parameters(
        "filter",
        [
            ("enabled", True, ParameterDescriptor(description="Run the filter.")),
            ("weights", [0.25, 0.5, 0.25]),
            ("window", [1, 2, 3]),
            ("frames", ["base_link", "odom"]),
            ("flags", [True, False]),
        ],
    )
    node.declare_parameter("limits.lower.x", -1.5)
    node.declare_parameter("magic", [b"\x01", b"\x02"])
    return node


def dynamic(name: str) -> Node:
    """Dynamic typing, with a value and without, and declarations by type only."""
    node = Node(name)
    node.declare_parameter("gain", 2.0, ParameterDescriptor(description="Gain."))
    node.declare_parameter("anything", 1, ParameterDescriptor(dynamic_typing=True))
    node.declare_parameter(
        "extra", descriptor=ParameterDescriptor(dynamic_typing=True, description="Free.")
    )
    node.declare_parameter("robot_ip", Parameter.Type.STRING)
    node.declare_parameter(
        "frames",
        Parameter.Type.STRING_ARRAY,
        ParameterDescriptor(description="Frames to watch.", read_only=True),
    )
    return node


def names(name: str) -> Node:
    """Names holding '-' and '/', and parameters named type, as rclpy declares them."""
    node = Node(name)
    node.declare_parameter(
        "axis_mappings.twist-linear-x.scale", 0.5, ParameterDescriptor(description="Scale.")
    )
    node.declare_parameter("axis_mappings.twist-linear-x.axis", 1)
    node.declare_parameter("walk.type", "topic")
    node.declare_parameter("type.type.mode", "fast")
    node.declare_parameter(
        "input_shape/height",
        480,
        ParameterDescriptor(integer_range=[IntegerRange(from_value=1, to_value=4096, step=1)]),
    )
    return node


def lossy(name: str) -> Node:
    """A parameter that is also the namespace of another, and two names of one Python
    attribute: no schema can state both of either pair."""
    node = Node(name)
    node.declare_parameter("limits", 1.0)
    node.declare_parameter("limits.upper", 2.0)
    node.declare_parameter("speed-max", 1.0)
    node.declare_parameter("speed_max", 2.0)
    return node


KINDS = {"driver": driver, "dynamic": dynamic, "names": names, "lossy": lossy}


def main(specs: list[str]) -> int:
    rclpy.init()
    nodes = []
    for spec in specs:
        name, _, kind = spec.partition(":")
        nodes.append(KINDS[kind](name))
    return serve(nodes)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
