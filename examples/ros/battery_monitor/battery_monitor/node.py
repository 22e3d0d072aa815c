"""The monitor node: parameters declared and validated by the generated module."""

from __future__ import annotations

import sys

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

from battery_monitor.battery_monitor_params import BatteryMonitorParams
from genparams.runtime import ParameterDeclarationError


class BatteryMonitor(Node):
    def __init__(self) -> None:
        super().__init__("battery_monitor")
        self.params = BatteryMonitorParams.declare(self)
        warn = self.params.thresholds.warn * self.params.cells
        self.get_logger().info(f"warning below {warn:.2f} V")


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    try:
        node = BatteryMonitor()
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
