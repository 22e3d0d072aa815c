"""A watch reads its first snapshot once connected, reads again when a key list changes,
and reports each change once, whatever arrives while a read is in flight."""

from __future__ import annotations

import time
import types
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from rcl_interfaces.msg import ParameterEvent
from rcl_interfaces.srv import GetParameters, ListParameters
from rclpy.parameter import Parameter
from rclpy.qos import QoSProfile, ReliabilityPolicy, qos_profile_parameter_events

from genparams.runtime import Changes, RemoteParameterError
from genparams.runtime.remote.watch import RemoteWatch
from tests.support import ROOT, RosHarness, load_generated

ARM_VALUES = {
    "joints": ["shoulder", "elbow"],
    "gains.shoulder.p": 1.0,
    "gains.shoulder.i": 0.0,
    "gains.elbow.p": 1.0,
    "gains.elbow.i": 0.0,
    "max_speed": 1.0,
    "legacy_mode": False,
}


@pytest.fixture
def arm(tmp_path: Path) -> types.ModuleType:
    return load_generated(ROOT / "examples" / "arm" / "arm.yaml", tmp_path)


def spin_until(ros: RosHarness, condition: Callable[[], bool], timeout: float = 10.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise TimeoutError("condition not reached")
        ros.executor.spin_once(timeout_sec=0.05)


def spin_until_logged(
    ros: RosHarness, capfd: pytest.CaptureFixture[str], text: str, timeout: float = 5.0
) -> str:
    """Spin until ``text`` is written to stderr; everything written there meanwhile."""
    err = ""
    deadline = time.monotonic() + timeout
    while text not in err:
        if time.monotonic() > deadline:
            raise TimeoutError(f"{text!r} not logged")
        ros.executor.spin_once(timeout_sec=0.05)
        err += capfd.readouterr().err
    return err


class HandServedTarget:
    """A node that serves the parameter services by hand: it counts the full reads (those
    that ask for the key list, before the entries it names), can fail
    the next ones (as a node does while a new key list's entries are not yet declared),
    and publishes parameter events of any type, as a node with dynamic typing may."""

    def __init__(self, ros: RosHarness, values: dict[str, Any]) -> None:
        self.node = ros.node(start_parameter_services=False)
        self.name = self.node.get_fully_qualified_name()
        self.values = dict(values)
        self.failures = 0
        self.reads = 0
        self.change_after_read: dict[str, Any] = {}  # changed once the next read is answered
        self.node.create_service(GetParameters, f"{self.name}/get_parameters", self.get)
        self.node.create_service(ListParameters, f"{self.name}/list_parameters", self.list)
        self.events = self.node.create_publisher(
            ParameterEvent, "/parameter_events", qos_profile_parameter_events
        )

    def get(
        self, request: GetParameters.Request, response: GetParameters.Response
    ) -> GetParameters.Response:
        self.reads += "joints" in request.names
        if self.failures:
            self.failures -= 1
        elif all(name in self.values for name in request.names):
            response.values = [
                Parameter(name, value=self.values[name]).get_parameter_value()
                for name in request.names
            ]
            if self.change_after_read:
                self.change(**self.change_after_read)
                self.change_after_read = {}
        return response

    def list(
        self, request: ListParameters.Request, response: ListParameters.Response
    ) -> ListParameters.Response:
        response.result.names = list(self.values)
        return response

    def change(self, **values: Any) -> None:
        """Store ``values`` and announce them in one event, in the order given."""
        names = {name.replace("__", "."): value for name, value in values.items()}
        self.values.update(names)
        event = ParameterEvent(node=self.name)
        event.changed_parameters = [
            Parameter(name, value=value).to_parameter_msg() for name, value in names.items()
        ]
        self.events.publish(event)


def test_the_first_snapshot_is_read_as_soon_as_events_are_connected(
    ros: RosHarness, arm: types.ModuleType, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(RemoteWatch, "CONNECT_TIMEOUT", 60.0)
    target = ros.node()
    cfg = arm.ArmParams.declare(target)
    watch = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name()).watch(print)
    assert ros.wait(watch.ready, timeout=10.0) == cfg.snapshot()
    watch.cancel()


def test_a_publisher_that_never_connects_delays_the_first_read_to_the_timeout(
    ros: RosHarness, arm: types.ModuleType, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(RemoteWatch, "CONNECT_TIMEOUT", 0.5)
    target = ros.node()
    cfg = arm.ArmParams.declare(target)
    # Best effort cannot feed the watch's reliable subscription: it is counted, never matched.
    stray = ros.node().create_publisher(
        ParameterEvent,
        "/parameter_events",
        QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT),
    )
    started = time.monotonic()
    watch = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name()).watch(print)
    assert ros.wait(watch.ready, timeout=10.0) == cfg.snapshot()
    assert time.monotonic() - started >= 0.5
    watch.cancel()
    stray.destroy()


