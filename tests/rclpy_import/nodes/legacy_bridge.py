"""A node that needs more than the schema format states today, and code no import can read."""

import os
from typing import Any

import rclpy
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter


class LegacyBridge(Node):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__("legacy_bridge", allow_undeclared_parameters=True, **kwargs)
        self.declare_parameter("rate", 5.0)
        self.declare_parameter("serial", Parameter.Type.STRING)
        self.declare_parameters(
            "",
            [
                ("port", rclpy.Parameter.Type.INTEGER),
                ("baud", 115200),
            ],
        )
        self.declare_parameter("anything", 1, ParameterDescriptor(dynamic_typing=True))
        self.declare_parameter("home", os.environ.get("HOME", "/"))
        self.declare_parameter(
            "limit", 2.0, ParameterDescriptor(description=f"Limit of {self.get_name()}.")
        )
        self.declare_parameter(
            "retries",
            3.0,
            ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=5)]),
        )
        if self.get_parameter("rate").value > 10.0:
            self.declare_parameter("fast_mode", True)
        self.declare_parameter("joints", ["left", "right"])
        for joint in self.get_parameter("joints").value:
            self.declare_parameter(joint, 0.0)
            self.declare_parameter(f"gains.{joint}.p", 1.0)

    def poll(self) -> float:
        rate: float = self.get_parameter("rate").value
        return rate

    def relax(self) -> None:
        self.set_descriptor("rate", ParameterDescriptor(description="Polling rate."))
