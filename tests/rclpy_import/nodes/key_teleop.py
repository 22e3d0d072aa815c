"""A teleop node in the common shape: each value read where it is declared."""

from typing import Any

from rclpy.node import Node


class KeyTeleop(Node):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__("key_teleop", **kwargs)
        self._hz = self.declare_parameter("hz", 10).value
        self._forward_rate = self.declare_parameter("forward_rate", 0.8).value
        self._backward_rate = self.declare_parameter("backward_rate", 0.5).value
        self._stamped = self.declare_parameter("twist_stamped_enabled", True).value
        self._frame = self.declare_parameter("frame_id", "").value
        self.repeat_rate = 20.0
        self.repeat_rate = self.declare_parameter("repeat_rate", self.repeat_rate).value
        rotation = self.declare_parameter("rotation_rate", 1.0)
        self._rotation_rate = rotation.value
        self._limits = self.declare_parameters("limits", [("linear", 1.0), ("angular", 2.0)])

    def period(self) -> float:
        hz = self.get_parameter("hz").get_parameter_value().integer_value
        return 1.0 / hz

    def speeds(self) -> tuple[float, float]:
        return self.get_parameter("limits.linear").value, self._limits[1].value
