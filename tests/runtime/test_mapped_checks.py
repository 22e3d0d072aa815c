"""What a mapped group checks in the on-set round, for a class declared under a prefix."""

from __future__ import annotations

import types

import pytest
from rcl_interfaces.msg import SetParametersResult
from rclpy.parameter import Parameter

from tests.runtime.schemas import generate
from tests.support import RosHarness

KEYS = """\
genparams: 1
name: keys
parameters:
  rate: {type: double, default: 10.0}
  joints: {type: string_array, default: [shoulder]}
  fingers: {type: string_array, default: [thumb]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0, validators: [{ge: 0.0}]}
  tips:
    for_each: fingers
    force: {type: double, default: 0.5}
"""


@pytest.fixture(scope="module")
def keys(tmp_path_factory: pytest.TempPathFactory) -> types.ModuleType:
    return generate(tmp_path_factory.mktemp("keys"), KEYS, "keys")


def test_a_parameter_outside_the_prefix_is_no_entry(
    ros: RosHarness, keys: types.ModuleType
) -> None:
    node = ros.node()
    keys.KeysParams.declare(node, "arm")
    node.declare_parameter("gains.wrist.p", 1.0)  # an entry's shape, at the root
    result = node.set_parameters([Parameter("gains.wrist.p", value=2.0)])[0]
    assert result.successful, result.reason
    assert node.get_parameter("gains.wrist.p").value == 2.0


def test_a_refused_change_of_keys_names_the_keys_it_changes(
    ros: RosHarness, keys: types.ModuleType
) -> None:
    node = ros.node(args=["-p", "arm.gains.wrist.p:=-1.0"])
    cfg = keys.KeysParams.declare(node, "arm")
    result = node.set_parameters_atomically(
        [
            Parameter("arm.rate", value=5.0),
            Parameter("arm.joints", value=["wrist"]),
            Parameter("arm.fingers", value=["index"]),
        ]
    )
    assert (result.successful, result.reason) == (
        False,
        "arm.joints, arm.fingers: cannot declare the new entries: "
        "arm.gains.wrist.p: override rejected: must be >= 0.0 (ge), got -1.0",
    )
    assert (cfg.rate, cfg.joints, list(cfg.gains)) == (10.0, ("shoulder",), ["shoulder"])


def test_another_callback_sees_the_entries_a_change_of_keys_removes(
    ros: RosHarness, keys: types.ModuleType
) -> None:
    node = ros.node()
    cfg = keys.KeysParams.declare(node, "arm")

    def keep_shoulder(parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.name == "arm.gains.shoulder.p" and parameter.value is None:
                return SetParametersResult(successful=False, reason="shoulder stays")
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(keep_shoulder)
    result = node.set_parameters([Parameter("arm.joints", value=["elbow"])])[0]
    assert (result.successful, result.reason) == (
        False,
        "arm.joints: the new entries were refused: shoulder stays",
    )
    assert list(cfg.gains) == ["shoulder"] and node.has_parameter("arm.gains.shoulder.p")
