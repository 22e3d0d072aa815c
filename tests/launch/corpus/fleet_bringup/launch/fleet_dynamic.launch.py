# In the shape of a fleet bringup that learns its robots only when it runs: the robot list
# from a file, a feature switch from the environment, a helper of another package, and a
# test on a launch argument, which Python sees as a substitution object.
import os

import yaml
from fleet_tools.launch_helpers import camera_nodes
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

FLEET_FILE = "/etc/fleet/robots.yaml"


def load_robots(path):
    with open(path) as stream:
        return yaml.safe_load(stream)["robots"]


def driver(robot, rate):
    return Node(package="diff_driver", executable="driver_node", name="driver",
                namespace=robot, parameters=[{"rate": rate}])


def generate_launch_description():
    ld = LaunchDescription([DeclareLaunchArgument("with_lidar", default_value="true")])
    rate = 20.0
    for robot in load_robots(FLEET_FILE):
        ld.add_action(driver(robot, rate))
    if os.environ.get("FLEET_DOCKING") == "1":
        ld.add_action(Node(package="dock", executable="dock_node", name="dock"))
        rate = 5.0
    if LaunchConfiguration("with_lidar") == "true":
        ld.add_action(Node(package="lidar_driver", executable="lidar_node", name="lidar"))
    for node in camera_nodes(["front", "rear"]):
        ld.add_action(node)
    ld.add_action(driver("spare", rate))
    ld.add_action(driver("backup", 10.0))
    return ld
