"""A lease client that decides at start-up what else to declare: by proxy or directly, on a
serial link or not, simulated or not, and how to retry (if/else, !=, not in, elif)."""

from typing import Any

from rclpy.node import Node


class LeaseClient(Node):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__("lease_client", **kwargs)
        self.leasing_mode = self.declare_parameter("leasing_mode", "direct").value
        link = self.declare_parameter("link", "serial").value
        self.declare_parameter("simulated", False)
        self.retries = self.declare_parameter("retries", 3).value
        if self.leasing_mode == "proxied":
            self.declare_parameter("proxy_host", "localhost")
        else:
            self.declare_parameter("lease_rate", 1.0)
        if link != "sim":
            self.declare_parameter("device", "/dev/ttyUSB0")
        if link not in ("sim", "udp"):
            self.declare_parameter("baud_rate", 115200)
        if self.get_parameter("simulated").value:
            self.declare_parameter("world", "empty")
        else:
            self.declare_parameter("calibration_file", "calibration.yaml")
        if self.retries == 0:
            self.declare_parameter("fail_fast", True)
        elif self.retries == 1:
            self.declare_parameter("retry_delay", 0.5)
        else:
            self.declare_parameter("backoff", 2.0)
