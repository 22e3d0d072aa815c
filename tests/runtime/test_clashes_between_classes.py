"""A name two classes of one node both want: one reason per name, and undeclare refused."""

from __future__ import annotations

import types

import pytest
from rclpy.exceptions import ParameterImmutableException

from genparams.runtime import ParameterDeclarationError
from tests.runtime.schemas import SAFETY, generate
from tests.support import RosHarness

# Wants `mode` too, and takes its old name `old_mode` from overrides.
CLASH = """\
genparams: 1
name: clash
parameters:
  mode: {type: int, default: 1, aliases: [old_mode]}
  level: {type: int, default: 2}
"""


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> tuple[types.ModuleType, ...]:
    folder = tmp_path_factory.mktemp("clash")
    return generate(folder, SAFETY, "safety"), generate(folder, CLASH, "clash")


@pytest.mark.parametrize(
    ("args", "problems"),
    [
        ([], ("mode: already declared on this node by SafetyParams",)),
        # The override under the old name is not for the other class's `mode`: the clash
        # is the one reason given for it, not its type too.
        (["-p", "old_mode:=fast"], ("mode: already declared on this node by SafetyParams",)),
        (
            ["-p", "old_mode:=fast", "-p", "level:=high"],
            (
                "mode: already declared on this node by SafetyParams",
                "level: override has the wrong type: expected integer, got string 'high'",
            ),
        ),
    ],
)
def test_a_name_another_class_declared_is_reported_once(
    ros: RosHarness,
    classes: tuple[types.ModuleType, ...],
    args: list[str],
    problems: tuple[str, ...],
) -> None:
    safety, clash = classes
    node = ros.node(args=args)
    safety.SafetyParams.declare(node)
    with pytest.raises(ParameterDeclarationError) as raised:
        clash.ClashParams.declare(node)
    assert tuple(map(str, raised.value.problems)) == problems
    assert not node.has_parameter("level")


def test_undeclare_names_the_class_that_declares_the_parameter(
    ros: RosHarness, classes: tuple[types.ModuleType, ...]
) -> None:
    safety, _ = classes
    node = ros.node()
    safety.SafetyParams.declare(node, "base")
    with pytest.raises(ParameterImmutableException) as refused:
        node.undeclare_parameter("base.limit")
    assert str(refused.value) == (
        "base.limit: cannot be undeclared: SafetyParams declares it and its typed view would "
        "keep the value (parameter services refuse it the same way)"
    )
    assert refused.value.name == "base.limit"  # type: ignore[attr-defined]
    assert node.get_parameter("base.limit").value == 5.0
