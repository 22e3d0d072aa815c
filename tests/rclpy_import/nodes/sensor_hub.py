"""A sensor hub taking its sensors from the params file: one set of settings per name found
under ``sensors`` in the node's overrides (``sensors.front.topic``), and one per camera name
found under ``cameras``, with no list of names to keep in step."""

from typing import Any

from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node

SENSORS = "sensors."


class SensorHubNode(Node):
    """Fuses the sensors the params file names."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__("sensor_hub", **kwargs)
        self.declare_parameter("publish_rate", 20.0)
        names = sorted(
            {name.split(".")[1] for name in self._parameter_overrides if name.startswith(SENSORS)}
        )
        for name in names:
            self.declare_parameter(f"sensors.{name}.topic", "/scan")
            self.declare_parameter(
                f"sensors.{name}.rate",
                30.0,
                ParameterDescriptor(
                    description="Expected rate [Hz].",
                    floating_point_range=[FloatingPointRange(from_value=1.0, to_value=200.0)],
                ),
            )
            self.declare_parameter(f"sensors.{name}.frame_id", name + "_link")
        self.camera_names = set(
            key.split(".", 2)[1]
            for key in self._parameter_overrides.keys()
            if key.startswith("cameras.")
        )
        self.cameras = {}
        for camera in self.camera_names:
            width, height = self.declare_parameters(
                namespace=f"cameras.{camera}",
                parameters=[("width", 640), ("height", 480)],
            )
            self.cameras[camera] = (width.value, height.value)
