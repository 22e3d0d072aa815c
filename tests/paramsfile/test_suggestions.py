"""The "did you mean" of an unknown name in a params file names the right parameter.

A leaf name shared by several parameters (``arm.gain``, ``base.gain``) must not
decide the suggestion on its own: the whole name does.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from genparams.paramsfile.check_params import suggestion

# drive.fpt and x.settings.exposed are near misses by whole name: a unique leaf must win.
CANDIDATES = [
    "arm.gain",
    "base.gain",
    "camera.fps",
    "camera.settings.exposure",
    "robot_name",
    "drive.fpt",
    "x.settings.exposed",
]


@pytest.mark.parametrize(
    ("given", "meant"),
    [
        ("bse.gain", "base.gain"),  # two parameters end in .gain: the closest whole name wins
        ("arm.gian", "arm.gain"),
        ("fps", "camera.fps"),  # the only parameter with this leaf, misplaced
        ("other.fps", "camera.fps"),
        ("drive.fps", "camera.fps"),  # misplaced: its leaf names one parameter
        ("x.settings.exposure", "camera.settings.exposure"),
        ("camera.fsp", "camera.fps"),  # misspelt leaf, right namespace
        ("robot_nam", "robot_name"),
        ("q.exposur", "camera.settings.exposure"),  # far as a whole, close by its leaf
    ],
)
def test_suggests_the_closest_parameter(given: str, meant: str) -> None:
    assert suggestion(given, CANDIDATES) == f" (did you mean {meant!r}?)"


@pytest.mark.parametrize("given", ["zzz.qqq", "totally_unrelated", "x.y.z"])
def test_suggests_nothing_when_nothing_is_close(given: str) -> None:
    assert suggestion(given, CANDIDATES) == ""


SCHEMA = """\
genparams: 1
name: robot
parameters:
  arm:
    gain: {type: double, default: 1.0}
  base:
    gain: {type: double, default: 2.0}
"""


def test_check_params_reports_the_closest_of_two_same_leaves(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    schema = tmp_path / "robot.yaml"
    schema.write_text(SCHEMA, encoding="utf-8")
    params = tmp_path / "params.yaml"
    params.write_text("/**:\n  ros__parameters:\n    bse.gain: 2.5\n", encoding="utf-8")
    assert main(["check-params", str(schema), str(params)]) == 1
    assert capsys.readouterr().out == (
        f"{params}:3:5: bse.gain: unknown parameter (did you mean 'base.gain'?): "
        "ROS would ignore it\n"
    )
