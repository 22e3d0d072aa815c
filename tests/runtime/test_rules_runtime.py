"""Cross-parameter rules on a real node: single sets, atomic sets, overrides at declare."""

from __future__ import annotations

import types
from pathlib import Path

import pytest
from rcl_interfaces.msg import SetParametersResult
from rclpy.parameter import Parameter

from genparams.runtime import Changes, ParameterDeclarationError
from tests.support import RosHarness, load_generated

MOTION = """\
genparams: 1
name: motion
parameters:
  min_speed: {type: double, default: 0.5, range: {min: 0.0, max: 10.0}}
  max_speed: {type: double, default: 2.0, range: {min: 0.0, max: 10.0}}
  width: {type: int, default: 640}
  height: {type: int, default: 480, validators: [{gt: 0}]}
  aspect_ratio: {type: double, default: 1.3333}
  topics: {type: string_array, default: [/a, /b]}
  weights: {type: double_array, default: [0.5, 0.5]}
rules:
  - name: speed_order
    check: min_speed <= max_speed
    description: The minimum speed cannot exceed the maximum.
  - name: aspect_matches
    check: abs(aspect_ratio - width / height) <= 0.01
  - name: one_weight_per_topic
    check: len(topics) == len(weights)
"""


@pytest.fixture
def module(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "motion.yaml"
    schema.write_text(MOTION)
    return load_generated(schema, tmp_path)


def _reason(result: SetParametersResult) -> str:
    assert not result.successful
    return str(result.reason)


def test_single_set_that_breaks_a_rule_is_rejected(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    cfg = module.MotionParams.declare(node)
    seen: list[Changes[object]] = []
    cfg.on_change(seen.append)
    client = ros.client(node)
    (result,) = client.set(Parameter("min_speed", value=3.0))
    assert _reason(result) == (
        "rule 'speed_order' broken: min_speed <= max_speed is false for "
        "min_speed=3.0, max_speed=2.0"
    )
    assert cfg.min_speed == 0.5 and node.get_parameter("min_speed").value == 0.5
    assert client.get("min_speed") == [0.5]
    assert seen == []
    # A value that keeps the rule passes; the rule reads the committed max_speed.
    (result,) = client.set(Parameter("min_speed", value=2.0))
    assert result.successful and cfg.min_speed == 2.0


def test_each_set_of_a_list_sees_the_ones_before_it(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    cfg = module.MotionParams.declare(node)
    first, second = ros.client(node).set(
        Parameter("max_speed", value=8.0), Parameter("min_speed", value=6.0)
    )
    assert first.successful and second.successful
    assert (cfg.min_speed, cfg.max_speed) == (6.0, 8.0)
    first, second = ros.client(node).set(
        Parameter("min_speed", value=9.0), Parameter("max_speed", value=9.5)
    )
    assert "rule 'speed_order' broken" in _reason(first)
    assert second.successful
    assert (cfg.min_speed, cfg.max_speed) == (6.0, 9.5)


def test_atomic_set_fixes_two_parameters_together(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node()
    cfg = module.MotionParams.declare(node)
    seen: list[Changes[object]] = []
    cfg.on_change(seen.append)
    client = ros.client(node)
    (alone,) = client.set(Parameter("width", value=800))
    assert _reason(alone) == (
        "rule 'aspect_matches' broken: abs(aspect_ratio - width / height) <= 0.01 is false for "
        "aspect_ratio=1.3333, width=800, height=480"
    )
    assert client.set_atomically(
        Parameter("width", value=800), Parameter("height", value=600)
    ).successful
    assert (cfg.width, cfg.height) == (800, 600)

    widescreen = [Parameter("width", value=1920), Parameter("height", value=1080)]
    assert "rule 'aspect_matches' broken" in _reason(client.set_atomically(*widescreen))
    assert (cfg.width, cfg.height) == (800, 600)
    assert client.set_atomically(*widescreen, Parameter("aspect_ratio", value=1.7778)).successful
    assert (cfg.width, cfg.height, cfg.aspect_ratio) == (1920, 1080, 1.7778)

    # Two rules broken at once: both are named.
    reason = _reason(
        client.set_atomically(Parameter("min_speed", value=5.0), Parameter("topics", value=["/a"]))
    )
    assert "rule 'speed_order' broken" in reason
    assert "rule 'one_weight_per_topic' broken: len(topics) == len(weights) is false" in reason
    assert [change.names for change in seen] == [
        {"width", "height"},
        {"width", "height", "aspect_ratio"},
    ]


def test_descriptors_state_the_rules_that_read_them(
    ros: RosHarness, module: types.ModuleType
) -> None:
    """``ros2 param describe`` shows a parameter's rules after its own constraints."""
    node = ros.node()
    module.MotionParams.declare(node, prefix="base")
    described = ros.client(node).describe("base.min_speed", "base.height", "base.weights")
    by_name = {d.name: d.additional_constraints for d in described}
    assert by_name == {
        "base.min_speed": "rule speed_order: min_speed <= max_speed "
        "(The minimum speed cannot exceed the maximum.)",
        "base.height": "must be > 0; "
        "rule aspect_matches: abs(aspect_ratio - width / height) <= 0.01",
        "base.weights": "rule one_weight_per_topic: len(topics) == len(weights)",
    }


def test_rule_reasons_name_prefixed_parameters(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node()
    cfg = module.MotionParams.declare(node, prefix="base")
    (result,) = ros.client(node).set(Parameter("base.max_speed", value=0.25))
    assert _reason(result) == (
        "rule 'speed_order' broken: min_speed <= max_speed is false for "
        "base.min_speed=0.5, base.max_speed=0.25"
    )
    assert cfg.max_speed == 2.0


def test_overrides_that_break_rules_are_reported_with_every_other_problem(
    ros: RosHarness, module: types.ModuleType
) -> None:
    node = ros.node(args=["-p", "min_speed:=5.0", "-p", "weights:=[1.0]", "-p", "height:=0"])
    with pytest.raises(ParameterDeclarationError) as caught:
        module.MotionParams.declare(node)
    assert tuple(map(str, caught.value.problems)) == (
        "height: override rejected: must be > 0 (gt), got 0",
        "rule 'speed_order' broken: min_speed <= max_speed is false for "
        "min_speed=5.0, max_speed=2.0",
        "rule 'one_weight_per_topic' broken: len(topics) == len(weights) is false for "
        "topics=('/a', '/b'), weights=(1.0,)",
    )
    assert not node.has_parameter("min_speed")


def test_overrides_that_keep_the_rules_declare(ros: RosHarness, module: types.ModuleType) -> None:
    node = ros.node(args=["-p", "min_speed:=5.0", "-p", "max_speed:=6.0"])
    cfg = module.MotionParams.declare(node)
    assert (cfg.min_speed, cfg.max_speed) == (5.0, 6.0)


def test_defaults_check_rules_without_ros(module: types.ModuleType) -> None:
    assert module.MotionParams.defaults({"min_speed": 1.0}).min_speed == 1.0
    with pytest.raises(ParameterDeclarationError, match="rule 'speed_order' broken"):
        module.MotionParams.defaults({"min_speed": 3.0})


def test_rules_hold_when_set_through_an_old_name(ros: RosHarness, tmp_path: Path) -> None:
    schema = tmp_path / "renamed.yaml"
    schema.write_text(
        "genparams: 1\nname: renamed\nparameters:\n"
        "  min_speed: {type: double, default: 0.5}\n"
        "  max_speed: {type: double, default: 2.0, aliases: [speed_limit]}\n"
        "rules:\n  - {name: speed_order, check: min_speed <= max_speed}\n"
    )
    module = load_generated(schema, tmp_path)
    node = ros.node()
    cfg = module.RenamedParams.declare(node)
    (result,) = ros.client(node).set(Parameter("speed_limit", value=0.25))
    assert "rule 'speed_order' broken" in _reason(result)
    assert cfg.max_speed == 2.0 and node.get_parameter("speed_limit").value == 2.0
    (result,) = ros.client(node).set(Parameter("speed_limit", value=3.0))
    assert result.successful and cfg.max_speed == 3.0
