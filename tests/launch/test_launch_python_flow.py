"""A ``.launch.py``'s Python followed without running it: loops over what Python holds,
tests on it, the file's own functions; and what only launch knows, reported with its place."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from genparams.launch.model import InlineParameters
from genparams.launch.packages import Packages
from genparams.launch.reader import read_launch
from tests.launch.test_launch_files import CORPUS, PACKAGE_ARGS, nodes, read, unknowns

FLEET = CORPUS / "fleet_bringup/launch/fleet.launch.py"
DYNAMIC = CORPUS / "fleet_bringup/launch/fleet_dynamic.launch.py"


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, (captured.out + captured.err).splitlines()


def test_a_fleet_bringup_built_by_loops_tests_and_functions() -> None:
    result = read("fleet_bringup/launch/fleet.launch.py")
    driver = "diff_driver/driver_node"
    assert nodes(result) == [
        # for robot, (x, y) in START.items(): a group with its namespace per robot
        ("/alpha/robot_state_publisher", "node", "robot_state_publisher/robot_state_publisher",
         "", [{"frame_prefix": "alpha/"}]),
        ("/beta/robot_state_publisher", "node", "robot_state_publisher/robot_state_publisher",
         "", [{"frame_prefix": "beta/"}]),
        # nodes += robot_nodes(robot, robot_id, rate=20.0) for each of enumerate(ROBOTS, 1)
        ("/alpha/driver", "node", driver, "",
         ["fleet_bringup/config/alpha.yaml",
          {"rate": 20.0, "robot_id": 1, "initial_pose": [0.0, 0.0], "max_speed": 1.5,
           "use_sim_time": False}]),
        ("/beta/driver", "node", driver, "",
         ["fleet_bringup/config/beta.yaml",
          {"rate": 20.0, "robot_id": 2, "initial_pose": [2.0, -1.0], "max_speed": 0.75,
           "use_sim_time": False}]),
        ("/beta/lidar", "node", "lidar_driver/lidar_node", "", [{"frame_id": "beta/laser"}]),
        # range(len(ROBOTS)) with `continue` on 0; zip() and a slice in a comprehension
        ("/relay_1", "node", "fleet_tools/relay", "", [{"pairs": ["alpha:beta"]}]),
        ("/fleet_monitor", "node", "fleet_tools/monitor", "",
         [{"drivers": ["/alpha/driver", "/beta/driver"], "robot_count": 2}]),
    ]  # fmt: skip
    assert unknowns(result) == []
    assert [n.location.line for n in result.nodes] == [61, 61, 28, 28, 42, 70, 74]


def test_a_launch_argument_reaches_a_function_default() -> None:
    result = read("fleet_bringup/launch/fleet.launch.py", use_sim_time="true")
    assert [nodes(result)[i][4][1]["use_sim_time"] for i in (2, 3)] == [True, True]


def test_check_deployment_checks_every_robot_of_the_fleet(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, out = run(capsys, "check-deployment", str(FLEET), *PACKAGE_ARGS)
    assert code == 1
    assert out == [
        f"{CORPUS}/fleet_bringup/config/beta.yaml:3:5: wheel_radus: unknown parameter "
        "(did you mean 'wheel_radius'?): ROS would ignore it",
        f"{FLEET}:28:9: max_speed: must be within [0.0, 1.0] (range), got 1.5",
    ]


def test_explain_shows_a_robot_built_in_a_loop(capsys: pytest.CaptureFixture[str]) -> None:
    code, out = run(capsys, "explain", "/beta/driver", "--launch", str(FLEET), *PACKAGE_ARGS,
                    "--format", "yaml")  # fmt: skip
    assert code == 1  # wheel_radus: what ROS would ignore
    assert out[1:] == [
        "/beta/driver:",
        "  ros__parameters:",
        "    initial_pose: [2.0, -1.0]",
        "    max_speed: 0.75",
        "    rate: 20.0",
        "    robot_id: 2",
        "    use_sim_time: false",
        "    wheel_radius: 0.05",
        "    wheel_radus: 0.08",
    ]


DYNAMIC_UNKNOWNS = [
    "fleet_dynamic.launch.py:17:5: what the statement 'with open(path) as stream:' adds",
    "fleet_dynamic.launch.py:29:5: what 'for robot in load_robots(FLEET_FILE):' adds "
    "(its items are not known)",
    "fleet_dynamic.launch.py:31:8: environment variable FLEET_DOCKING (unset here)",
    "fleet_dynamic.launch.py:31:5: what \"if os.environ.get('FLEET_DOCKING') == '1':\" adds "
    "(its test is not known)",
    "fleet_dynamic.launch.py:34:8: the test \"LaunchConfiguration('with_lidar') == 'true'\" "
    "(on a substitution, whose value only launch knows)",
    "fleet_dynamic.launch.py:34:5: what \"if LaunchConfiguration('with_lidar') == 'true':\" "
    "adds (its test is not known)",
    "fleet_dynamic.launch.py:36:17: the value of \"camera_nodes(['front', 'rear'])\"",
    "fleet_dynamic.launch.py:36:5: what \"for node in camera_nodes(['front', 'rear']):\" adds "
    "(its items are not known)",
    "fleet_dynamic.launch.py:31:5: parameter rate",
]


def test_what_only_launch_knows_is_reported_never_guessed() -> None:
    result = read("fleet_bringup/launch/fleet_dynamic.launch.py")
    driver = "diff_driver/driver_node"
    assert nodes(result) == [
        ("/spare/driver", "node", driver, "", [{}]),  # its rate is set under the unknown if
        ("/backup/driver", "node", driver, "", [{"rate": 10.0}]),
    ]
    assert unknowns(result) == DYNAMIC_UNKNOWNS


def test_an_environment_variable_set_here_decides_the_test(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setenv("FLEET_DOCKING", "1")
    result = read("fleet_bringup/launch/fleet_dynamic.launch.py")
    assert [(n[0], n[4]) for n in nodes(result)] == [
        ("/dock", []),
        ("/spare/driver", [{"rate": 5.0}]),
        ("/backup/driver", [{"rate": 10.0}]),
    ]
    assert len(unknowns(result)) == len(DYNAMIC_UNKNOWNS) - 3


def test_check_deployment_lists_the_loops_and_tests_it_cannot_read(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, out = run(capsys, "check-deployment", str(DYNAMIC), *PACKAGE_ARGS)
    assert code == 0
    assert out == [f"{DYNAMIC.parent}/{line}: set at launch time" for line in DYNAMIC_UNKNOWNS]


def read_source(tmp_path: Path, source: str, **arguments: str) -> tuple[list[str], list[str]]:
    """The full names of the nodes a launch file starts, and what it leaves to launch."""
    launch = tmp_path / "shape.launch.py"
    launch.write_text(source, encoding="utf-8")
    result = read_launch(launch, arguments, Packages({}))
    return [n.full_name for n in result.nodes], unknowns(result)


HEADER = "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n"


def test_elif_else_break_and_nested_functions(tmp_path: Path) -> None:
    found = read_source(
        tmp_path,
        HEADER
        + """\
