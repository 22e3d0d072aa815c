"""Path-copying updates of value trees, on hand-written group classes."""

from __future__ import annotations

from typing import Any

import pytest

from genparams.runtime.core.tree import (
    Group,
    GroupMap,
    build_tree,
    copy_node,
    replace_values,
    reuse_values,
    to_dict,
)


class Pid(Group):
    __slots__ = ("kd", "kp")
    kd: float
    kp: float


class Arm(Group):
    __slots__ = ("name", "pid")
    name: str
    pid: Pid


class Single(Group):
    __slots__ = ("only",)
    only: int


class WithBinding(Group):
    """Like Params: a slot that is not a field, copied only when asked for."""

    __slots__ = ("_binding",)


class Root(WithBinding):
    __slots__ = ("arm", "rate", "single")
    arm: Arm
    rate: float
    single: Single


GROUPS = {"arm": Arm, "arm.pid": Pid, "single": Single}
VALUES = {"arm.name": "left", "arm.pid.kd": 0.1, "arm.pid.kp": 1.0, "rate": 5.0, "single.only": 1}


def tree() -> Root:
    return build_tree(Root, GROUPS, VALUES, extra={"_binding": "marker"})


def test_one_update_copies_only_its_path() -> None:
    before = tree()
    after = replace_values(before, {("arm", "pid", "kp"): 2.0}, extra=("_binding",))
    assert after.arm.pid.kp == 2.0 and before.arm.pid.kp == 1.0
    assert after.arm is not before.arm and after.arm.pid is not before.arm.pid
    assert after.single is before.single  # untouched groups are shared
    assert after._binding == "marker"  # type: ignore[attr-defined]
    assert to_dict(after) == {
        **to_dict(before),
        "arm": {"name": "left", "pid": {"kd": 0.1, "kp": 2.0}},
    }


def test_many_updates_at_every_depth() -> None:
    before = tree()
    after = replace_values(
        before,
        {
            ("rate",): 9.0,
            ("arm", "name"): "right",
            ("arm", "pid", "kd"): 0.5,
            ("single", "only"): 7,
        },
    )
    assert to_dict(after) == {
        "arm": {"name": "right", "pid": {"kd": 0.5, "kp": 1.0}},
        "rate": 9.0,
        "single": {"only": 7},
    }
    assert to_dict(before)["rate"] == 5.0


def test_copy_of_a_one_field_group_and_of_extra_slots() -> None:
    root = tree()
    single = copy_node(root.single)
    assert single == root.single and single is not root.single
    copied = copy_node(root, ("_binding",))
    assert copied == root and copied._binding == "marker"  # type: ignore[attr-defined]


class Spare:
    """What a binding keeps: the one reference to a root no reader can reach."""

    def __init__(self, root: Any) -> None:
        self.root = root


@pytest.mark.parametrize(
    "updates",
    [{("arm", "pid", "kp"): 2.0}, {("arm", "pid", "kp"): 2.0, ("arm", "name"): "right"}],
    ids=["one path", "two paths"],
)
def test_reuse_writes_in_place_what_nobody_else_holds(updates: dict[Any, Any]) -> None:
    spare = Spare(tree())
    root, arm, pid = spare.root, spare.root.arm, spare.root.arm.pid
    del arm, pid  # only the tree holds them now
    ids = id(root), id(root.arm), id(root.arm.pid)
    del root
    after = reuse_values(spare.root, updates, extra=("_binding",))
    assert (id(after), id(after.arm), id(after.arm.pid)) == ids
    assert after.arm.pid.kp == 2.0 and after._binding == "marker"


@pytest.mark.parametrize("held", ["root", "arm", "pid"])
def test_reuse_copies_what_anyone_holds_and_everything_below_it(held: str) -> None:
    spare = Spare(tree())
    kept = {"root": spare.root, "arm": spare.root.arm, "pid": spare.root.arm.pid}[held]
    shown = repr(kept)
    after = reuse_values(spare.root, {("arm", "pid", "kp"): 2.0}, extra=("_binding",))
    assert after.arm.pid.kp == 2.0
    assert repr(kept) == shown  # what was held was copied, not written
    assert all(group is not kept for group in (after, after.arm, after.arm.pid))


def test_reuse_copies_maps_of_entries() -> None:
    entries = GroupMap({"a": build_tree(Single, {}, {"only": 1})})
    holder = Spare(build_tree(Root, GROUPS, VALUES, extra={"_binding": None}))
    object.__setattr__(holder.root, "single", entries)
    iterator = iter(holder.root.single)  # holds the map's dict, not the map
    after = reuse_values(holder.root, {("single", "a", "only"): 2})
    assert after.single["a"].only == 2 and entries["a"].only == 1
    assert list(iterator) == ["a"]


@pytest.mark.parametrize(
    "updates",
    [
        {("single", "a", "only"): 2},  # one update: a path through the map
        {("single", "a", "only"): 2, ("rate",): 6.0},  # several: grouped by head
    ],
)
def test_replace_goes_through_maps_of_entries(updates: dict[Any, Any]) -> None:
    entries = GroupMap({"a": build_tree(Single, {}, {"only": 1})})
    before = tree()
    object.__setattr__(before, "single", entries)
    after: Any = replace_values(before, updates)  # its single is a map of entries here
    assert after.single["a"].only == 2 and entries["a"].only == 1
    assert type(after.single) is GroupMap and after.single is not entries
