# In the shape of a navigation stack's bringup: arguments, an include of the navigation
# launch file under a namespace, and a map server only some runs start.
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node, PushRosNamespace

BRINGUP = "nav_stack"


def generate_launch_description():
    bringup_dir = get_package_share_directory(BRINGUP)
    launch_dir = os.path.join(bringup_dir, "launch")

    namespace = LaunchConfiguration("namespace")
    use_sim_time = LaunchConfiguration("use_sim_time")
    params_file = LaunchConfiguration("params_file")
    slam = LaunchConfiguration("slam")

    declare_namespace = DeclareLaunchArgument("namespace", default_value="robot1")
    declare_sim_time = DeclareLaunchArgument("use_sim_time", default_value="false")
    declare_params = DeclareLaunchArgument(
        "params_file", default_value=os.path.join(bringup_dir, "params", "nav_params.yaml")
    )
    declare_slam = DeclareLaunchArgument("slam", default_value="False")

    bringup = GroupAction(
        [
            PushRosNamespace(namespace),
            Node(
                condition=IfCondition(slam),
                package="slam_toolbox",
                executable="async_slam_toolbox_node",
                name="slam_toolbox",
                parameters=[params_file, {"use_sim_time": use_sim_time}],
            ),
            Node(
                condition=IfCondition(PythonExpression(["not ", slam])),
                package="nav2_map_server",
                executable="map_server",
                name="map_server",
                parameters=[
                    params_file,
                    {"use_sim_time": use_sim_time, "yaml_filename": "map.yaml"},
                ],
            ),
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(launch_dir, "navigation.launch.py")),
                launch_arguments={"use_sim_time": use_sim_time, "params_file": params_file}.items(),
            ),
        ]
    )

    ld = LaunchDescription()
    ld.add_action(declare_namespace)
    ld.add_action(declare_sim_time)
    ld.add_action(declare_params)
    ld.add_action(declare_slam)
    ld.add_action(bringup)
    return ld