MODE = "sim"


def generate_launch_description():
    ld = LaunchDescription()
    prefix = "fleet"

    def named(suffix, **extra):
        return Node(package="p", executable="e", name=prefix + "_" + suffix, **extra)

    if MODE == "real":
        ld.add_action(named("hardware"))
    elif MODE == "sim" and not False:
        ld.add_action(named("simulator", namespace="sim"))
    else:
        ld.add_action(named("replay"))
    for count in range(10):
        if count >= 2:
            break
        ld.add_action(named(str(count)))
    else:
        ld.add_action(named("never"))
    ld.add_action(named("last") if len(ld) > 2 else None)
    return ld
""",
    )
    assert found == (["/sim/fleet_simulator", "/fleet_0", "/fleet_1", "/fleet_last"], [])


def test_functions_it_cannot_follow_stay_reported(tmp_path: Path) -> None:
    found = read_source(
        tmp_path,
        HEADER
        + """\
def countdown(n):
    return countdown(n + 1)


def two(a, b):
    return [Node(package="p", executable="e", name=a), Node(package="p", executable="e", name=b)]


def maybe(flag):
    if flag == LaunchConfiguration("x"):
        return []
    return [Node(package="p", executable="e", name="maybe")]


def generate_launch_description():
    nodes = [DeclareLaunchArgument("x", default_value="y")]
    nodes += two("a", "b")
    nodes += two("c", c="d")
    nodes.extend(countdown(0))
    nodes += maybe("y")
    while nodes:
        nodes.append(Node(package="p", executable="e", name="looped"))
    return LaunchDescription(nodes)
