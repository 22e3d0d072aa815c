"""A camera driver node whose parameters come from camera_driver.yaml."""

from __future__ import annotations

import sys

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.utilities import try_shutdown

from camera_node.camera_driver_params import CameraDriverParams
from genparams.runtime import Changes, ParameterDeclarationError


class CameraDriver(Node):
    def __init__(self) -> None:
        super().__init__("camera_driver")
        self.params = CameraDriverParams.declare(self)
        self.params.on_change(self.reconfigure)
        camera = self.params.camera
        self.get_logger().info(
            f"started: {camera.width}x{camera.height} {camera.encoding} at {camera.fps} Hz, "
            f"serial {self.params.serial}"
        )

    def reconfigure(self, changes: Changes[CameraDriverParams]) -> None:
        for change in changes:
            self.get_logger().info(f"reconfigured {change.name}: {change.old!r} -> {change.new!r}")


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    try:
        node = CameraDriver()
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
        try_shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
