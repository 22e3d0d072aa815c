"""Publishes an arm's joint states; parameters through two kinds of helpers."""

from rclpy.node import Node

from arm_state.params import declared


class ArmStateNode(Node):
    def __init__(self, **kwargs):
        super().__init__("arm_state", **kwargs)
        self.rate = self.get_param("rate", 10)
        self.use_gui = self.get_param("use_gui", False)
        self.publish_positions = declared(self, "publish_default_positions", True, "zeros")
        self.delta = declared(self, "delta", 0.0)

    def get_param(self, name, value=None):
        self.declare_parameter(name, value)
        return self.get_parameter(name).value


if __name__ == "__main__":
    node = ArmStateNode()
