"""Trailing underscores, copying and pickling, NaN, prefixes, undeclare, defaults, old names."""

from __future__ import annotations

import copy
import dataclasses
import math
import pickle
import types
from pathlib import Path
from typing import Any

import pytest
from rclpy.exceptions import ParameterImmutableException
from rclpy.parameter import Parameter

from genparams.runtime import Changes, ParameterDeclarationError
from genparams.runtime.core.errors import RemoteSetError
from tests.runtime.schemas import MOTION, SAFETY, generate
from tests.support import RosHarness

DOUBLE = Parameter.Type.DOUBLE


@pytest.fixture
def motion(tmp_path: Path) -> types.ModuleType:
    return generate(tmp_path, MOTION, "motion")


@pytest.fixture
def safety(tmp_path: Path) -> types.ModuleType:
    return generate(tmp_path, SAFETY, "safety")


def test_to_dict_keeps_a_real_trailing_underscore_and_round_trips(
    ros: RosHarness, motion: types.ModuleType
) -> None:
    node = ros.node()
    cfg = motion.MotionParams.declare(node)
    assert node.has_parameter("lambda_") and node.has_parameter("frame.from_")
    as_dict = cfg.to_dict()
    assert as_dict["lambda_"] == 0.1 and as_dict["frame"] == {"from_": "odom"}
    assert motion.MotionParams.defaults(as_dict) == cfg.snapshot()


def test_keyword_names_still_lose_the_underscore_genparams_added(tmp_path: Path) -> None:
    module = generate(
        tmp_path,
        "genparams: 1\nname: kw\nparameters:\n  lambda: {type: int, default: 1}\n",
        "kw",
    )
    snapshot = module.KwParams.defaults()
    assert snapshot.lambda_ == 1 and snapshot.to_dict() == {"lambda": 1}
    assert module.KwParams.defaults(snapshot.to_dict()) == snapshot


@dataclasses.dataclass(frozen=True)
class Holder:
    snapshot: Any
    label: str


def test_snapshots_copy_and_pickle_like_frozen_values(
    ros: RosHarness, motion: types.ModuleType
) -> None:
    node = ros.node()
    cfg = motion.MotionParams.declare(node)
    node.set_parameters([Parameter("max_speed", DOUBLE, 3.5)])
    snap = cfg.snapshot()
    assert copy.copy(snap) is snap and copy.deepcopy(snap) is snap
    restored = pickle.loads(pickle.dumps(snap))
    assert restored == snap and restored.max_speed == 3.5 and restored.frame.from_ == "odom"
    assert restored.snapshot() is restored  # a detached value, like defaults()
    held = dataclasses.asdict(Holder(snap, "x"))
    assert held["snapshot"] == snap
    # The live view copies to a snapshot of what it shows now.
    frozen = copy.deepcopy(cfg)
    node.set_parameters([Parameter("max_speed", DOUBLE, 4.5)])
    assert frozen.max_speed == 3.5 and cfg.max_speed == 4.5
    assert pickle.loads(pickle.dumps(cfg)).max_speed == 4.5


def test_nan_is_no_change(ros: RosHarness, motion: types.ModuleType) -> None:
    node = ros.node()
    cfg = motion.MotionParams.declare(node)
    seen: list[Changes[Any]] = []
    cfg.on_change(seen.append)
    snap = cfg.snapshot()
    assert math.isnan(snap.gain) and snap == snap and snap == motion.MotionParams.defaults()
    node.set_parameters([Parameter("gain", DOUBLE, math.nan)])
    node.set_parameters([Parameter("weights", Parameter.Type.DOUBLE_ARRAY, [1.0, math.nan])])
    assert seen == [] and cfg.snapshot() is snap
    node.set_parameters([Parameter("gain", DOUBLE, 1.0)])
    node.set_parameters([Parameter("gain", DOUBLE, math.nan)])
    first = seen[0].changed[0]
    assert math.isnan(first.old) and first.new == 1.0
    assert len(seen) == 2


