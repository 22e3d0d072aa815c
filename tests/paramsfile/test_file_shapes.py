"""Params files rcl refuses or misreads for their shape, each problem named as a user reads it."""

from __future__ import annotations

import pytest

from genparams.paramsfile.params_reader import read_params_file

SHAPES = {
    "no_node_name": (
        "ros__parameters:\n  a: 1\n",
        ["p.yaml:1:1: ros__parameters: no node name above it: ROS refuses the file"],
    ),
    "a_dotted_key_holding_a_mapping": (
        "/n:\n  ros__parameters:\n    g:\n      a.b:\n        c: 1\n      d: 2\n",
        [
            "p.yaml:6:7: g.d: ROS reads this key as 'g.a.d': a dotted key holding a mapping "
            "above it shifts the names after it (nest the keys instead of dotting them)"
        ],
    ),
    "close_to_ros__parameters": (  # as close as a misspelling is taken to be (ratio 0.8)
        "/n:\n  ros__parametXXX:\n    a: 1\n",
        [
            "p.yaml:2:3: ros__parametXXX: unknown key 'ros__parametXXX' "
            "(did you mean 'ros__parameters'?): ROS refuses the file"
        ],
    ),
    "far_from_ros__parameters": (
        "/n:\n  ros__paramexxxx:\n    a: 1\n",
        [
            "p.yaml:3:8: /n.ros__paramexxxx.a: a value outside ros__parameters: ROS refuses "
            "the file (parameters go under /n/ros__paramexxxx: {ros__parameters: ...})"
        ],
    ),
}


@pytest.mark.parametrize(("text", "problems"), SHAPES.values(), ids=SHAPES.keys())
def test_a_file_shape_rcl_refuses_or_misreads_is_named(text: str, problems: list[str]) -> None:
    assert [str(p) for p in read_params_file(text, "p.yaml").problems] == problems
