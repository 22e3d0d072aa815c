"""What a remote read or set says when the target or the values do not fit the schema."""

from __future__ import annotations

import types
from pathlib import Path

import pytest

from genparams.runtime import RemoteParameterError, RemoteSetError
from tests.support import ROOT, RosHarness, load_generated


@pytest.fixture
def arm(tmp_path: Path) -> types.ModuleType:
    return load_generated(ROOT / "examples" / "arm" / "arm.yaml", tmp_path)


def test_every_rejected_value_is_named_in_one_reason(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    target = ros.node()
    arm.ArmParams.declare(target, prefix="left")
    remote = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name(), "left")
    future = remote.set({"max_sped": 1.0, "max_speed": 50.0, "gains.elbow.p": -1.0})
    with pytest.raises(RemoteSetError) as caught:
        future.result()
    assert caught.value.reason == (
        "max_sped: no such parameter in arm (did you mean 'max_speed'?); "
        "left.max_speed: must be within [0.0, 3.0] (range), got 50.0; "
        "left.gains.elbow.p: must be >= 0.0 (ge), got -1.0"
    )


def test_an_empty_array_is_sent_with_its_schema_type(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    target = ros.node()
    cfg = arm.ArmParams.declare(target)
    remote = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)
    assert ros.wait(remote.set({"joints": []})) is None
    assert cfg.joints == ()
    assert dict(cfg.gains) == {}


def test_only_the_undeclared_names_under_a_prefix_are_reported(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    target = ros.node()
    target.declare_parameter("left.joints", ["shoulder"])
    target.declare_parameter("left.max_speed", 1.0)
    name = target.get_fully_qualified_name()
    remote = arm.ArmParams.remote(ros.node(), name, "left")
    assert remote.wait_for_services(timeout_sec=10.0)
    with pytest.raises(RemoteParameterError) as caught:
        ros.wait(remote.get())
    assert str(caught.value) == f"{name} does not follow arm: left.legacy_mode: not declared"
