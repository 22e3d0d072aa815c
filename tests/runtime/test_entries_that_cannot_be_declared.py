"""A change of keys whose entries another class declared first in the same set.

Two classes on one node, one under the other's mapped group, each check their part of
an atomic set alone; when the first declares the entry names the second wants, the
second keeps its previous entries and takes the new keys, as the node stored them.
"""

from __future__ import annotations

import types
from typing import Any

import pytest
from rcl_interfaces.msg import SetParametersResult
from rclpy.parameter import Parameter

from genparams.runtime import Changes
from tests.runtime.schemas import generate
from tests.support import RosHarness

OUTER = """\
genparams: 1
name: outer
parameters:
  joints: {type: string_array, default: []}
  gains:
    for_each: joints
    p: {type: double, default: 1.0}
"""

# Declared under the prefix "gains": its entries gains.<name>.p are outer's entry names.
INNER = """\
genparams: 1
name: inner
parameters:
  names: {type: string_array, default: [base]}
  limit: {type: int, default: 3}
  "*":
    for_each: names
    p: {type: double, default: 2.0}
"""


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> tuple[types.ModuleType, ...]:
    folder = tmp_path_factory.mktemp("taken")
    return generate(folder, OUTER, "outer"), generate(folder, INNER, "inner")


def test_keys_change_and_entries_keep_their_shape(
    ros: RosHarness, classes: tuple[types.ModuleType, ...], capfd: pytest.CaptureFixture[str]
) -> None:
    outer_module, inner_module = classes
    node = ros.node()
    outer = outer_module.OuterParams.declare(node)
    inner = inner_module.InnerParams.declare(node, "gains")
    seen: list[Changes[Any]] = []
    inner.on_change(seen.append)
    before = inner.snapshot()

    result = node.set_parameters_atomically(
        [
            Parameter("joints", value=["wrist", "hand"]),
            Parameter("gains.names", value=["base", "wrist", "hand"]),
            Parameter("gains.limit", value=5),
        ]
    )

    assert result.successful, result.reason
    assert list(outer.gains) == ["wrist", "hand"] and outer.gains["wrist"].p == 1.0
    assert node.get_parameter("gains.wrist.p").value == 1.0  # outer's entry
    # inner holds what the node stored, and the entries it had.
    assert inner.names == ("base", "wrist", "hand") and inner.limit == 5 and list(inner) == ["base"]
    assert inner["base"].p == 2.0
    (changes,) = seen
    assert changes.before is before and changes.after is inner.snapshot()
    assert [(c.name, c.old, c.new) for c in changes] == [
        ("names", ("base",), ("base", "wrist", "hand")),
        ("limit", 3, 5),
    ]
    assert changes.after.snapshot() is changes.after  # a frozen value, as every snapshot
    assert (changes.after.names, changes.after.limit) == (("base", "wrist", "hand"), 5)
    assert (before.names, before.limit) == (("base",), 3)
    logged = capfd.readouterr().err
    assert (
        "mapped entries keep their previous keys: "
        "gains.wrist.p: already declared on this node by other code; "
        "gains.hand.p: already declared on this node by other code\n"
    ) in logged


def test_entries_refused_when_declared_keep_their_shape(
    ros: RosHarness, classes: tuple[types.ModuleType, ...], capfd: pytest.CaptureFixture[str]
) -> None:
    """An on-set callback that lets each entry name through once: it accepts the new
    entries when the change of keys is checked, and refuses their declaration after."""
    outer_module, _ = classes
    node = ros.node()
    outer = outer_module.OuterParams.declare(node)
    seen: set[str] = set()

    def once(parameters: list[Parameter]) -> SetParametersResult:
        names = {p.name for p in parameters if p.name.startswith("gains.")}
        if names & seen:
            return SetParametersResult(successful=False, reason="seen before")
        seen.update(names)
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(once)
    result = node.set_parameters([Parameter("joints", value=["wrist"])])[0]

    assert result.successful, result.reason
    assert outer.joints == ("wrist",) and list(outer.gains) == []
    assert not node.has_parameter("gains.wrist.p")
    assert "cannot change mapped entries: seen before\n" in capfd.readouterr().err
    result = node.set_parameters([Parameter("joints", value=[])])[0]
    assert result.successful and outer.joints == () and list(outer.gains) == []