""",
    )
    assert found == (["/a", "/b"], [
        "shape.launch.py:21:14: the value of \"two('c', c='d')\" (its arguments do not fit "
        "two(a, b))",
        "shape.launch.py:5:12: the value of 'countdown(n + 1)' (calls within calls deeper than 16)",
        "shape.launch.py:13:8: the test \"flag == LaunchConfiguration('x')\" (on a substitution, "
        "whose value only launch knows)",
        "shape.launch.py:13:5: what \"if flag == LaunchConfiguration('x'):\" adds (its test is not "
        "known)",
        "shape.launch.py:24:5: what the statement 'while nodes:' adds",
    ])  # fmt: skip


def test_arguments_declared_in_a_loop_have_their_defaults(tmp_path: Path) -> None:
    source = (
        HEADER
        + """\
SENSORS = {"front": "true", "rear": "false"}


def generate_launch_description():
    ld = LaunchDescription()
    for sensor, default in SENSORS.items():
        ld.add_action(DeclareLaunchArgument(sensor + "_enabled", default_value=default))
        ld.add_action(Node(package="p", executable="e", name=sensor,
                           condition=IfCondition(LaunchConfiguration(sensor + "_enabled"))))
    found = [n for n in ["a", "b", "c"] if n != "b"]
    ld.add_action(Node(package="p", executable="e", name=found[-1], namespace=f"{found[0]}"))
    return ld
"""
    )
    assert read_source(tmp_path, source) == (["/front", "/a/c"], [])
    assert read_source(tmp_path, source, rear_enabled="true")[0] == ["/front", "/rear", "/a/c"]


def test_an_include_per_robot_gets_its_arguments(tmp_path: Path) -> None:
    (tmp_path / "robot.launch.xml").write_text(
        '<launch>\n  <arg name="robot"/>\n  <arg name="speed" default="1.0"/>\n'
        '  <node pkg="p" exec="e" name="base" namespace="$(var robot)">\n'
        '    <param name="speed" value="$(var speed)"/>\n  </node>\n</launch>\n',
        encoding="utf-8",
    )
    source = (
        HEADER
        + f"""\
FLEET = [("alpha", 0.5), ("beta", 2)]


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(
            XMLLaunchDescriptionSource("{tmp_path}/robot.launch.xml"),
            launch_arguments={{"robot": name, "speed": str(speed)}}.items(),
        )
        for name, speed in FLEET
    ] if FLEET else [])
"""
    )
    launch = tmp_path / "fleet.launch.py"
    launch.write_text(source, encoding="utf-8")
    result = read_launch(launch, {}, Packages({}))
    speeds = [s.values[0][1] for n in result.nodes for s in n.parameters
              if isinstance(s, InlineParameters)]  # fmt: skip
    assert [n.full_name for n in result.nodes] == ["/alpha/base", "/beta/base"]
    assert speeds == [0.5, 2]
    assert unknowns(result) == []


def test_loops_too_long_to_follow_stop_with_a_report(tmp_path: Path) -> None:
    found = read_source(
        tmp_path,
        HEADER
        + """\
def generate_launch_description():
    ld = LaunchDescription([Node(package="p", executable="e", name="first")])
    for i in range(100000):
        ld.add_action(Node(package="p", executable="e", name="never"))
    total = 0
    for i in range(4000):
        for j in range(4000):
            total += 1
    return ld
""",
    )
    assert found == ([], [
        "shape.launch.py:6:14: the value of 'range(100000)' (over 4096 items)",
        "shape.launch.py:6:5: what 'for i in range(100000):' adds (its items are not known)",
        "shape.launch.py:4:1: the rest of generate_launch_description() (over 50000 statements "
        "to follow)",
    ])  # fmt: skip


def test_a_list_holding_itself_stops_with_a_report(tmp_path: Path) -> None:
    found = read_source(
        tmp_path,
        HEADER
        + """\
