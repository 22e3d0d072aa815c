"""Two nodes in one file: --class picks one."""

from typing import Any

from rclpy.node import Node


class ClientNode(Node):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__("introspection_client", **kwargs)
        self.declare_parameter("client_configure_introspection", "disabled")


class ServiceNode(Node):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__("introspection_service", **kwargs)
        self.declare_parameter("service_configure_introspection", "disabled")
