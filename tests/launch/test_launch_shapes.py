"""The smaller shapes of launch files, each read as launch would run it."""

from __future__ import annotations

from pathlib import Path

from genparams.launch.model import InlineParameters, LaunchResult, ParamsFileRef
from genparams.launch.packages import Packages
from genparams.launch.reader import read_launch

PYTHON = """\
from launch import LaunchDescription
from launch_ros.actions import LifecycleNode, Node, PushROSNamespace, SetParameter

NS = "fleet"


def generate_launch_description():
    share = get_package_share_directory("pkg")
    return LaunchDescription([
        DeclareLaunchArgument("real", default_value="false"),
        GroupAction([
            PushROSNamespace(NS),
            SetParameter(name="use_sim_time", value=True),
            LifecycleNode(
                package="pkg", executable="driver", name="driver", namespace="front",
                parameters=[ParameterFile(os.path.join(share, "driver.yaml"), allow_substs=True),
                            {"limits": {"speed": 2.0, "names": ["a", "b"]},
                             "label": TextSubstitution(text="x")}],
            ),
        ]),
        Node(package="pkg", executable="sim", name="sim",
             condition=UnlessCondition(LaunchConfiguration("real"))),
        Node(package="pkg", executable="hw", name="hw", namespace="/abs",
             condition=IfCondition(LaunchConfiguration("real"))),
        IncludeLaunchDescription(
            XMLLaunchDescriptionSource([FindPackageShare("pkg"), "/more.launch.xml"]),
            launch_arguments=[("rate", "5")],
        ),
    ])
"""
XML = """\
<launch>
  <arg name="rate" default="1"/>
  <group namespace="tools" if="true">
    <set_parameter name="use_sim_time" value="false"/>
    <node pkg="pkg" exec="logger" name="logger"><param name="rate" value="$(var rate)"/></node>
  </group>
  <node pkg="pkg" exec="after" name="after"/>
</launch>
"""


def read(tmp_path: Path, **arguments: str) -> LaunchResult:
    (tmp_path / "main.launch.py").write_text(PYTHON, encoding="utf-8")
    (tmp_path / "more.launch.xml").write_text(XML, encoding="utf-8")
    packages = Packages({"pkg": tmp_path})
    return read_launch(tmp_path / "main.launch.py", arguments, packages)


def summary(result: LaunchResult) -> list[tuple[str, str, list[object]]]:
    found = []
    for node in result.nodes:
        sources: list[object] = []
        for source in node.parameters:
            if isinstance(source, ParamsFileRef):
                sources.append(Path(source.path).name)
            elif isinstance(source, InlineParameters):
                sources.append({name: value for name, value, _ in source.values})
        found.append((node.full_name, node.kind, sources))
    return found


def test_every_shape_is_followed(tmp_path: Path) -> None:
    result = read(tmp_path)
    assert summary(result) == [
        ("/fleet/front/driver", "lifecycle_node",
         [{"use_sim_time": True}, "driver.yaml",
          {"limits.speed": 2.0, "limits.names": ["a", "b"], "label": "x"}]),
        ("/sim", "node", []),  # a SetParameter stays in its group; UnlessCondition(false)
        ("/tools/logger", "node", [{"use_sim_time": False}, {"rate": 5}]),
        ("/after", "node", []),
    ]  # fmt: skip
    assert result.unknowns == []


def test_an_argument_flips_the_conditions(tmp_path: Path) -> None:
    names = [n.full_name for n in read(tmp_path, real="true").nodes]
    assert names == ["/fleet/front/driver", "/abs/hw", "/tools/logger", "/after"]
