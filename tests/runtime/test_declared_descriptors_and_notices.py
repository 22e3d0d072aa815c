"""What a node shows right after declare(): descriptors, start-up problems and notices."""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import pytest
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime import ParameterDeclarationError
from genparams.runtime.core.errors import DetachedSnapshotError
from tests.support import RosHarness, load_generated

SCHEMA = """\
genparams: 1
name: rig
parameters:
  frame: {type: string, default: base_link, read_only: true}
  ticks: {type: int, default: 10, range: {min: 0, max: 100, step: 5}}
  gain: {type: double, default: 1.0}
  label: {type: string, default: x}
  legacy_mode:
    type: bool
    default: false
    deprecated: "no longer used"
  top_speed: {type: double, default: 1.0, aliases: [speed_limit]}
  names: {type: string_array, default: [a]}
"""


@pytest.fixture
def rig(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "rig.yaml"
    schema.write_text(SCHEMA, encoding="utf-8")
    return load_generated(schema, tmp_path)


def test_descriptors_show_read_only_fixed_type_and_integer_step(
    ros: RosHarness, rig: types.ModuleType
) -> None:
    node = ros.node()
    rig.RigParams.declare(node)
    frame, ticks = ros.client(node).describe("frame", "ticks")
    assert frame.read_only is True and frame.dynamic_typing is False
    assert ticks.read_only is False and ticks.dynamic_typing is False
    (integer_range,) = ticks.integer_range
    assert (integer_range.from_value, integer_range.to_value, integer_range.step) == (0, 100, 5)


def test_every_wrongly_typed_start_value_is_reported(
    ros: RosHarness, rig: types.ModuleType
) -> None:
    node = ros.node(args=["-p", "gain:=fast", "-p", "label:=3"])
    with pytest.raises(ParameterDeclarationError) as caught:
        rig.RigParams.declare(node)
    problems = caught.value.problems
    assert [problem.key for problem in problems] == ["gain", "label"]


def test_on_change_of_a_snapshot_names_the_live_view(
    ros: RosHarness, rig: types.ModuleType
) -> None:
    snapshot = rig.RigParams.declare(ros.node()).snapshot()
    with pytest.raises(DetachedSnapshotError) as caught:
        snapshot.on_change(lambda *_: None)
    assert str(caught.value) == (
        "on_change needs the live view returned by declare(), not a snapshot"
    )


def test_start_values_warn_at_declare_with_full_names(
    ros: RosHarness, rig: types.ModuleType, capfd: pytest.CaptureFixture[str]
) -> None:
    node = ros.node(args=["-p", "cam.legacy_mode:=true", "-p", "cam.speed_limit:=2.0"])
    rig.RigParams.declare(node, "cam")
    err = capfd.readouterr().err
    assert err.count("parameter 'cam.legacy_mode' is deprecated: no longer used") == 1
    assert (
        err.count(
            "parameter 'cam.speed_limit' is deprecated: it was renamed to 'cam.top_speed'; "
            "use 'cam.top_speed'"
        )
        == 1
    )


def test_values_rclpy_declared_from_overrides_are_taken_over(
    ros: RosHarness, rig: types.ModuleType
) -> None:
    node = ros.node(args=["-p", "gain:=2.5"], automatically_declare_parameters_from_overrides=True)
    cfg = rig.RigParams.declare(node)
    assert cfg.gain == 2.5
    (gain,) = ros.client(node).describe("gain")
    assert gain.dynamic_typing is False


def test_declare_publishes_the_schema_unless_told_not_to(
    ros: RosHarness, rig: types.ModuleType
) -> None:
    topic = "/genparams/schema"
    publishing = ros.node()
    rig.RigParams.declare(publishing)
    quiet = ros.node()
    rig.RigParams.declare(quiet, publish_schema=False)

    def schema_topics(node: Node) -> list[str]:
        return [
            name
            for name, _ in node.get_publisher_names_and_types_by_node(node.get_name(), "/")
            if name.endswith(topic)
        ]

    assert schema_topics(publishing) == [f"/{publishing.get_name()}{topic}"]
    assert schema_topics(quiet) == []


def test_a_default_a_custom_validator_rejects_is_reported_as_the_default(
    ros: RosHarness, tmp_path: Path
) -> None:
    schema = tmp_path / "odd.yaml"
    schema.write_text(
        "genparams: 1\nname: odd\nparameters:\n"
        "  lanes: {type: int, default: 3, validators: [{custom: 'tests.custom_checks:is_even'}]}\n",
        encoding="utf-8",
    )
    module = load_generated(schema, tmp_path)
    with pytest.raises(ParameterDeclarationError) as caught:
        module.OddParams.declare(ros.node())
    assert tuple(map(str, caught.value.problems)) == (
        "lanes: default rejected: 3 is odd (tests.custom_checks:is_even)",
    )


def test_a_node_with_old_names_and_arrays_sets_each_parameter_once(
    ros: RosHarness, rig: types.ModuleType
) -> None:
    node = ros.node()
    cfg = rig.RigParams.declare(node)
    seen: list[object] = []
    cfg.on_change(seen.append)
    results = node.set_parameters([Parameter("speed_limit", value=2.0)])
    assert [r.successful for r in results] == [True]
    assert len(seen) == 1 and cfg.top_speed == 2.0
    results = node.set_parameters([Parameter("names", value=[])])
    assert [r.successful for r in results] == [True]
    assert len(seen) == 2 and cfg.names == ()


def test_a_set_made_by_a_subscriber_is_delivered_after_it_returns(
    ros: RosHarness, rig: types.ModuleType
) -> None:
    node = ros.node()
    cfg = rig.RigParams.declare(node)
    order: list[str] = []

    def react(changes: Any) -> None:
        names = [change.name for change in changes.changed]
        order.extend(names)
        if names == ["gain"]:
            assert node.set_parameters([Parameter("ticks", value=15)])[0].successful
            order.append("set returned")

    cfg.on_change(react)
    assert node.set_parameters([Parameter("gain", value=2.0)])[0].successful
    assert order == ["gain", "set returned", "ticks"]
