"""A pan-tilt node naming its parameters as its config files do: a '/', a '-', a `type`."""

from typing import Any

from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.node import Node


class PanTilt(Node):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__("pan_tilt", **kwargs)
        self.declare_parameter(
            "input_shape/height",
            480,
            ParameterDescriptor(integer_range=[IntegerRange(from_value=1, to_value=4096, step=1)]),
        )
        self.declare_parameter("pan.type", "servo", ParameterDescriptor(description="Motor."))
        self.speed = self.declare_parameter("pan.max-speed", 1.5).value
        self.declare_parameters("tilt", [("type", "stepper"), ("max-speed", 0.5)])

    def limits(self) -> tuple[str, int, float]:
        kind = self.get_parameter("pan.type").value
        height = self.get_parameter("input_shape/height").value
        return kind, height, self.get_parameter("tilt.max-speed").value
