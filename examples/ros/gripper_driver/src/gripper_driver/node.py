"""The gripper node: parameters declared and validated by the generated module."""

from __future__ import annotations

import sys

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

from genparams.runtime import Changes, ParameterDeclarationError
from gripper_driver.gripper_params import GripperParams


class GripperDriver(Node):
    def __init__(self) -> None:
        super().__init__("gripper_driver")
        self.params = GripperParams.declare(self)
        self.params.on_change(self.reconfigure)
        self.get_logger().info(f"gripping with {self.params.grip.force} N")

    def reconfigure(self, changes: Changes[GripperParams]) -> None:
        for change in changes:
            self.get_logger().info(f"{change.name}: {change.old!r} -> {change.new!r}")


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    try:
        node = GripperDriver()
    except ParameterDeclarationError as exc:
        print(exc, file=sys.stderr)
        rclpy.shutdown()
        return 1
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
