"""Launch files read and never run: every node of bringups in the shapes of a navigation
stack, a ros2_control demo, a MoveIt config and a camera driver in a component container,
with its full name, namespace and parameters; each unknown with its place."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from genparams.cli import main
from genparams.launch.model import InlineParameters, LaunchResult, ParamsFileRef
from genparams.launch.packages import Packages
from genparams.launch.reader import read_launch

HERE = Path(__file__).parent
CORPUS = HERE / "corpus"
PACKAGES = ("nav_stack", "nav2_controller", "rrbot_demo", "arm_moveit_config", "camera_driver",
            "fleet_bringup", "diff_driver")  # fmt: skip
GIVEN = {name: CORPUS / name for name in PACKAGES}
PACKAGE_ARGS = [a for name in PACKAGES for a in ("--package-path", f"{name}={CORPUS / name}")]


def read(relative: str, **arguments: str) -> LaunchResult:
    return read_launch(CORPUS / relative, arguments, Packages(GIVEN))


def nodes(result: LaunchResult) -> list[tuple[str, str, str, str, list[Any]]]:
    """Each node: full name, kind, package/executable, container, its parameter sources."""
    found = []
    for node in result.nodes:
        sources: list[Any] = []
        for source in node.parameters:
            if isinstance(source, ParamsFileRef):
                sources.append(Path(source.path).relative_to(CORPUS).as_posix())
            elif isinstance(source, InlineParameters):
                sources.append({name: value for name, value, _ in source.values})
        executable = f"{node.package}/{node.executable}"
        found.append((node.full_name, node.kind, executable, node.container, sources))
    return found


def unknowns(result: LaunchResult) -> list[str]:
    return [f"{Path(u.location.file).name}:{u.location.line}:{u.location.column}: {u.what}"
            for u in result.unknowns]  # fmt: skip


NAV_PARAMS = "nav_stack/params/nav_params.yaml"


def test_a_navigation_bringup() -> None:
    result = read("nav_stack/launch/bringup.launch.py")
    sim = {"use_sim_time": False}
    assert nodes(result) == [
        ("/robot1/controller_server", "node", "nav2_controller/controller_server", "",
         [sim, NAV_PARAMS]),
        ("/robot1/planner_server", "node", "nav2_planner/planner_server", "", [sim, NAV_PARAMS]),
        ("/robot1/bt_navigator", "node", "nav2_bt_navigator/bt_navigator", "",
         [sim, NAV_PARAMS, {}]),  # its one value is set at launch time
        ("/robot1/lifecycle_manager_navigation", "node",
         "nav2_lifecycle_manager/lifecycle_manager", "",
         [sim, {"autostart": True,
                "node_names": ["controller_server", "planner_server", "bt_navigator"]}]),
    ]  # fmt: skip
    assert unknowns(result) == [
        "bringup.launch.py:43:39: the value of \"PythonExpression(['not ', slam])\"",
        "bringup.launch.py:43:27: the condition \"IfCondition(PythonExpression(['not ', slam]))\"",
        "navigation.launch.py:41:52: environment variable NAV_STACK_BT_XML (unset here)",
        "navigation.launch.py:41:52: parameter default_nav_to_pose_bt_xml",
        "navigation.launch.py:73:13: what an OpaqueFunction starts",
    ]
    assert result.files == [str(CORPUS / "nav_stack/launch/bringup.launch.py"),
                            str(CORPUS / "nav_stack/launch/navigation.launch.py")]  # fmt: skip


def test_arguments_change_names_conditions_and_containers() -> None:
    result = read(
        "nav_stack/launch/bringup.launch.py",
        namespace="robot2",
        use_composition="True",
        slam="true",
        use_sim_time="true",
    )
    assert nodes(result) == [
        ("/robot2/slam_toolbox", "node", "slam_toolbox/async_slam_toolbox_node", "",
         [NAV_PARAMS, {"use_sim_time": True}]),
        ("/robot2/controller_server", "composable_node",
         "nav2_controller/nav2_controller::ControllerServer", "/nav_container", [NAV_PARAMS]),
    ]  # fmt: skip


def test_a_ros2_control_demo() -> None:
    result = read("rrbot_demo/launch/rrbot.launch.py", gui="false")
    assert nodes(result) == [
        ("", "node", "controller_manager/ros2_control_node", "",
         ["rrbot_demo/config/rrbot_controllers.yaml"]),
        ("", "node", "robot_state_publisher/robot_state_publisher", "", [{}]),
        ("", "node", "controller_manager/spawner", "", []),
    ]  # fmt: skip
    assert unknowns(result) == [
        "rrbot.launch.py:19:33: the value of "
        "\"Command([PathJoinSubstitution([FindExecutable(name='xacro')]\"",
        "rrbot.launch.py:31:20: the name of the node controller_manager/ros2_control_node "
        "(the launch file does not name it: its code does)",
        "rrbot.launch.py:19:33: parameter robot_description",
        "rrbot.launch.py:37:28: the name of the node robot_state_publisher/robot_state_publisher "
        "(the launch file does not name it: its code does)",
        "rrbot.launch.py:49:39: the name of the node controller_manager/spawner "
        "(the launch file does not name it: its code does)",
    ]


def test_a_moveit_config_in_xml() -> None:
    result = read("arm_moveit_config/launch/demo.launch.xml")
    assert nodes(result) == [
        ("/robot_state_publisher", "node", "robot_state_publisher/robot_state_publisher", "",
         [{"publish_frequency": 30.0}]),
        ("/arm/move_group", "node", "moveit_ros_move_group/move_group", "",
         ["arm_moveit_config/config/move_group.yaml",
          {"use_sim_time": False, "planning_pipelines.pipeline_names": ["ompl"],
           "default_planning_pipeline": "ompl"}]),
        ("/rviz2", "node", "rviz2/rviz2", "", [{"use_sim_time": False}]),
    ]  # fmt: skip
    assert unknowns(result) == [
        "rsp.launch.xml:5:5: the substitution in \"$(command 'xacro "
        "$(find-pkg-share arm_moveit_config)/config/arm.urdf.xacro')\"",
        "rsp.launch.xml:5:5: parameter robot_description",
        "demo.launch.xml:19:7: environment variable MOVEIT_CAPABILITIES (unset here)",
        "demo.launch.xml:19:7: parameter capabilities",
    ]
    without_rviz = read("arm_moveit_config/launch/demo.launch.xml", use_rviz="false")
    assert [n.full_name for n in without_rviz.nodes][-1] == "/arm/move_group"


def test_a_driver_in_a_component_container_in_yaml(monkeypatch: pytest.MonkeyPatch) -> None:
    result = read("camera_driver/launch/camera.launch.yaml", fps="30")
    assert nodes(result) == [
        ("/sensors/camera_container", "container", "rclcpp_components/component_container",
         "", []),
        ("/sensors/front_camera", "composable_node",
         "camera_driver/camera_driver::CameraComponent", "/sensors/camera_container",
         ["camera_driver/config/camera.yaml", {"camera.fps": 30}]),
        ("/sensors/camera_monitor", "node", "camera_driver/camera_monitor", "",
         [{"camera_name": "front_camera"}]),
    ]  # fmt: skip
    assert unknowns(result) == [
        "camera.launch.yaml:25:16: environment variable CAMERA_SERIAL (unset here)",
        "camera.launch.yaml:25:16: parameter serial",
    ]
    monkeypatch.setenv("CAMERA_SERIAL", "ZZZZ9999")
    result = read("camera_driver/launch/camera.launch.yaml", camera_name="rear_camera")
    assert nodes(result)[1][0] == "/sensors/rear_camera"
    assert nodes(result)[1][4][1] == {"camera.fps": 15.0, "serial": "ZZZZ9999"}
    assert unknowns(result) == []


def test_packages_are_found_through_the_ament_index(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    index = tmp_path / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True)
    (index / "camera_driver").write_text("", encoding="utf-8")
    (tmp_path / "share" / "camera_driver").symlink_to(CORPUS / "camera_driver")
    monkeypatch.setenv("AMENT_PREFIX_PATH", f"/nonexistent:{tmp_path}")
    result = read_launch(
        CORPUS / "camera_driver/launch/camera.launch.yaml", {}, Packages.from_environment({})
    )
    files = [s.path for s in result.nodes[1].parameters if isinstance(s, ParamsFileRef)]
    assert files == [str(tmp_path / "share/camera_driver/config/camera.yaml")]
    result = read_launch(CORPUS / "camera_driver/launch/camera.launch.yaml", {}, Packages())
    assert "camera.launch.yaml:21:15: package 'camera_driver' (not in the ament index: give "\
        "--package-path camera_driver=DIR)" in unknowns(result)  # fmt: skip


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, (captured.out + captured.err).splitlines()


def test_check_deployment_checks_each_node_against_its_package_schema(
    capsys: pytest.CaptureFixture[str],
) -> None:
    launch = CORPUS / "camera_driver/launch/camera.launch.yaml"
    code, out = run(capsys, "check-deployment", str(launch), *PACKAGE_ARGS)
    assert code == 1
    assert out == [
        f"{CORPUS}/camera_driver/config/camera.yaml:7:7: camera.widht: unknown parameter "
        "(did you mean 'camera.width'?): ROS would ignore it",
        f"{launch}:25:16: environment variable CAMERA_SERIAL (unset here): set at launch time",
        f"{launch}:25:16: parameter serial: set at launch time",
    ]


def test_a_manifest_entry_wins_over_the_package_schema(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    manifest = tmp_path / "manifest.yaml"
    schema = CORPUS / "camera_driver/genparams/CameraComponent.yaml"
    manifest.write_text(
        "genparams_deployment: 1\nnodes:\n"
        f"  /sensors/front_camera: {{schemas: [{schema}], known: [camera.widht]}}\n"
        "rules:\n  - {name: one_clock, same: use_sim_time}\n"
        "  - {name: fps, check: '/sensors/front_camera.camera.fps <= 15.0'}\n",
        encoding="utf-8",
    )
    launch = CORPUS / "camera_driver/launch/camera.launch.yaml"
    code, out = run(
        capsys, "check-deployment", str(launch), "--manifest", str(manifest), *PACKAGE_ARGS
    )
    assert code == 0, out
    code, out = run(capsys, "check-deployment", str(launch), "--manifest", str(manifest),
                    "--arg", "fps:=30.0", *PACKAGE_ARGS)  # fmt: skip
    assert code == 1
    assert out[0] == (
        f"{manifest}:6:24: fps: broken: /sensors/front_camera.camera.fps <= 15.0 is false for "
        f"/sensors/front_camera.camera.fps=30.0 (/sensors/front_camera.camera.fps from "
        f"{launch}:23:16 (/sensors/front_camera))"
    )


def test_a_clean_navigation_bringup_checks_clean(capsys: pytest.CaptureFixture[str]) -> None:
    launch = CORPUS / "nav_stack/launch/bringup.launch.py"
    code, out = run(capsys, "check-deployment", str(launch), *PACKAGE_ARGS, "-v")
    assert code == 0, out
    assert f"{launch}: /robot1/controller_server: nav2_controller/controller_server, package "\
        f"schema {CORPUS}/nav2_controller/genparams/controller_server.yaml" in out  # fmt: skip


def test_launch_nodes_lists_them_as_json(capsys: pytest.CaptureFixture[str]) -> None:
    launch = CORPUS / "arm_moveit_config/launch/demo.launch.xml"
    code, out = run(capsys, "launch-nodes", str(launch), "--format", "json", *PACKAGE_ARGS,
                    "--arg", "use_sim_time:=true")  # fmt: skip
    assert code == 0
    data = json.loads("\n".join(out))
    move_group = data["nodes"][1]
    assert (move_group["full_name"], move_group["namespace"], move_group["name"]) == (
        "/arm/move_group", "/arm", "move_group",
    )  # fmt: skip
    assert move_group["parameters"][1]["values"]["use_sim_time"] is True
    assert move_group["location"] == f"{launch}:12:5"
    assert (
        data["set_at_launch_time"][0]["location"]
        == f"{CORPUS}/arm_moveit_config/launch/rsp.launch.xml:5:5"
    )


def test_explain_takes_a_node_of_a_launch_file(capsys: pytest.CaptureFixture[str]) -> None:
    launch = CORPUS / "camera_driver/launch/camera.launch.yaml"
    code, out = run(capsys, "explain", "/sensors/front_camera", "--launch", str(launch),
                    *PACKAGE_ARGS, "--format", "yaml")  # fmt: skip
    assert code == 1  # camera.widht: what ROS would ignore
    assert "    camera:\n" not in out  # dotted names, one per line
    assert "    camera.fps: 15.0" in out and "    serial: ABCD1234" in out
    code, out = run(
        capsys, "explain", "/sensors/front_camra", "--launch", str(launch), *PACKAGE_ARGS
    )
    assert code == 1
    assert out[-1].endswith("did you mean /sensors/front_camera?")
