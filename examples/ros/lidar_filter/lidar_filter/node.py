"""The filter node: parameters declared and validated by the generated module."""

from __future__ import annotations

import sys

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

from genparams.runtime import ParameterDeclarationError
from lidar_filter.lidar_filter_params import LidarFilterParams


class LidarFilter(Node):
    def __init__(self) -> None:
        super().__init__("lidar_filter")
        self.params = LidarFilterParams.declare(self)
        limits = self.params.limits
        self.get_logger().info(f"keeping returns in [{limits.min}, {limits.max}] m")


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    try:
        node = LidarFilter()
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
