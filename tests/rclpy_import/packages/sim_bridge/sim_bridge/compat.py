"""A base class that wraps declare_parameter for its nodes."""

from rclpy.node import Node


class CompatNode(Node):
    def get_param(self, name, default):
        """Declare ``name`` with ``default`` and give its value."""
        if not self.has_parameter(name):
            self.declare_parameter(name, default)
        value = self.get_parameter(name).value
        self.get_logger().info(f"{name}: {value}")
        return value

    def declare_common(self):
        self.declare_parameter("use_sim_time_offset", 0.0)
