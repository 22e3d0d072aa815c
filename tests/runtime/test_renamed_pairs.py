"""Both names of renamed parameters in one request: one value each pair, one result each name."""

from __future__ import annotations

import types

import pytest
from rclpy.parameter import Parameter

from tests.runtime.schemas import generate
from tests.support import RosHarness

RENAMED = """\
genparams: 1
name: renamed
parameters:
  speed: {type: double, default: 1.0, aliases: [velocity]}
  gain: {type: double, default: 2.0, aliases: [kp]}
"""


@pytest.fixture(scope="module")
def renamed(tmp_path_factory: pytest.TempPathFactory) -> types.ModuleType:
    return generate(tmp_path_factory.mktemp("renamed"), RENAMED, "renamed")


@pytest.mark.parametrize(
    ("request_", "reason"),
    [
        (
            [Parameter("velocity", value=3.0), Parameter("speed", value=4.0)],
            "velocity: is the old name of speed, but was given a different value",
        ),
        (
            [
                Parameter("velocity", value=3.0),
                Parameter("speed", value=4.0),
                Parameter("kp", value=3.0),
                Parameter("gain", value=4.0),
            ],
            "kp: is the old name of gain, but was given a different value; "
            "velocity: is the old name of speed, but was given a different value",
        ),
    ],
    ids=["second pair", "both pairs"],
)
def test_both_names_with_different_values_are_refused(
    ros: RosHarness, renamed: types.ModuleType, request_: list[Parameter], reason: str
) -> None:
    node = ros.node()
    cfg = renamed.RenamedParams.declare(node)
    result = node.set_parameters_atomically(request_)
    assert (result.successful, result.reason) == (False, reason)
    assert (cfg.speed, cfg.gain) == (1.0, 2.0)


def test_both_names_with_one_value_set_once_each(
    ros: RosHarness, renamed: types.ModuleType
) -> None:
    node = ros.node()
    cfg = renamed.RenamedParams.declare(node)
    results = node.set_parameters([Parameter("kp", value=5.0), Parameter("gain", value=5.0)])
    assert [r.successful for r in results] == [True, True]
    assert cfg.gain == 5.0 and node.get_parameter("kp").value == 5.0
