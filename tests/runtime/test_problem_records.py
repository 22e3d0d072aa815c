"""The runtime's problems are records, written one way: a node's refusal of a set, its
refusal to start and a remote client's refusal before sending read alike."""

from __future__ import annotations

import types
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

from genparams.errors import ParameterProblem, render_problem, render_problems
from genparams.runtime import ParameterDeclarationError, RemoteSetError
from tests.support import ROOT, RosHarness, load_generated

ARM = ROOT / "examples" / "arm" / "arm.yaml"
CAMERA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"


@pytest.fixture
def arm(tmp_path: Path) -> types.ModuleType:
    return load_generated(ARM, tmp_path)


def test_a_node_and_a_remote_client_word_a_refusal_alike(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    target = ros.node()
    cfg = arm.ArmParams.declare(target, prefix="left")
    refused = target.set_parameters_atomically(
        [
            Parameter("left.gains.shoulder.i", value=-2.0),
            Parameter("left.gains.elbow.p", value=-1.0),
        ]
    )
    assert not refused.successful and cfg.gains["elbow"].p == 1.0
    remote = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name(), "left")
    with pytest.raises(RemoteSetError) as caught:
        remote.set({"gains.shoulder.i": -2.0, "gains.elbow.p": -1.0}).result()
    problems = caught.value.problems
    assert [(p.key, p.rule) for p in problems] == [
        ("left.gains.shoulder.i", ""),
        ("left.gains.elbow.p", ""),
    ]
    assert refused.reason == caught.value.reason == render_problems(problems)
    assert refused.reason == (
        "left.gains.shoulder.i: must be >= 0.0 (ge), got -2.0; "
        "left.gains.elbow.p: must be >= 0.0 (ge), got -1.0"
    )


def test_a_refused_set_shows_every_character_of_the_value(ros: RosHarness, tmp_path: Path) -> None:
    module = load_generated(CAMERA, tmp_path)
    node = ros.node(args=["-p", "serial:=ABCD1234"])
    module.CameraDriverParams.declare(node)
    # A Hangul filler prints as nothing, and repr() leaves it as it is.
    (result,) = node.set_parameters([Parameter("camera.encoding", value="rgb8\u3164")])
    assert not result.successful
    assert result.reason == (
        "camera.encoding: must be one of ['rgb8', 'mono8', 'bgr8'] (one_of), got 'rgb8\\u3164'"
    )


def test_a_node_refusing_to_start_lists_records_one_line_each(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    node = ros.node(args=["-p", "max_speed:=50.0", "-p", "gains.elbow.p:=-1.0"])
    with pytest.raises(ParameterDeclarationError) as caught:
        arm.ArmParams.declare(node)
    problems = caught.value.problems
    assert all(isinstance(p, ParameterProblem) and p.place == "" for p in problems)
    assert [p.key for p in problems] == ["max_speed", "gains.elbow.p"]
    lines = str(caught.value).split("\n")
    assert lines[1:] == [f"  - {render_problem(p)}" for p in problems]
    assert problems[0].message == "override rejected: must be within [0.0, 3.0] (range), got 50.0"


def test_defaults_name_each_unknown_parameter_as_a_record(arm: types.ModuleType) -> None:
    with pytest.raises(ParameterDeclarationError) as caught:
        arm.ArmParams.defaults({"max_sped": 1.0})
    assert caught.value.problems == (ParameterProblem("max_sped", "no such parameter"),)


def test_a_set_that_passes_builds_no_record(
    ros: RosHarness, arm: types.ModuleType, monkeypatch: pytest.MonkeyPatch
) -> None:
    built: list[ParameterProblem] = []

    class Counted(ParameterProblem):
        __slots__ = ()

        def __init__(self, *args: str, **kwargs: str) -> None:
            super().__init__(*args, **kwargs)
            built.append(self)

    node = ros.node()
    cfg = arm.ArmParams.declare(node)
    modules = (
        "node.binding",
        "core.rule_check",
        "node.lifecycle",
        "node.mapped",
        "node.consistency",
    )
    for module in modules:
        monkeypatch.setattr(f"genparams.runtime.{module}.ParameterProblem", Counted)
    for value in (0.5, 2.0, 1.0):
        (result,) = node.set_parameters([Parameter("gains.elbow.p", value=value)])
        assert result.successful
    assert cfg.gains["elbow"].p == 1.0 and built == []
    (result,) = node.set_parameters([Parameter("gains.elbow.p", value=-1.0)])
    assert not result.successful and [p.key for p in built] == ["gains.elbow.p"]
