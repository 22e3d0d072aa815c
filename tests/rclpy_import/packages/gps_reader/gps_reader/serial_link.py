"""The serial side: it declares what it needs on the node that builds it."""

from rcl_interfaces.msg import IntegerRange, ParameterDescriptor

from .limits import DEFAULT_BAUD, TIMEOUT_S, Frames


class SerialLink:
    def __init__(self, node, port="/dev/ttyUSB0"):
        self.node = node
        self.port = node.declare_parameter("port", port).value
        self.baud = node.declare_parameter(
            "baud",
            DEFAULT_BAUD,
            ParameterDescriptor(
                description="bits per second",
                integer_range=[IntegerRange(from_value=1200, to_value=115200, step=0)],
            ),
        ).value
        self.timeout = node.declare_parameter("timeout", TIMEOUT_S).value
        self.frame = node.declare_parameter("frame_id", Frames.CHILD).value
