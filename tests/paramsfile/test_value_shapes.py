"""check-params on values ROS cannot type: nested lists, empty items, mixed lists, wrong kinds."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from tests.support import ROOT

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"

PARAMS = """\
/**:
  ros__parameters:
    serial: true
    camera.width: 12.5
    topics: [[a], b]
    camera.height:
      - 1
      -
    control.pid.kp: [1, 2, 2.5]
    robot_name: [a, 1]
    camera.encoding: [1.5, 2]
"""

REPORT = """\
params.yaml:3:13: serial: wrong type: expected string, got bool True
params.yaml:4:19: camera.width: wrong type: expected integer, got double 12.5
params.yaml:5:14: topics: item 0: ROS parameters are flat lists of values
params.yaml:8:8: camera.height: item 1: no value: ROS refuses the file
params.yaml:9:28: control.pid.kp: item 2 is a double but item 0 is an integer: ROS refuses \
lists that mix types (write every item with a decimal point, 2.0 not 2)
params.yaml:10:21: robot_name: item 1 is an integer but item 0 is a string: ROS refuses \
lists that mix types
params.yaml:11:28: camera.encoding: item 1 is an integer but item 0 is a double: ROS refuses \
lists that mix types (write every item with a decimal point, 2.0 not 2)
"""


def test_each_shape_is_named_with_its_item(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    params = tmp_path / "params.yaml"
    params.write_text(PARAMS, encoding="utf-8")
    code = main(["check-params", str(SCHEMA), str(params)])
    out = capsys.readouterr()
    assert code == 1
    assert (out.out + out.err).replace(str(params), "params.yaml") == REPORT
