"""The node: its own parameter, and the link it builds with itself."""

import math

import numpy as np
from rclpy.node import Node

from gps_reader.serial_link import SerialLink


class GpsNode(Node):
    def __init__(self, **kwargs):
        super().__init__("gps_reader", **kwargs)
        self.declare_parameter("heading_offset", np.pi / 2)
        self.declare_parameter("max_tilt", math.pi / 8)
        self.link = SerialLink(self)


def main():
    node = GpsNode()
    node.destroy_node()
