"""Maps whose entries sit beside other names (schema key "*"), set and read on real nodes."""

from __future__ import annotations

import types
from typing import Any

import pytest
from rclpy.parameter import Parameter

from genparams.runtime import Changes
from tests.runtime.schemas import generate
from tests.support import RosHarness

BESIDE = """\
genparams: 1
name: beside
parameters:
  joints: {type: string_array, default: [shoulder, elbow]}
  interfaces: {type: string_array, default: [x-1]}
  "*":                      # <interface>.scale, beside the top-level names
    for_each: interfaces
    scale: {type: double, default: 1.0}
  constraints:
    goal_time: {type: double, default: 0.5}
    from: {type: string, default: base}
    snapshot: {type: bool, default: false}
    inner:
      depth: {type: int, default: 1}
    "*":                    # constraints.<joint>.goal, beside goal_time
      for_each: joints
      goal: {type: double, default: 0.1, validators: [{ge: 0.0}]}
  weights:
    "*":                    # two map levels in a row: weights.<joint>.<interface>.w
      for_each: joints
      "*":
        for_each: interfaces
        w: {type: double, default: 1.0}
  arm:
    wrist:
      tilt: {type: double, default: 0.0}
      "*":                  # arm.wrist.<joint>.speed, beside tilt
        for_each: joints
        speed: {type: double, default: 1.0}
  defaults:
    strictness: {type: int, default: 1}
  snapshot: {type: bool, default: false}
"""

# Parameter, value set, how the live view reads it back.
SETS = [
    ("x-1.scale", 2.5, lambda cfg: cfg["x-1"].scale),
    ("snapshot", True, lambda cfg: cfg.snapshot_),
    ("defaults.strictness", 4, lambda cfg: cfg.defaults_.strictness),
    ("constraints.goal_time", 2.0, lambda cfg: cfg.constraints.goal_time),
    ("constraints.from", "tool", lambda cfg: cfg.constraints.from_),
    ("constraints.snapshot", True, lambda cfg: cfg.constraints.snapshot),
    ("constraints.inner.depth", 3, lambda cfg: cfg.constraints.inner.depth),
    ("constraints.elbow.goal", 0.7, lambda cfg: cfg.constraints["elbow"].goal),
    ("weights.elbow.x-1.w", 4.0, lambda cfg: cfg.weights["elbow"]["x-1"].w),
    ("arm.wrist.tilt", 0.5, lambda cfg: cfg.arm.wrist.tilt),
    ("arm.wrist.shoulder.speed", 3.0, lambda cfg: cfg.arm.wrist["shoulder"].speed),
]


@pytest.fixture(scope="module")
def beside(tmp_path_factory: pytest.TempPathFactory) -> types.ModuleType:
    return generate(tmp_path_factory.mktemp("beside"), BESIDE, "beside")


@pytest.mark.parametrize(("name", "value", "read"), SETS, ids=[s[0] for s in SETS])
def test_a_set_reaches_the_live_view_and_the_change_record(
    ros: RosHarness, beside: types.ModuleType, name: str, value: object, read: object
) -> None:
    node = ros.node()
    cfg = beside.BesideParams.declare(node)
    seen: list[Changes[Any]] = []
    cfg.on_change(seen.append)
    old = read(cfg)  # type: ignore[operator]
    result = node.set_parameters([Parameter(name, value=value)])[0]
    assert result.successful, result.reason
    assert read(cfg) == value and read(cfg.snapshot()) == value  # type: ignore[operator]
    assert [(c.name, c.old, c.new) for c in seen[0]] == [(name, old, value)]
    assert node.get_parameter(name).value == value


@pytest.mark.parametrize(
    ("keys", "reason"),
    [
        (
            Parameter("joints", value=["shoulder", "goal_time"]),
            "joints: item 'goal_time' is already a name in constraints: an entry cannot "
            "share it (for_each)",
        ),
        (
            Parameter("joints", value=["elbow", "tilt"]),
            "joints: item 'tilt' is already a name in arm.wrist: an entry cannot "
            "share it (for_each)",
        ),
        (
            Parameter("joints", value=["inner"]),
            "joints: item 'inner' is already a name in constraints: an entry cannot "
            "share it (for_each)",
        ),
        (
            Parameter("interfaces", value=["joints"]),
            "interfaces: item 'joints' is already a name in the top level: an entry cannot "
            "share it (for_each)",
        ),
        (
            Parameter("interfaces", value=["defaults"]),
            "interfaces: item 'defaults' is already a name in the top level: an entry cannot "
            "share it (for_each)",
        ),
        (  # entries and fields share the namespace's attributes: goal-time is goal_time
            Parameter("joints", value=["goal-time"]),
            "joints: item 'goal-time' and 'goal_time' of constraints share the Python "
            "attribute 'goal_time': an entry cannot share it (for_each)",
        ),
        (
            Parameter("joints", value=["from_"]),
            "joints: item 'from_' and 'from' of constraints share the Python attribute "
            "'from_': an entry cannot share it (for_each)",
        ),
    ],
)
def test_a_key_cannot_repeat_a_name_beside_its_entries(
    ros: RosHarness, beside: types.ModuleType, keys: Parameter, reason: str
) -> None:
    node = ros.node()
    cfg = beside.BesideParams.declare(node)
    result = node.set_parameters([keys])[0]
    assert (result.successful, result.reason) == (False, reason)
    assert list(cfg.constraints) == ["shoulder", "elbow"] and list(cfg) == ["x-1"]


def test_a_key_may_repeat_a_name_of_another_namespace(
    ros: RosHarness, beside: types.ModuleType
) -> None:
    node = ros.node()
    cfg = beside.BesideParams.declare(node)
    keys = ["strictness", "depth", "w", "scale"]  # names deeper or elsewhere
    result = node.set_parameters([Parameter("joints", value=keys)])[0]
    assert result.successful, result.reason
    assert list(cfg.constraints) == keys and list(cfg.weights) == keys
    assert node.get_parameter("constraints.strictness.goal").value == 0.1
    assert node.get_parameter("weights.depth.x-1.w").value == 1.0
    result = node.set_parameters([Parameter("interfaces", value=["goal_time", "inner"])])[0]
    assert result.successful, result.reason
    assert list(cfg) == ["goal_time", "inner"] and cfg["inner"].scale == 1.0


def test_entries_sit_in_the_dict_beside_the_plain_names(beside: types.ModuleType) -> None:
    snapshot = beside.BesideParams.defaults({"constraints": {"elbow": {"goal": 0.2}}})
    assert snapshot.to_dict()["constraints"] == {
        "goal_time": 0.5,
        "from": "base",
        "snapshot": False,
        "inner": {"depth": 1},
        "shoulder": {"goal": 0.1},
        "elbow": {"goal": 0.2},
    }


def test_values_with_the_same_entries_are_equal(beside: types.ModuleType) -> None:
    cls = beside.BesideParams
    changed = cls.defaults({"weights.elbow.x-1.w": 2.0})
    assert cls.defaults() == cls.defaults() and changed != cls.defaults()
    assert changed.weights["shoulder"] == cls.defaults().weights["shoulder"]
    assert changed.weights["elbow"] != cls.defaults().weights["elbow"]
