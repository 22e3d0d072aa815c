# In the shape of a multi-robot bringup: a driver per robot built by a helper function from
# module lists, a lidar only on the robots that carry one, a state publisher per robot in
# its own namespace, and one monitor that lists the whole fleet.
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace

ROBOTS = ["alpha", "beta"]
START = {"alpha": (0.0, 0.0), "beta": (2.0, -1.0)}
LIDAR_ROBOTS = ("beta",)
DOCKING = False
TOP_SPEED = 1.5


def config_file(robot):
    share = get_package_share_directory("fleet_bringup")
    return os.path.join(share, "config", robot + ".yaml")


def robot_nodes(robot, robot_id, rate=10.0, sim_time=LaunchConfiguration("use_sim_time")):
    x, y = START[robot]
    speed = TOP_SPEED / 2 if robot in LIDAR_ROBOTS else TOP_SPEED
    found = [
        Node(
            package="diff_driver",
            executable="driver_node",
            name="driver",
            namespace=robot,
            parameters=[
                config_file(robot),
                {"rate": rate, "robot_id": robot_id, "initial_pose": [x, y],
                 "max_speed": speed, "use_sim_time": sim_time},
            ],
        )
    ]
    if robot in LIDAR_ROBOTS:
        found.append(
            Node(package="lidar_driver", executable="lidar_node", name="lidar",
                 namespace=robot, parameters=[{"frame_id": f"{robot}/laser"}])
        )
    elif DOCKING:
        found.append(Node(package="dock", executable="dock_node", name="dock", namespace=robot))
    else:
        pass
    return found


def generate_launch_description():
    ld = LaunchDescription([DeclareLaunchArgument("use_sim_time", default_value="false")])
    nodes = []
    for robot_id, robot in enumerate(ROBOTS, start=1):
        nodes += robot_nodes(robot, robot_id, rate=20.0)
    for robot, (x, y) in START.items():
        ld.add_action(
            GroupAction([
                PushRosNamespace(robot),
                Node(package="robot_state_publisher", executable="robot_state_publisher",
                     name="robot_state_publisher", parameters=[{"frame_prefix": robot + "/"}]),
            ])
        )
    drivers = ["/" + robot + "/driver" for robot in ROBOTS if robot != "gamma"]
    for index in range(len(ROBOTS)):
        if index == 0:
            continue
        nodes.append(
            Node(package="fleet_tools", executable="relay", name=f"relay_{index}",
                 parameters=[{"pairs": [a + ":" + b for a, b in zip(ROBOTS, ROBOTS[1:])]}])
        )
    nodes.append(
        Node(package="fleet_tools", executable="monitor", name="fleet_monitor",
             parameters=[{"drivers": drivers, "robot_count": len(drivers)}])
    )
    for node in nodes:
        ld.add_action(node)
    return ld