def test_a_target_without_the_schema_fails_ready(ros: RosHarness, arm: types.ModuleType) -> None:
    target = ros.node()
    target.declare_parameter("max_speed", 1.0)
    name = target.get_fully_qualified_name()
    watch = arm.ArmParams.remote(ros.node(), name).watch(print)
    with pytest.raises(RemoteParameterError) as caught:
        ros.wait(watch.ready)
    assert str(caught.value) == (
        f"{name} does not follow arm: joints: not declared; legacy_mode: not declared"
    )
    watch.cancel()


def test_a_failed_first_read_is_not_tried_again(ros: RosHarness, arm: types.ModuleType) -> None:
    target = HandServedTarget(ros, ARM_VALUES)
    target.failures = 1
    watch = arm.ArmParams.remote(ros.node(), target.name).watch(print)
    with pytest.raises(RemoteParameterError):
        ros.wait(watch.ready)
    assert target.reads == 1
    watch.cancel()


def test_a_reread_after_a_key_list_change_is_tried_three_times(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    target = HandServedTarget(ros, ARM_VALUES)
    seen: list[Changes[Any]] = []
    watch = arm.ArmParams.remote(ros.node(), target.name).watch(seen.append)
    ros.wait(watch.ready)
    target.failures = 2  # the entries of the new list are declared by the third read
    target.change(joints=["shoulder"])
    spin_until(ros, lambda: len(seen) == 1)
    assert target.reads == 1 + 3
    assert sorted((c.name, c.old, c.new) for c in seen[0]) == [
        ("gains.elbow.i", 0.0, None),
        ("gains.elbow.p", 1.0, None),
        ("joints", ("shoulder", "elbow"), ("shoulder",)),
    ]
    assert list(watch.latest.gains) == ["shoulder"]
    watch.cancel()


def test_a_reread_that_keeps_failing_is_logged_and_the_watch_goes_on(
    ros: RosHarness, arm: types.ModuleType, capfd: pytest.CaptureFixture[str]
) -> None:
    target = HandServedTarget(ros, ARM_VALUES)
    seen: list[Changes[Any]] = []
    remote = arm.ArmParams.remote(ros.node(), target.name)
    watch = remote.watch(seen.append)
    ros.wait(watch.ready)
    capfd.readouterr()
    target.failures = 3
    target.change(joints=["shoulder"])
    spin_until_logged(ros, capfd, "cannot read")
    assert target.reads == 1 + 3 and seen == []
    # The events that follow are applied to the last snapshot read.
    target.change(max_speed=2.5)
    spin_until(ros, lambda: len(seen) == 1)
    assert [(c.name, c.old, c.new) for c in seen[0]] == [("max_speed", 1.0, 2.5)]
    watch.cancel()


def test_a_failed_reread_logs_who_could_not_be_read(
    ros: RosHarness, arm: types.ModuleType, capfd: pytest.CaptureFixture[str]
) -> None:
    target = HandServedTarget(ros, ARM_VALUES)
    remote = arm.ArmParams.remote(ros.node(), target.name)
    watch = remote.watch(print)
    ros.wait(watch.ready)
    capfd.readouterr()
    target.failures = 3
    target.change(joints=["shoulder"])
    err = spin_until_logged(ros, capfd, "RemoteParameterError")
    assert f"ArmParams.remote('{target.name}'): cannot read {target.name}:\nTraceback" in err
    watch.cancel()


def test_changes_arriving_during_a_reread_are_reported_with_it_once(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    target = ros.node()
    cfg = arm.ArmParams.declare(target)
    seen: list[Changes[Any]] = []
    watch = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name()).watch(seen.append)
    ros.wait(watch.ready)
    # Both events are out before the watch spins: the second arrives while it reads again.
    target.set_parameters([Parameter("joints", value=["shoulder", "wrist"])])
    target.set_parameters([Parameter("gains.shoulder.p", value=5.0)])
    spin_until(ros, lambda: watch.latest == cfg.snapshot())
    target.set_parameters([Parameter("max_speed", value=2.0)])
    spin_until(ros, lambda: len(seen) == 2)
    assert sorted((c.name, c.old, c.new) for c in seen[0]) == [
        ("gains.elbow.i", 0.0, None),
        ("gains.elbow.p", 1.0, None),
        ("gains.shoulder.p", 1.0, 5.0),
        ("gains.wrist.i", None, 0.0),
        ("gains.wrist.p", None, 1.0),
        ("joints", ("shoulder", "elbow"), ("shoulder", "wrist")),
    ]
    assert [(c.name, c.old, c.new) for c in seen[1]] == [("max_speed", 1.0, 2.0)]
    watch.cancel()


def test_a_change_made_just_after_the_first_read_is_reported(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    target = HandServedTarget(ros, ARM_VALUES)
    target.change_after_read = {"max_speed": 2.5}
    seen: list[Changes[Any]] = []
    watch = arm.ArmParams.remote(ros.node(), target.name).watch(seen.append)
    assert ros.wait(watch.ready).max_speed == 1.0
    spin_until(ros, lambda: len(seen) == 1)
    assert [(c.name, c.old, c.new) for c in seen[0]] == [("max_speed", 1.0, 2.5)]
    assert watch.latest.max_speed == 2.5
    watch.cancel()


def test_parameters_outside_the_schema_do_not_hide_the_rest_of_an_event(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    target = ros.node()
    target.declare_parameter("unrelated", 1)
    target.declare_parameter("left.unrelated", 1)
    cfg = arm.ArmParams.declare(target, prefix="left")
    seen: list[Changes[Any]] = []
    remote = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name(), "left")
    watch = remote.watch(seen.append)
    ros.wait(watch.ready)
    target.set_parameters_atomically(
        [
            Parameter("unrelated", value=2),
            Parameter("left.unrelated", value=2),
            Parameter("left.max_speed", value=2.0),
        ]
    )
    spin_until(ros, lambda: len(seen) == 1)
    assert [(c.name, c.old, c.new) for c in seen[0]] == [("max_speed", 1.0, 2.0)]
    assert watch.latest == cfg.snapshot()
    watch.cancel()


def test_a_value_of_the_wrong_type_is_skipped_with_a_warning(
    ros: RosHarness, arm: types.ModuleType, capfd: pytest.CaptureFixture[str]
) -> None:
    target = HandServedTarget(ros, ARM_VALUES)
    seen: list[Changes[Any]] = []
    remote = arm.ArmParams.remote(ros.node(), target.name)
    watch = remote.watch(seen.append)
    ros.wait(watch.ready)
    capfd.readouterr()
    target.change(max_speed=7, legacy_mode=True)
    spin_until(ros, lambda: len(seen) == 1)
    assert [(c.name, c.old, c.new) for c in seen[0]] == [("legacy_mode", False, True)]
    assert watch.latest.max_speed == 1.0
    assert (
        f"ArmParams.remote('{target.name}'): ignoring max_speed: "
        "expected double, got integer 7 (ROS does not convert: write 7.0)"
    ) in capfd.readouterr().err
    watch.cancel()


def test_a_callback_that_raises_is_logged_and_called_again(
    ros: RosHarness, arm: types.ModuleType, capfd: pytest.CaptureFixture[str]
) -> None:
    target = ros.node()
    arm.ArmParams.declare(target)
    seen: list[Changes[Any]] = []

    def fragile(changes: Changes[Any]) -> None:
        seen.append(changes)
        raise ValueError("subscriber bug")

    watch = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name()).watch(fragile)
    ros.wait(watch.ready)
    capfd.readouterr()
    target.set_parameters([Parameter("max_speed", value=2.0)])
    spin_until(ros, lambda: len(seen) == 1)
    target.set_parameters([Parameter("max_speed", value=2.5)])
    spin_until(ros, lambda: len(seen) == 2)
    err = capfd.readouterr().err
    assert f"watch callback {fragile!r} raised:\n" in err
    assert "ValueError: subscriber bug" in err
    watch.cancel()
