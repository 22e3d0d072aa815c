"""A camera driver written with plain rclpy: every declaration translates exactly."""

from typing import Any

from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.qos import QoSReliabilityPolicy

DEFAULT_RATE = 30.0
AXES = ["pan", "tilt"]


def ranged(text: str, low: float, high: float, step: float = 0.0) -> ParameterDescriptor:
    return ParameterDescriptor(
        description=text,
        floating_point_range=[FloatingPointRange(from_value=low, to_value=high, step=step)],
    )


class CameraDriverNode(Node):
    """Camera driver with an exposure controller."""

    FRAME = "camera_link"

    def __init__(self, **kwargs: Any) -> None:
        super().__init__("camera_driver", **kwargs)
        # Image format
        self.fps = self.declare_parameter(
            "fps", DEFAULT_RATE, ranged("Frame rate [Hz].", 1.0, 120.0, 0.5)
        ).value
        self.declare_parameter(
            "width",
            640,
            ParameterDescriptor(
                description="Image width.",
                integer_range=[IntegerRange(from_value=64, to_value=4096, step=64)],
            ),
        )
        frame = ParameterDescriptor(description="Frame of the images.")
        frame.read_only = True
        self.declare_parameter("frame_id", self.FRAME, frame)
        self.declare_parameter(
            "encoding",
            "rgb8",
            ParameterDescriptor(
                description="Pixel encoding.", additional_constraints="one of rgb8, mono8"
            ),
        )
        self.declare_parameters(
            namespace="exposure",
            parameters=[
                ("auto", True),
                ("gain", 1.5, ranged("Analog gain.", 0.0, 10.0)),
                ("target", [0.4, 0.6]),
            ],
        )
        for axis in AXES:
            self.declare_parameter(f"mount.{axis}.offset", 0.0)
        self.declare_parameter("topics", ["/image_raw", "/camera_info"])
        self.declare_parameter("ids", [1, 2, 3])
        self.declare_parameter("image_reliability", QoSReliabilityPolicy.BEST_EFFORT)
        self.timer = self.create_timer(1.0 / self.fps, self.tick)

    def tick(self) -> None:
        width = self.get_parameter("width").value
        gain = self.get_parameter("exposure.gain").get_parameter_value().double_value
        self.get_logger().debug(f"{width} px, gain {gain}")
