# In the shape of a navigation launch file: the servers as plain nodes, or loaded into a
# container when composition is asked for; the lifecycle manager names them.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, OpaqueFunction
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import EnvironmentVariable, LaunchConfiguration
from launch_ros.actions import LoadComposableNodes, Node, SetParameter
from launch_ros.descriptions import ComposableNode

LIFECYCLE_NODES = ["controller_server", "planner_server", "bt_navigator"]


def generate_launch_description():
    use_sim_time = LaunchConfiguration("use_sim_time")
    params_file = LaunchConfiguration("params_file")
    use_composition = LaunchConfiguration("use_composition")
    autostart = LaunchConfiguration("autostart")

    servers = GroupAction(
        condition=UnlessCondition(use_composition),
        actions=[
            SetParameter("use_sim_time", use_sim_time),
            Node(
                package="nav2_controller",
                executable="controller_server",
                name="controller_server",
                parameters=[params_file],
            ),
            Node(
                package="nav2_planner",
                executable="planner_server",
                name="planner_server",
                parameters=[params_file],
            ),
            Node(
                package="nav2_bt_navigator",
                executable="bt_navigator",
                name="bt_navigator",
                parameters=[
                    params_file,
                    {"default_nav_to_pose_bt_xml": EnvironmentVariable("NAV_STACK_BT_XML")},
                ],
            ),
            Node(
                package="nav2_lifecycle_manager",
                executable="lifecycle_manager",
                name="lifecycle_manager_navigation",
                parameters=[{"autostart": autostart, "node_names": LIFECYCLE_NODES}],
            ),
        ],
    )
    composed = LoadComposableNodes(
        condition=IfCondition(use_composition),
        target_container="/nav_container",
        composable_node_descriptions=[
            ComposableNode(
                package="nav2_controller",
                plugin="nav2_controller::ControllerServer",
                name="controller_server",
                parameters=[params_file],
            ),
        ],
    )

    return LaunchDescription(
        [
            DeclareLaunchArgument("use_sim_time", default_value="false"),
            DeclareLaunchArgument("params_file"),
            DeclareLaunchArgument("use_composition", default_value="False"),
            DeclareLaunchArgument("autostart", default_value="true"),
            servers,
            composed,
            OpaqueFunction(function=lambda context: []),
        ]
    )