def test_reapplying_the_same_params_file_is_no_reconfigure(
    ros: RosHarness, motion: types.ModuleType, tmp_path: Path
) -> None:
    params = tmp_path / "params.yaml"
    params.write_text(
        "/**:\n  ros__parameters:\n    gain: .nan\n    weights: [1.0, .nan]\n    max_speed: 3.0\n"
    )
    node = ros.node(args=["--params-file", str(params)])
    cfg = motion.MotionParams.declare(node)
    seen: list[Changes[Any]] = []
    cfg.on_change(seen.append)
    again = [
        Parameter("gain", DOUBLE, math.nan),
        Parameter("weights", Parameter.Type.DOUBLE_ARRAY, [1.0, math.nan]),
        Parameter("max_speed", DOUBLE, 3.0),
    ]
    assert ros.client(node).set_atomically(*again).successful
    assert seen == []


def test_several_classes_share_a_prefix_but_one_class_declares_once(
    ros: RosHarness, motion: types.ModuleType, safety: types.ModuleType, tmp_path: Path
) -> None:
    node = ros.node()
    cfg = motion.MotionParams.declare(node)
    other = safety.SafetyParams.declare(node)  # the root again, other names: fine
    assert (cfg.max_speed, other.mode) == (2.0, "normal")
    with pytest.raises(ParameterDeclarationError) as twice:
        motion.MotionParams.declare(node)
    assert tuple(map(str, twice.value.problems)) == (
        "MotionParams is already declared at the root: declare a class once per prefix "
        "and share the view it returns",
    )
    motion.MotionParams.declare(node, prefix="arm")  # another prefix: fine
    clash = generate(
        tmp_path,
        "genparams: 1\nname: clash\nparameters:\n  mode: {type: string, default: x}\n",
        "clash",
    )
    with pytest.raises(ParameterDeclarationError) as clashing:
        clash.ClashParams.declare(node)
    assert tuple(map(str, clashing.value.problems)) == (
        "mode: already declared on this node by SafetyParams",
    )


def test_undeclare_of_a_genparams_parameter_is_refused_like_the_services_refuse_it(
    ros: RosHarness, motion: types.ModuleType
) -> None:
    node = ros.node()
    cfg = motion.MotionParams.declare(node, prefix="base")
    with pytest.raises(ParameterImmutableException, match="cannot be undeclared"):
        node.undeclare_parameter("base.max_speed")
    with pytest.raises(ParameterImmutableException):
        node.undeclare_parameter("base.top_speed")  # an old name too
    assert node.has_parameter("base.max_speed") and cfg.max_speed == 2.0
    (refused,) = ros.client(node).set(Parameter("base.max_speed"))
    assert not refused.successful and "cannot be undeclared" in refused.reason
    node.declare_parameter("mine", 1)
    node.undeclare_parameter("mine")  # parameters of other code are untouched
    assert not node.has_parameter("mine")


def test_defaults_takes_nested_dicts_ints_for_doubles_and_says_what_failed(
    motion: types.ModuleType,
) -> None:
    made = motion.MotionParams.defaults({"max_speed": 3, "frame": {"from_": "map"}})
    assert made.max_speed == 3.0 and type(made.max_speed) is float
    assert made.frame.from_ == "map"
    assert motion.MotionParams.defaults({"top_speed": 4}).max_speed == 4.0
    with pytest.raises(ParameterDeclarationError) as bad:
        motion.MotionParams.defaults({"max_speed": 30})
    assert str(bad.value) == (
        "MotionParams.defaults(): cannot build motion parameters (1 problem):\n"
        "  - max_speed: value rejected: must be within [0.0, 10.0] (range), got 30.0"
    )


def test_remote_set_takes_old_names(ros: RosHarness, motion: types.ModuleType) -> None:
    node = ros.node()
    cfg = motion.MotionParams.declare(node)
    remote = motion.MotionParams.remote(ros.client_node, node.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)
    assert ros.wait(remote.set({"top_speed": 6})) is None
    assert cfg.max_speed == 6.0 and node.get_parameter("top_speed").value == 6.0
    with pytest.raises(RemoteSetError):
        ros.wait(remote.set({"top_speed": 60}))
