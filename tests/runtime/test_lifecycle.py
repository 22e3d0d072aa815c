"""Lifecycle nodes (rclpy.lifecycle.Node) declare and validate like plain nodes."""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import pytest
from lifecycle_msgs.msg import Transition
from lifecycle_msgs.srv import ChangeState
from rclpy.lifecycle import Node as LifecycleNode
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.parameter import Parameter

from genparams.runtime import Changes, ParameterDeclarationError
from tests.support import RosHarness, load_generated, unique_name

MOTION = """\
genparams: 1
name: motion
parameters:
  min_speed: {type: double, default: 0.5, range: {min: 0.0, max: 10.0}}
  max_speed: {type: double, default: 2.0, range: {min: 0.0, max: 10.0}}
  frame: {type: string, default: base_link, read_only: true}
rules:
  - {name: speed_order, check: min_speed <= max_speed}
"""


@pytest.fixture
def module(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "motion.yaml"
    schema.write_text(MOTION)
    return load_generated(schema, tmp_path)


def make_driver(module: types.ModuleType, ros: RosHarness, args: list[str]) -> Any:
    params_cls = module.MotionParams

    class Driver(LifecycleNode):
        def __init__(self) -> None:
            super().__init__(
                unique_name("lifecycle"), context=ros.context, cli_args=["--ros-args", *args]
            )
            self.params = params_cls.declare(self)
            self.configured_with: tuple[float, float] | None = None
            self.changes: list[Changes[Any]] = []
            self.params.on_change(self.changes.append)

        def on_configure(self, state: State) -> TransitionCallbackReturn:
            snapshot = self.params.snapshot()
            self.configured_with = (snapshot.min_speed, snapshot.max_speed)
            return TransitionCallbackReturn.SUCCESS

    return Driver()


def test_lifecycle_node_declares_and_validates_through_services(
    ros: RosHarness, module: types.ModuleType
) -> None:
    driver: Any = ros.add_node(make_driver(module, ros, ["-p", "max_speed:=4.0"]))
    client = ros.client(driver)
    assert client.get("min_speed", "max_speed", "frame") == [0.5, 4.0, "base_link"]
    (descriptor,) = client.describe("max_speed")
    assert descriptor.floating_point_range[0].to_value == 10.0

    (ok,) = client.set(Parameter("min_speed", value=3.0))
    assert ok.successful and driver.params.min_speed == 3.0
    (broken,) = client.set(Parameter("max_speed", value=1.0))
    assert not broken.successful
    assert broken.reason == (
        "rule 'speed_order' broken: min_speed <= max_speed is false for "
        "min_speed=3.0, max_speed=1.0"
    )
    (read_only,) = client.set(Parameter("frame", value="odom"))
    assert not read_only.successful and driver.params.frame == "base_link"
    assert [[(c.name, c.old, c.new) for c in changes] for changes in driver.changes] == [
        [("min_speed", 0.5, 3.0)]
    ]

    # The lifecycle services keep working next to the parameter services.
    change_state = ros.client_node.create_client(
        ChangeState, f"{driver.get_fully_qualified_name()}/change_state"
    )
    try:
        assert change_state.wait_for_service(timeout_sec=10.0)
        request = ChangeState.Request()
        request.transition.id = Transition.TRANSITION_CONFIGURE
        assert ros.wait(change_state.call_async(request)).success
    finally:
        ros.client_node.destroy_client(change_state)
    assert driver.configured_with == (3.0, 4.0)
    assert client.set_atomically(
        Parameter("min_speed", value=6.0), Parameter("max_speed", value=7.0)
    ).successful
    assert (driver.params.min_speed, driver.params.max_speed) == (6.0, 7.0)


def test_lifecycle_node_with_bad_overrides_refuses_to_start(
    ros: RosHarness, module: types.ModuleType
) -> None:
    with pytest.raises(ParameterDeclarationError) as caught:
        make_driver(module, ros, ["-p", "min_speed:=5.0", "-p", "frame:=7"])
    assert tuple(map(str, caught.value.problems)) == (
        "frame: override has the wrong type: expected string, got integer 7",
        "rule 'speed_order' broken: min_speed <= max_speed is false for "
        "min_speed=5.0, max_speed=2.0",
    )
