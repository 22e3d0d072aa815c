"""Deprecated parameters and old names (aliases) on real nodes, through the parameter services."""

from __future__ import annotations

import os
import subprocess
import sys
import types
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

from genparams.runtime import ParameterDeclarationError
from tests.support import ROOT, RosHarness, load_generated

DRIVE = """\
genparams: 1
name: drive
parameters:
  max_speed:
    type: double
    default: 1.0
    description: Top speed.
    unit: m/s
    range: {min: 0.0, max: 3.0}
    aliases: [speed_limit, limits.speed]
  legacy_mode:
    type: bool
    default: false
    deprecated: "no longer used; the controller picks the mode"
  wheels:
    base: {type: double, default: 0.5, aliases: [wheel_base]}
"""


@pytest.fixture
def drive(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "drive.yaml"
    schema.write_text(DRIVE)
    return load_generated(schema, tmp_path)


def warnings_about(stderr: str, name: str) -> list[str]:
    return [line for line in stderr.splitlines() if f"parameter '{name}' is deprecated" in line]


def test_deprecated_override_warns_once(
    ros: RosHarness, drive: types.ModuleType, capfd: pytest.CaptureFixture[str]
) -> None:
    node = ros.node(args=["-p", "legacy_mode:=true"])
    cfg = drive.DriveParams.declare(node)
    client = ros.client(node)
    assert cfg.legacy_mode is True
    assert client.set(Parameter("legacy_mode", value=False))[0].successful
    assert client.set(Parameter("legacy_mode", value=True))[0].successful
    (line,) = warnings_about(capfd.readouterr().err, "legacy_mode")
    assert "WARN" in line and line.endswith(
        "parameter 'legacy_mode' is deprecated: no longer used; the controller picks the mode"
    )


def test_deprecated_parameter_warns_on_first_runtime_set_only(
    ros: RosHarness, drive: types.ModuleType, capfd: pytest.CaptureFixture[str]
) -> None:
    node = ros.node()
    drive.DriveParams.declare(node)
    client = ros.client(node)
    assert warnings_about(capfd.readouterr().err, "legacy_mode") == []  # default: no warning
    assert client.set(Parameter("max_speed", value=2.0))[0].successful
    assert warnings_about(capfd.readouterr().err, "legacy_mode") == []
    assert client.set(Parameter("legacy_mode", value=True))[0].successful
    assert client.set(Parameter("legacy_mode", value=False))[0].successful
    assert len(warnings_about(capfd.readouterr().err, "legacy_mode")) == 1


def test_old_name_is_declared_like_the_new_one(ros: RosHarness, drive: types.ModuleType) -> None:
    node = ros.node()
    drive.DriveParams.declare(node)
    new, old, nested = ros.client(node).describe("max_speed", "speed_limit", "limits.speed")
    assert old.description == "Deprecated: old name of max_speed; use that. Top speed. [m/s]"
    assert old.type == new.type and old.floating_point_range == new.floating_point_range
    assert nested.description.startswith("Deprecated: old name of max_speed;")
    assert ros.client(node).get("max_speed", "speed_limit", "limits.speed") == [1.0, 1.0, 1.0]


def test_sets_under_either_name_keep_both_equal(
    ros: RosHarness, drive: types.ModuleType, capfd: pytest.CaptureFixture[str]
) -> None:
    node = ros.node()
    cfg = drive.DriveParams.declare(node)
    client = ros.client(node)
    names = ("max_speed", "speed_limit", "limits.speed")

    assert client.set(Parameter("speed_limit", value=2.0))[0].successful
    assert client.get(*names) == [2.0, 2.0, 2.0] and cfg.max_speed == 2.0
    assert client.set(Parameter("max_speed", value=0.5))[0].successful
    assert client.get(*names) == [0.5, 0.5, 0.5] and cfg.max_speed == 0.5
    assert client.set(Parameter("speed_limit", value=1.5))[0].successful
    (result,) = client.set(Parameter("speed_limit", value=9.0))  # the range holds for old names
    assert result.reason == "speed_limit: must be within [0.0, 3.0] (range), got 9.0"
    assert client.get(*names) == [1.5, 1.5, 1.5] and cfg.max_speed == 1.5

    result = client.set_atomically(
        Parameter("max_speed", value=1.0), Parameter("speed_limit", value=2.0)
    )
    assert (
        result.reason
        == "speed_limit: is the old name of max_speed, but was given a different value"
    )
    assert cfg.max_speed == 1.5

    err = capfd.readouterr().err
    (line,) = warnings_about(err, "speed_limit")
    assert line.endswith(
        "parameter 'speed_limit' is deprecated: it was renamed to 'max_speed'; use 'max_speed'"
    )
    assert warnings_about(err, "max_speed") == []


def test_override_under_an_old_name_applies(
    ros: RosHarness, drive: types.ModuleType, tmp_path: Path, capfd: pytest.CaptureFixture[str]
) -> None:
    params = tmp_path / "params.yaml"
    params.write_text("/**:\n  ros__parameters:\n    wheel_base: 0.8\n    limits: {speed: 2.5}\n")
    node = ros.node(args=["--params-file", str(params)])
    cfg = drive.DriveParams.declare(node, prefix="")
    assert (cfg.wheels.base, cfg.max_speed) == (0.8, 2.5)
    assert ros.client(node).get("wheels.base", "wheel_base", "limits.speed") == [0.8, 0.8, 2.5]
    err = capfd.readouterr().err
    assert len(warnings_about(err, "wheel_base")) == len(warnings_about(err, "limits.speed")) == 1


def test_conflicting_old_and_new_overrides_refuse_to_start(
    ros: RosHarness, drive: types.ModuleType
) -> None:
    node = ros.node(
        args=[
            "-p",
            "max_speed:=1.0",
            "-p",
            "speed_limit:=2.0",
            "-p",
            "wheel_base:=0.7",
            "-p",
            "wheels.base:=0.7",
        ]
    )
    with pytest.raises(ParameterDeclarationError) as caught:
        drive.DriveParams.declare(node)
    assert tuple(map(str, caught.value.problems)) == (
        "max_speed: given as 1.0 and under its old name speed_limit as 2.0; keep only max_speed",
    )
    assert not node.has_parameter("wheels.base")


def test_old_names_under_a_prefix(ros: RosHarness, drive: types.ModuleType) -> None:
    node = ros.node(args=["-p", "rear.speed_limit:=2.0"])
    cfg = drive.DriveParams.declare(node, prefix="rear")
    client = ros.client(node)
    assert cfg.max_speed == 2.0 and client.get("rear.max_speed") == [2.0]
    assert client.set(Parameter("rear.limits.speed", value=0.25))[0].successful
    assert cfg.max_speed == 0.25 and client.get("rear.speed_limit") == [0.25]


def test_defaults_accept_old_names(drive: types.ModuleType) -> None:
    assert drive.DriveParams.defaults({"wheel_base": 0.9}).wheels.base == 0.9


def test_arm_demo_runs() -> None:
    """The command of the "Mapped parameters" section of docs/runtime-guide.md."""
    result = subprocess.run(
        [sys.executable, str(ROOT / "examples" / "arm" / "demo.py")],
        capture_output=True,
        text=True,
        timeout=120,
        env=dict(os.environ),
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        "max_speed = 2.0 (given as speed_limit in params.yaml)",
        "  cfg.gains = {'shoulder': (1.0, 0.0), 'elbow': (1.0, 0.0)}",
        "  node parameters under gains: ['elbow.i', 'elbow.p', 'shoulder.i', 'shoulder.p']",
        "set joints := [shoulder, wrist, left-arm]",
        "  cfg.gains = {'shoulder': (1.0, 0.0), 'wrist': (2.5, 0.0), 'left-arm': (1.0, 0.1)}",
        "  node parameters under gains: ['left-arm.i', 'left-arm.p', 'shoulder.i', 'shoulder.p', "
        "'wrist.i', 'wrist.p']",
        "set joints := [left.arm] -> rejected: joints: item 0 'left.arm' cannot name an entry "
        "of gains: use any text but '.', '*', spaces and control characters (for_each)",
        "set speed_limit := 0.5 -> max_speed, speed_limit = [0.5, 0.5]; cfg: 0.5",
    ]
    assert len(warnings_about(result.stderr, "speed_limit")) == 1
