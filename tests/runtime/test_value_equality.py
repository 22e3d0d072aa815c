"""When a value counts as changed (NaN is the same as NaN, in arrays too), what a
subscriber's ``Changes`` holds, and how the runtime's errors read."""

from __future__ import annotations

import math
from typing import Any

import pytest

from genparams.runtime import Changes, ParameterDeclarationError
from genparams.runtime.core.changes import Change, same_value
from genparams.runtime.core.errors import RemoteSetError
from genparams.runtime.core.problems import ParameterProblem

NAN = math.nan
OTHER_NAN = float("nan")  # another object: a tuple compares its items by identity first


@pytest.mark.parametrize(
    ("a", "b", "same"),
    [
        (1.0, 1.0, True),
        (1, 1.0, True),
        (NAN, NAN, True),
        (NAN, 1.0, False),
        (1.0, NAN, False),
        (NAN, "nan", False),
        ("nan", NAN, False),
        ((1.0, NAN), (1.0, OTHER_NAN), True),
        ((NAN, 1.0), (OTHER_NAN, 2.0), False),
        ((NAN,), (NAN, NAN), False),
        ((NAN, NAN), (NAN,), False),
        ((NAN, 1.0), (NAN, 2.0), False),
        ((NAN,), [NAN], False),
        ([NAN], (NAN,), False),
        ((), (), True),
        (("a", NAN), ("a", OTHER_NAN), True),
        (b"\x01", b"\x01", True),
        (b"\x01", b"\x02", False),
    ],
)
def test_same_value(a: Any, b: Any, same: bool) -> None:
    assert same_value(a, b) is same
    assert same_value(b, a) is same


def test_changes_list_each_changed_name_once() -> None:
    changed = (Change("speed", 1.0, 2.0), Change("camera.fps", 30.0, 15.0))
    changes = Changes(before="old", after="new", changed=changed)
    assert changes.names == frozenset({"speed", "camera.fps"})
    assert "camera.fps" in changes and "camera" not in changes and 1 not in changes
    assert list(changes) == list(changed) and len(changes) == 2
    empty = Changes(before="old", after="old", changed=())
    assert len(empty) == 0 and list(empty) == [] and empty.names == frozenset()


def test_declaration_errors_list_every_problem() -> None:
    speed = ParameterProblem("speed", "must be > 0 (gt), got -1")
    one = ParameterDeclarationError("motion", "/robot", [speed])
    assert one.problems == (speed,)
    assert str(one) == (
        "/robot: cannot declare motion parameters (1 problem):\n  - speed: must be > 0 (gt), got -1"
    )
    two = ParameterDeclarationError(
        "motion",
        "MotionParams.defaults()",
        (ParameterProblem("a", "no such parameter"), ParameterProblem("", "rule 'r' broken")),
        doing="build",
    )
    assert str(two) == (
        "MotionParams.defaults(): cannot build motion parameters (2 problems):\n"
        "  - a: no such parameter\n  - rule 'r' broken"
    )


def test_remote_set_errors_say_who_refused() -> None:
    speed = ParameterProblem("speed", "must be > 0 (gt), got -1")
    before = RemoteSetError.before_sending([speed, ParameterProblem("gain\u200b", "no such")])
    reason = "speed: must be > 0 (gt), got -1; gain\\u200b: no such"
    assert str(before) == f"rejected before sending: {reason}"
    assert before.reason == reason and before.sent is False
    assert before.problems == (speed, ParameterProblem("gain\u200b", "no such"))
    after = RemoteSetError("busy", sent=True)
    assert str(after) == "rejected by the node: busy"
    assert after.reason == "busy" and after.sent is True and after.problems == ()
