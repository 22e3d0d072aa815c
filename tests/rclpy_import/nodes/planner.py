"""A planner declaring parameters by type only, dynamically typed, one per joint and one
per sensor, and some only in some modes, as hand-written nodes do."""

from typing import Any

from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter


class PlannerNode(Node):
    """Plans arm motions."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__("planner", **kwargs)
        self.declare_parameter("frame_id", Parameter.Type.STRING)
        self.declare_parameter(
            "timeout",
            Parameter.Type.DOUBLE,
            ParameterDescriptor(
                description="Give up after this long [s].",
                floating_point_range=[FloatingPointRange(from_value=0.0, to_value=60.0)],
            ),
        )
        self.declare_parameter(
            "threshold", 5, ParameterDescriptor(dynamic_typing=True, description="A count.")
        )
        self.declare_parameter("plugin_arg", descriptor=ParameterDescriptor(dynamic_typing=True))
        self.declare_parameter("mode", "advanced")
        self.declare_parameter("level", 1)
        self.declare_parameter("joints", ["shoulder", "elbow"])
        self.declare_parameter("sensors", ["imu"])
        for joint in self.get_parameter("joints").value:
            self.declare_parameter(
                f"offsets.{joint}",
                0.0,
                ParameterDescriptor(
                    floating_point_range=[FloatingPointRange(from_value=-3.0, to_value=3.0)]
                ),
            )
        self.sensors = self.get_parameter("sensors").get_parameter_value().string_array_value
        for sensor in self.sensors:
            self.declare_parameter(sensor, "", ParameterDescriptor(description="Its topic."))
        if self.get_parameter("mode").value == "advanced":
            self.declare_parameter("gain", 1.0)
        self.mode = self.get_parameter("mode").value
        if self.mode in ("advanced", "expert"):
            self.declare_parameter("horizon", 10)
        if 2 == self.get_parameter("level").value:
            self.declare_parameter("debug_topic", "/planner/debug")

    def plan(self) -> float:
        gain: float = self.get_parameter("gain").value
        # An optional parameter's alternative is used while it is not set: the read stays.
        frame = self.get_parameter_or("frame_id", Parameter("frame_id", value="map")).value
        # One with a default is always set: the alternative is never used.
        level = self.get_parameter_or("level", Parameter("level", value=0)).value
        # No parameter is named "offsets" (one per joint is): rclpy gives the alternative.
        offset = self.get_parameter_or("offsets", Parameter("offsets", value=0.5)).value
        self.get_logger().debug(f"planning in {frame} at level {level}, offset {offset}")
        return gain
