"""A waypoint player naming its per-item parameters in steps: a name built in a variable
first, and a nested function declaring one part of each waypoint at each call."""

from typing import Any

from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node


class WaypointPlayer(Node):
    """Plays waypoints in turn."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__("waypoint_player", **kwargs)
        self.declare_parameter("waypoints", ["home", "dock"])
        self.declare_parameter("axes", ["x", "yaw"])
        for axis in self.get_parameter("axes").value:
            key = "tolerance." + axis
            self.declare_parameter(key, 0.05)
        self.targets: dict[str, list[float]] = {}
        for waypoint in self.get_parameter("waypoints").value:

            def part(field: str, size: int) -> list[float]:
                full = f"{waypoint}.{field}"  # noqa: B023 (called in the same turn)
                text = "Values of " + field + "."
                return list(
                    self.declare_parameter(
                        full,
                        [float()] * size,  # noqa: UP018 (as nodes write it)
                        ParameterDescriptor(description=text),
                    ).value
                )

            self.targets[waypoint] = part("pose", 3) + part("speed", 1)
