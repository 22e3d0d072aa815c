"""A teleop node that declares whatever its params file names."""

from rclpy.node import Node


class PadTeleop(Node):
    def __init__(self, **kwargs):
        super().__init__(
            "pad_teleop",
            allow_undeclared_parameters=True,
            automatically_declare_parameters_from_overrides=True,
            **kwargs,
        )
        self.require_enable = self.get_parameter("require_enable_button").value
        self.enable_button = self.get_parameter("enable_button").value
        self.linear = self.get_parameters_by_prefix("axis_linear")
        self.scale = {k: p.value for k, p in self.get_parameters_by_prefix("scale_linear").items()}
