"""The node files of the import-rclpy tests: how to run the import on each, and how to
run each one's own declaration code on a real node."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

NODES = Path(__file__).resolve().parent / "nodes"
GOLDEN = Path(__file__).resolve().parent / "golden"


@dataclass(frozen=True)
class Case:
    name: str  # golden files: <name>.yaml, <name>.stderr, <name>.diff
    file: str  # under NODES
    cls: str | None  # --class, and the class the real-node test instantiates
    code: int  # expected exit code
    declare: str | None = None  # a module function declaring on a given node, if no class
    params: str | None = None  # a params file under NODES both real nodes start with

    @property
    def ros_args(self) -> list[str]:
        """The arguments that give a node the case's params file."""
        return ["--params-file", str(NODES / self.params)] if self.params else []

    @property
    def args(self) -> list[str]:
        return [self.file, *(["--class", self.cls] if self.cls else [])]


CASES = [
    Case("arm_controller", "arm_controller.py", None, 0),
    Case("camera_driver", "camera_driver.py", None, 0),
    Case("fleet_monitor", "fleet_monitor.py", None, 1, params="fleet_monitor.params.yaml"),
    Case("key_teleop", "key_teleop.py", None, 0),
    Case("lease_client", "lease_client.py", None, 0),
    Case("legacy_bridge", "legacy_bridge.py", None, 1),
    Case("pan_tilt", "pan_tilt.py", None, 0),
    Case("planner", "planner.py", None, 0),
    Case("sensor_hub", "sensor_hub.py", None, 1, params="sensor_hub.params.yaml"),
    Case("serial_driver", "serial_driver.py", None, 0, declare="declare"),
    Case("two_nodes_service", "two_nodes.py", "ServiceNode", 0),
    Case("waypoint_player", "waypoint_player.py", None, 0),
]
CLASSES = {
    "arm_controller": "ArmControllerNode",
    "camera_driver": "CameraDriverNode",
    "fleet_monitor": "FleetMonitor",
    "key_teleop": "KeyTeleop",
    "lease_client": "LeaseClient",
    "legacy_bridge": "LegacyBridge",
    "pan_tilt": "PanTilt",
    "planner": "PlannerNode",
    "sensor_hub": "SensorHubNode",
    "two_nodes_service": "ServiceNode",
    "waypoint_player": "WaypointPlayer",
}
