"""An arm controller declaring a group of parameters per joint, per wheel and per sensor,
each named by an item of a list parameter, as hand-written controllers do."""

from typing import Any

from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node


def gain(text: str) -> ParameterDescriptor:
    return ParameterDescriptor(
        description=text,
        floating_point_range=[FloatingPointRange(from_value=0.0, to_value=100.0)],
    )


class ArmControllerNode(Node):
    """Joint-space controller of an arm on a wheeled base."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__("arm_controller", **kwargs)
        self.joints = self.declare_parameter(
            "joints",
            ["shoulder", "elbow", "wrist"],
            ParameterDescriptor(description="Joints to control, in order."),
        ).value
        self.declare_parameter("wheel_names", ["left_wheel", "right_wheel"])
        self.declare_parameter("sensors", ["imu"])
        self.declare_parameter("rate", 100.0)
        for joint in self.joints:
            self.declare_parameter(f"gains.{joint}.p", 10.0, gain("Proportional gain."))
            self.declare_parameter(f"gains.{joint}.i", 0.0, gain("Integral gain."))
            self.declare_parameter(f"gains.{joint}.d", 0.5, gain("Derivative gain."))
            self.declare_parameter("gains." + joint + ".ff_velocity_scale", 1.0)
            self.declare_parameter(f"joint_limits.{joint}.has_velocity_limits", True)
            self.declare_parameter(
                f"joint_limits.{joint}.max_velocity",
                1.5,
                ParameterDescriptor(description="Largest velocity [rad/s].", read_only=True),
            )
        self.wheels = {}
        wheel_names = self.get_parameter("wheel_names").get_parameter_value().string_array_value
        for wheel in wheel_names:
            radius, inverted = self.declare_parameters(
                namespace=f"wheels.{wheel}",
                parameters=[("radius", 0.05), ("inverted", False)],
            )
            self.wheels[wheel] = (radius.value, inverted.value)
        for sensor in self.get_parameter("sensors").value:
            self.declare_parameter(f"{sensor}.frame_id", "")
            self.declare_parameter(f"{sensor}.filter.cutoff", 20.0)

    def gains_of(self, joint: str) -> tuple[float, float, float]:
        p = self.get_parameter(f"gains.{joint}.p").value
        i = self.get_parameter(f"gains.{joint}.i").value
        d = self.get_parameter(f"gains.{joint}.d").value
        return p, i, d
