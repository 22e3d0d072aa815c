"""A fleet monitor built to declare whatever its params file names, reading one set of
settings per robot found under ``robots`` (``robots.r1.namespace``)."""

from typing import Any

from rclpy.node import Node


class FleetMonitor(Node):
    """Watches the robots the params file names."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(
            "fleet_monitor",
            automatically_declare_parameters_from_overrides=True,
            **kwargs,
        )
        self.period = self.get_parameter("period").value
        robots = self.get_parameters_by_prefix("robots")
        self.robots = {}
        for robot in sorted({key.split(".")[0] for key in robots}):
            namespace = (
                self.get_parameter(f"robots.{robot}.namespace").get_parameter_value().string_value
            )
            battery = self.get_parameter(f"robots.{robot}.battery_low").value
            self.robots[robot] = (namespace, battery)
