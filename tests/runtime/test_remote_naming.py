"""A remote client names its target as ROS resolves it, and says so in its repr."""

from __future__ import annotations

import types
from pathlib import Path

import pytest

from genparams.runtime.remote.client import RemoteParams
from tests.support import ROOT, RosHarness, load_generated


@pytest.fixture
def arm(tmp_path: Path) -> types.ModuleType:
    return load_generated(ROOT / "examples" / "arm" / "arm.yaml", tmp_path)


@pytest.mark.parametrize(
    ("namespace", "target", "prefix", "shown"),
    [
        ("/", "arm", "", "ArmParams.remote('/arm')"),
        ("/robot", "arm", "", "ArmParams.remote('/robot/arm')"),
        ("/robot", "arm", "left", "ArmParams.remote('/robot/arm', prefix='left')"),
        ("/robot", "/other/arm", "", "ArmParams.remote('/other/arm')"),
        ("/lidarX", "arm", "", "ArmParams.remote('/lidarX/arm')"),
    ],
)
def test_the_target_is_resolved_in_the_client_namespace(
    ros: RosHarness, arm: types.ModuleType, namespace: str, target: str, prefix: str, shown: str
) -> None:
    client = ros.node(namespace=namespace)
    remote = arm.ArmParams.remote(client, target, prefix)
    assert repr(remote) == shown
    assert remote.target == shown.split("'")[1]


def test_waiting_for_a_node_that_is_not_there_ends_at_the_timeout(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    remote = arm.ArmParams.remote(ros.node(), "/nobody_serves_this")
    assert remote.wait_for_services(timeout_sec=0.2) is False


def test_a_client_built_by_hand_has_no_prefix_unless_given(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    remote = RemoteParams(arm.ArmParams, ros.node(), "/arm")
    assert repr(remote) == "ArmParams.remote('/arm')"
    assert remote.full_name("max_speed") == "max_speed"
