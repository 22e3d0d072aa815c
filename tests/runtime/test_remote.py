"""Typed remote access: one node reads, sets and watches another through ``remote()``."""

from __future__ import annotations

import time
import types
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from rcl_interfaces.msg import SetParametersResult
from rclpy.parameter import Parameter

from genparams.runtime import Changes, RemoteParameterError, RemoteSetError
from tests.support import ROOT, RosHarness, load_generated

MOTION = """\
genparams: 1
name: motion
parameters:
  robot: {type: string, default: rover, read_only: true}
  min_speed: {type: double, default: 0.5, range: {min: 0.0, max: 10.0}}
  max_speed: {type: double, default: 2.0, range: {min: 0.0, max: 10.0}}
  drive:
    mode: {type: string, default: eco, choices: [eco, sport]}
    wheels: {type: int_array, default: [1, 2, 3, 4]}
rules:
  - {name: speed_order, check: min_speed <= max_speed}
"""


@pytest.fixture
def module(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "motion.yaml"
    schema.write_text(MOTION)
    return load_generated(schema, tmp_path)


def spin_until(ros: RosHarness, condition: Callable[[], bool], timeout: float = 10.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise TimeoutError("condition not reached")
        ros.executor.spin_once(timeout_sec=0.05)


class SetCounter:
    """An on-set callback on the target that counts the sets reaching it."""

    def __init__(self) -> None:
        self.calls = 0

    def __call__(self, parameters: list[Parameter]) -> SetParametersResult:
        self.calls += 1
        return SetParametersResult(successful=True)


def test_get_and_set_through_remote(ros: RosHarness, module: types.ModuleType) -> None:
    target = ros.node()
    cfg = module.MotionParams.declare(target, prefix="base")
    counter = SetCounter()
    target.add_on_set_parameters_callback(counter)
    client_node = ros.node()
    remote = module.MotionParams.remote(client_node, target.get_fully_qualified_name(), "base")
    assert remote.wait_for_services(timeout_sec=10.0)

    snapshot = ros.wait(remote.get())
    assert type(snapshot) is module.MotionParams
    assert snapshot == cfg.snapshot()
    assert (snapshot.drive.mode, snapshot.drive.wheels) == ("eco", (1, 2, 3, 4))

    # Ints are taken for doubles and lists for arrays; the set is atomic.
    assert ros.wait(remote.set({"max_speed": 6, "min_speed": 5.5, "drive.wheels": [7]})) is None
    assert (cfg.min_speed, cfg.max_speed, cfg.drive.wheels) == (5.5, 6.0, (7,))
    assert counter.calls == 1

    # The node's own rejection comes back with its reason: this rule also reads max_speed,
    # which is not being set, so only the node can check it.
    with pytest.raises(RemoteSetError) as caught:
        ros.wait(remote.set({"min_speed": 9.0}))
    assert caught.value.sent is True
    assert caught.value.reason == (
        "rule 'speed_order' broken: min_speed <= max_speed is false for "
        "base.min_speed=9.0, base.max_speed=6.0"
    )
    assert counter.calls == 2 and cfg.min_speed == 5.5


@pytest.mark.parametrize(
    ("values", "reason"),
    [
        (
            {"max_speed": 50.0},
            "base.max_speed: must be within [0.0, 10.0] (range), got 50.0",
        ),
        (
            {"drive.mode": "turbo"},
            "base.drive.mode: must be one of ['eco', 'sport'] (one_of), got 'turbo'",
        ),
        ({"min_speed": "fast"}, "base.min_speed: expected double, got string 'fast'"),
        (
            {"min_speed": 4.0, "max_speed": 3.0},
            "rule 'speed_order' broken: min_speed <= max_speed is false for "
            "base.min_speed=4.0, base.max_speed=3.0",
        ),
        (
            {"robot": "other"},
            "base.robot: read-only: set it when the node starts (-p, a params file or launch)",
        ),
        ({"max_sped": 1.0}, "max_sped: no such parameter in motion (did you mean 'max_speed'?)"),
    ],
)
def test_set_rejected_before_sending(
    ros: RosHarness, module: types.ModuleType, values: dict[str, Any], reason: str
) -> None:
    target = ros.node()
    cfg = module.MotionParams.declare(target, prefix="base")
    counter = SetCounter()
    target.add_on_set_parameters_callback(counter)
    remote = module.MotionParams.remote(ros.node(), target.get_fully_qualified_name(), "base")

    future = remote.set(values)
    assert future.done()  # no round trip: nothing was spun, nothing sent
    with pytest.raises(RemoteSetError) as caught:
        future.result()
    assert caught.value.sent is False
    assert caught.value.reason.startswith(reason)
    assert str(caught.value) == f"rejected before sending: {caught.value.reason}"
    ros.executor.spin_once(timeout_sec=0.1)
    assert counter.calls == 0
    assert cfg.snapshot() == module.MotionParams.defaults()


def test_remote_calls_can_be_awaited(ros: RosHarness, module: types.ModuleType) -> None:
    target = ros.node()
    cfg = module.MotionParams.declare(target)
    remote = module.MotionParams.remote(ros.node(), target.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)

    async def speed_up() -> float:
        before = await remote.get()
        await remote.set({"max_speed": before.max_speed + 1.5})
        after = await remote.get()
        return float(after.max_speed)

    assert ros.wait(ros.executor.create_task(speed_up)) == 3.5
    assert cfg.max_speed == 3.5


def test_watch_reports_typed_changes(ros: RosHarness, module: types.ModuleType) -> None:
    target = ros.node()
    target.declare_parameter("unrelated", 1)
    cfg = module.MotionParams.declare(target)
    seen: list[Changes[Any]] = []
    remote = module.MotionParams.remote(ros.node(), target.get_fully_qualified_name())
    watch = remote.watch(seen.append)
    first = ros.wait(watch.ready)
    assert first == cfg.snapshot()

    target.set_parameters([Parameter("unrelated", value=2)])
    target.set_parameters_atomically(
        [Parameter("max_speed", value=4.0), Parameter("drive.mode", value="sport")]
    )
    spin_until(ros, lambda: len(seen) == 1)
    (changes,) = seen
    assert sorted((c.name, c.old, c.new) for c in changes) == [
        ("drive.mode", "eco", "sport"),
        ("max_speed", 2.0, 4.0),
    ]
    assert changes.before is first
    assert changes.after == cfg.snapshot() == watch.latest

    watch.cancel()
    target.set_parameters([Parameter("max_speed", value=5.0)])
    deadline = time.monotonic() + 0.5
    while time.monotonic() < deadline:
        ros.executor.spin_once(timeout_sec=0.05)
    assert len(seen) == 1


def test_a_target_that_does_not_follow_the_schema_is_named(
    ros: RosHarness, module: types.ModuleType
) -> None:
    target = ros.node()
    target.declare_parameter("min_speed", 1)  # an int where the schema says double
    name = target.get_fully_qualified_name()
    remote = module.MotionParams.remote(ros.node(), name)
    assert remote.wait_for_services(timeout_sec=10.0)
    with pytest.raises(RemoteParameterError) as caught:
        ros.wait(remote.get())
    assert str(caught.value) == (
        f"{name} does not follow motion: drive.mode: not declared; drive.wheels: not declared; "
        "max_speed: not declared; robot: not declared"
    )
    for parameter, value in (("drive.mode", "eco"), ("drive.wheels", [1]), ("max_speed", 2.0)):
        target.declare_parameter(parameter, value)
    target.declare_parameter("robot", "r")
    with pytest.raises(RemoteParameterError) as caught:
        ros.wait(remote.get())
    assert str(caught.value) == (
        f"{name} does not follow motion: "
        "min_speed: expected double, got integer 1 (ROS does not convert: write 1.0)"
    )


def test_mapped_entries_through_remote(ros: RosHarness, tmp_path: Path) -> None:
    arm = load_generated(ROOT / "examples" / "arm" / "arm.yaml", tmp_path)
    target = ros.node()
    cfg = arm.ArmParams.declare(target)
    remote = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)

    snapshot = ros.wait(remote.get())
    assert snapshot == cfg.snapshot()
    assert {key: entry.p for key, entry in snapshot.gains.items()} == {
        "shoulder": 1.0,
        "elbow": 1.0,
    }
    ros.wait(remote.set({"gains.elbow.p": 2}))
    assert cfg.gains["elbow"].p == 2.0
    with pytest.raises(RemoteSetError, match=r"gains\.elbow\.i: must be >= 0\.0"):
        remote.set({"gains.elbow.i": -1.0}).result()

    seen: list[Changes[Any]] = []
    watch = remote.watch(seen.append)
    ros.wait(watch.ready)
    target.set_parameters([Parameter("gains.shoulder.i", value=0.5)])
    spin_until(ros, lambda: len(seen) == 1)
    assert [(c.name, c.old, c.new) for c in seen[0]] == [("gains.shoulder.i", 0.0, 0.5)]
    # A new key list declares and undeclares entries: the watch reads them all again.
    target.set_parameters([Parameter("joints", value=["shoulder", "wrist"])])
    spin_until(ros, lambda: len(seen) == 2 and watch.latest == cfg.snapshot())
    assert sorted((c.name, c.old, c.new) for c in seen[1]) == [
        ("gains.elbow.i", 0.0, None),
        ("gains.elbow.p", 2.0, None),
        ("gains.wrist.i", None, 0.0),
        ("gains.wrist.p", None, 1.0),
        ("joints", ("shoulder", "elbow"), ("shoulder", "wrist")),
    ]
    watch.cancel()


def test_entries_with_dashed_keys_through_remote(ros: RosHarness, tmp_path: Path) -> None:
    arm = load_generated(ROOT / "examples" / "arm" / "arm.yaml", tmp_path)
    target = ros.node()
    cfg = arm.ArmParams.declare(target)
    remote = arm.ArmParams.remote(ros.node(), target.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)
    ros.wait(remote.set({"joints": ["left-arm", "1st"]}))
    ros.wait(remote.set({"gains.left-arm.p": 2.5}))
    assert cfg.gains["left-arm"].p == 2.5
    with pytest.raises(RemoteSetError, match=r"gains\.1st\.i: must be >= 0\.0"):
        remote.set({"gains.1st.i": -1.0}).result()
    snapshot = ros.wait(remote.get())
    assert snapshot == cfg.snapshot() and list(snapshot.gains) == ["left-arm", "1st"]
