"""A pad node whose commands come from its params file, named as the file names them:
`twist-linear-x`, a `type` in every command; two parameters of its own use '/' and '-'."""

from rclpy.node import Node


class CommandPad(Node):
    def __init__(self, **kwargs):
        super().__init__(
            "command_pad",
            allow_undeclared_parameters=True,
            automatically_declare_parameters_from_overrides=True,
            **kwargs,
        )
        self.declare_parameter("input_shape/height", 480)
        self.declare_parameter("dead-zone", 0.05)
        self.drive = self.get_parameters_by_prefix("drive")
