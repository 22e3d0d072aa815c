"""Kept values go back into the params file at the place that gave them: a round trip of
a commented file changes only the lines of the changed values."""

from __future__ import annotations

import difflib
import math

import pytest

from genparams.outputs.keep_values import KeepError, NodeValues, apply, plan
from genparams.paramsfile.params_reader import read_params_file

BRINGUP = """\
# Robot bringup: shared values first, then each node.
/**:
  ros__parameters:
    use_sim_time: false   # the real robot
/robot/camera:
  ros__parameters:
    # frame rate, tuned on the bench
    camera:
      fps: 15.0          # Hz
      encoding: "rgb8"
    topics:
      - /image
      - /info
    gains: [1.0, 2.0]    # flow list
    label: plain text
/robot/planner:
  ros__parameters: {max_speed: 1.0}
"""
SIM = """\
/robot/camera:
  ros__parameters:
    camera.fps: 30.0     # the simulator runs faster
"""


def documents() -> list:  # type: ignore[type-arg]
    return [read_params_file(BRINGUP, "bringup.yaml"), read_params_file(SIM, "sim.yaml")]


def changed_lines(before: str, after: str) -> list[str]:
    return [
        line
        for line in difflib.unified_diff(before.splitlines(), after.splitlines(), lineterm="", n=0)
        if line[:1] in "+-" and not line.startswith(("+++", "---"))
    ]


def test_only_the_lines_of_changed_values_change() -> None:
    values = {
        "camera.fps": 25.0,  # sim.yaml wins for it: written there
        "camera.encoding": "true",  # a string ROS would read as a bool: quoted
        "topics": ["/image", "/info", "/depth"],
        "gains": [1.0, 2.5],
        "label": "plain text",  # unchanged
        "use_sim_time": True,
    }
    changes = plan([NodeValues("/robot/camera", values, {})], documents(), None)
    texts = apply(changes, {"bringup.yaml": BRINGUP, "sim.yaml": SIM})
    assert changed_lines(SIM, texts["sim.yaml"]) == [
        "-    camera.fps: 30.0     # the simulator runs faster",
        "+    camera.fps: 25.0     # the simulator runs faster",
    ]
    assert changed_lines(BRINGUP, texts["bringup.yaml"]) == [
        "-    use_sim_time: false   # the real robot",
        "+    use_sim_time: true   # the real robot",
        '-      encoding: "rgb8"',
        '+      encoding: "true"',
        "-      - /image",  # a block list becomes a flow list
        "-      - /info",
        "-    gains: [1.0, 2.0]    # flow list",
        "+      [/image, /info, /depth]",
        "+    gains: [1.0, 2.5]    # flow list",
    ]
    again = [read_params_file(texts["bringup.yaml"], "bringup.yaml"),
             read_params_file(texts["sim.yaml"], "sim.yaml")]  # fmt: skip
    assert plan([NodeValues("/robot/camera", values, {})], again, None) == []  # kept for good


def test_values_no_file_gave_go_to_the_named_file() -> None:
    values = {"camera.height": 480, "camera.width": 800, "label": "plain text"}
    node = NodeValues("/robot/camera", values, {"camera.width": 640, "camera.height": 480})
    changes = plan([node], documents(), "kept.yaml")
    assert [(c.name, c.old, c.new, c.file, c.location) for c in changes] == [
        ("camera.width", 640, 800, "kept.yaml", None)
    ]
    texts = apply(changes, {})
    assert texts == {"kept.yaml": "/robot/camera:\n  ros__parameters:\n    camera.width: 800\n"}
    existing = "/robot/camera:\n  ros__parameters:\n    # kept\n    camera.height: 500\n"
    with_file = [*documents(), read_params_file(existing, "kept.yaml")]
    node = NodeValues("/robot/camera", {**values, "camera.height": 480}, {"camera.width": 640})
    texts = apply(plan([node], with_file, "kept.yaml"), {"kept.yaml": existing})
    assert texts["kept.yaml"] == (
        "/robot/camera:\n  ros__parameters:\n    camera.width: 800\n    # kept\n"
        "    camera.height: 480\n"
    )


def test_nan_is_kept_as_nan_and_equal_values_are_not_written() -> None:
    text = "/n:\n  ros__parameters:\n    x: .nan\n    y: 1.0\n"
    document = read_params_file(text, "f.yaml")
    node = NodeValues("/n", {"x": math.nan, "y": 1.0}, {})
    assert plan([node], [document], None) == []


def test_a_flow_section_cannot_take_new_lines() -> None:
    node = NodeValues("/robot/planner", {"min_speed": 0.5}, {"min_speed": 0.0})
    changes = plan([node], documents(), "bringup.yaml")
    with pytest.raises(KeepError, match="block style"):
        apply(changes, {"bringup.yaml": BRINGUP})
