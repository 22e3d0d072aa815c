"""What rclpy ignores in silence is said at declare(): an override no parameter owns, and a
params-file section one slip away from the node's name. Real nodes, started with their
params files as ROS arguments, in processes of their own."""

from __future__ import annotations

import sys
from pathlib import Path

from genparams.runtime.node.ignored import params_files, section_names
from tests.patience import WAIT_S, run_patiently
from tests.support import ROOT

FILE = """\
# the robot's camera
/robot/camera:
  ros__parameters:
    serial: ABCD1234
    camera:
      fps: 15.0
      fsp: 20.0          # a typo: rclpy ignores it
    front:
      camera:
        fsp: 1.0
    rear.exposure: 3
/robot/camra:            # one slip from /robot/camera
  ros__parameters:
    serial: ABCD1234
    camera: {fps: 5.0}
/robot_2/camera:          # the other robot's copy: no slip
  ros__parameters:
    serial: ABCD1234
"/**":
  ros__parameters:
    use_sim_time: false
"""


def start(tmp_path: Path, prefix: str = "", warn: str = "on", name: str = "camera") -> list[str]:
    """The warnings the node logged at declare()."""
    params = tmp_path / "params.yaml"
    params.write_text(FILE, encoding="utf-8")
    args = [sys.executable, "-m", "tests.runtime.ignored_node", "/robot", name, prefix, warn]
    ros_args = ["--ros-args", "--params-file", str(params)]
    if prefix:
        ros_args += ["-p", f"{prefix}.serial:=ABCD1234"]
    done = run_patiently([*args, *ros_args], budget_s=2 * WAIT_S, cwd=ROOT)
    assert done.returncode == 0 and done.stdout == "declared\n", done.stderr
    return [line.split("]: ", 1)[1] for line in done.stderr.splitlines() if "[WARN]" in line]


def test_an_unowned_override_and_a_near_section_are_warned(tmp_path: Path) -> None:
    file = tmp_path / "params.yaml"
    assert start(tmp_path) == [
        "parameter override 'camera.fsp' is owned by no parameter of this node "
        "(did you mean 'camera.fps'?): rclpy ignores it",
        "parameter override 'front.camera.fsp' is owned by no parameter of this node "
        "(did you mean 'camera.fps'?): rclpy ignores it",
        "parameter override 'rear.exposure' is owned by no parameter of this node: "
        "rclpy ignores it",
        f"{file}: section /robot/camra is not this node (/robot/camera): rclpy applies it to "
        "no node of that name here; a typo of /robot/camera?",
    ]


def test_a_prefixed_class_warns_for_its_own_prefix_only(tmp_path: Path) -> None:
    warnings = start(tmp_path, prefix="front")
    assert warnings[0] == (
        "parameter override 'front.camera.fsp' is owned by no parameter of this node "
        "(did you mean 'front.camera.fps'?): rclpy ignores it"
    )
    assert not any("'camera.fsp'" in w or "rear." in w for w in warnings), warnings


def test_warn_unknown_false_turns_them_off(tmp_path: Path) -> None:
    assert start(tmp_path, warn="off") == []


def test_a_node_the_file_names_exactly_gets_no_section_warning(tmp_path: Path) -> None:
    # /robot/camra is named in the file: its own section, and /robot/camera is one slip away.
    warnings = start(tmp_path, name="camra")
    assert not any("section" in w for w in warnings[:-1])
    assert warnings[-1].endswith(
        "section /robot/camera is not this node (/robot/camra): "
        "rclpy applies it to no node of that name here; a typo of /robot/camra?"
    )


def test_the_files_and_sections_are_read_from_ros_arguments(tmp_path: Path) -> None:
    argv = [
        "prog",
        "x",
        "--ros-args",
        "-p",
        "a:=1",
        "--params-file",
        "a.yaml",
        "--",
        "--params-file",
        "no.yaml",
        "--ros-args",
        "--params-file",
        "b.yaml",
    ]
    assert params_files(argv) == [Path("a.yaml"), Path("b.yaml")]
    file = tmp_path / "nested.yaml"
    file.write_text(
        "/**:\n  controller_manager:\n    ros__parameters:\n      rate: 1\n"
        "  ros__parameters: {a: 1}\nns:\n  'cam':\n    ros__parameters:\n      x: 1\n",
        encoding="utf-8",
    )
    assert section_names(file) == ["/ns/cam"]
    assert section_names(tmp_path / "absent.yaml") == []
