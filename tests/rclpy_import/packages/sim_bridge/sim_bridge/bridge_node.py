"""A bridge node: its parameters through the base class's helper."""

import os

from ament_index_python.packages import get_package_share_directory

from . import compat
from .defaults import RATE_HZ, TOPICS


class BridgeNode(compat.CompatNode):
    def __init__(self, **kwargs):
        super().__init__("sim_bridge", **kwargs)
        self.declare_common()
        self.rate = self.get_param("rate", RATE_HZ)
        self.topics = self.get_param("topics", TOPICS)
        for key, value in (("world", "empty"), ("robots", 1)):
            self.get_param(key, value)
        self.get_param(
            "config_file",
            os.path.join(get_package_share_directory("sim_bridge"), "config", "bridge.yaml"),
        )
        joints = self.get_param("joints", ["left", "right"])
        self.get_param("gains", [55.0] * len(self.get_parameter("joints").value))
        self.get_param("input_shape/height", 480)
        print(joints)