def generate_launch_description():
    nodes = [Node(package="p", executable="e", name="a")]
    nodes.append(nodes)
    return LaunchDescription(nodes)
""",
    )
    assert found == ([], ["shape.launch.py:1:1: the launch file (its values nest too deep to "
                          "follow)"])  # fmt: skip


def test_spreads_generators_and_dicts_filled_in_a_loop(tmp_path: Path) -> None:
    source = (
        HEADER
        + """\
COMMON: dict[str, bool] = {"use_sim_time": False}
GAINS = {"kp": 1.0, "ki": 0.1}


def generate_launch_description():
    arguments = [DeclareLaunchArgument("unused", default_value="x")]
    params = {**COMMON, "mode": "fast"}
    for gain, value in GAINS.items():
        params["pid." + gain] = value * 2
    nodes = (Node(package="p", executable="e", name=n, parameters=[params]) for n in ("a", "b"))
    broken = {[1]: "never"}
    return LaunchDescription([*arguments, *nodes, *UNKNOWN_LIST])
"""
    )
    launch = tmp_path / "shape.launch.py"
    launch.write_text(source, encoding="utf-8")
    result = read_launch(launch, {}, Packages({}))
    assert nodes(result) == [
        (f"/{n}", "node", "p/e", "",
         [{"use_sim_time": False, "mode": "fast", "pid.kp": 2.0, "pid.ki": 0.2}])
        for n in ("a", "b")
    ]  # fmt: skip
    assert unknowns(result) == [
        "shape.launch.py:14:15: the key '[1]'",
        "shape.launch.py:15:52: the variable 'UNKNOWN_LIST'",
    ]


def test_a_return_under_an_unknown_test_leaves_the_description_unknown(tmp_path: Path) -> None:
    found = read_source(
        tmp_path,
        HEADER
        + """\
def generate_launch_description():
    nodes = [Node(package="p", executable="e", name="a")]
    for robot in ["x", "y"]:
        if os.environ["FLEET_STOP_AT"] == robot:
            break
        nodes.append(Node(package="p", executable="e", name=robot))
    return LaunchDescription(nodes)
""",
    )
    assert found == ([], [
        "shape.launch.py:7:12: environment variable FLEET_STOP_AT (unset here)",
        "shape.launch.py:7:9: what \"if os.environ['FLEET_STOP_AT'] == robot:\" adds (its test "
        "is not known)",
        "shape.launch.py:4:1: what generate_launch_description() returns (it may return under a "
        "test or loop only launch decides)",
    ])  # fmt: skip


def test_arguments_declared_in_a_function_have_their_defaults(tmp_path: Path) -> None:
    source = (
        HEADER
        + """\
def declare_arguments(default_robot="alpha"):
    return [DeclareLaunchArgument("robot", default_value=default_robot),
            DeclareLaunchArgument("rate")]


def generate_launch_description():
    robot = LaunchConfiguration("robot")
    return LaunchDescription(declare_arguments() + [
        Node(package="p", executable="e", name="driver", namespace=robot,
             parameters=[{"rate": LaunchConfiguration("rate")}]),
    ])
"""
    )
    assert read_source(tmp_path, source) == (["/alpha/driver"], [
        "shape.launch.py:6:13: parameter rate",  # launch argument rate: no default, none given
    ])  # fmt: skip
    assert read_source(tmp_path, source, robot="beta", rate="2.5")[0] == ["/beta/driver"]


def test_values_too_large_to_work_out_are_left_to_launch(tmp_path: Path) -> None:
    """The limits of import-rclpy's evaluator hold here too (one rule): a power's exponent
    over 64 and a text repeated past 4096 characters are not computed while reading."""
    found = read_source(
        tmp_path,
        HEADER
        + """\
def generate_launch_description():
    big = 10 ** 10 ** 9
    name = "n" * 5000
    small = "n" * 3 + str(2 ** 10)
    return LaunchDescription([Node(package="p", executable="e", name=small)])
""",
    )
    assert found[0] == ["/nnn1024"], found
    assert [line.split(": ", 1)[0] for line in found[1]] == [
        "shape.launch.py:5:11",
        "shape.launch.py:6:12",
    ], found
