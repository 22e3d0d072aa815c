"""Group values as users meet them: read-only, printable, copied and unpickled, turned to dicts."""

from __future__ import annotations

import copy
import pickle
import sys
import types

import pytest

from genparams.runtime.core.tree import Group, GroupMap, _rebuild, build_tree, to_dict
from tests.runtime.schemas import MOTION, generate


@pytest.fixture(scope="module")
def motion(tmp_path_factory: pytest.TempPathFactory) -> types.ModuleType:
    return generate(tmp_path_factory.mktemp("motion"), MOTION, "motion")


def test_attributes_cannot_be_deleted(motion: types.ModuleType) -> None:
    snapshot = motion.MotionParams.defaults()
    with pytest.raises(AttributeError) as raised:
        del snapshot.max_speed
    assert str(raised.value) == (
        "MotionParams.max_speed is read-only: change parameters through the node "
        "(set_parameters, ros2 param set), and read them here"
    )
    with pytest.raises(AttributeError, match=r"^FrameGroup\.from_ is read-only"):
        del snapshot.frame.from_
    assert snapshot.max_speed == 2.0 and snapshot.frame.from_ == "odom"


def test_repr_names_the_class_and_every_field(motion: types.ModuleType) -> None:
    frame = motion.MotionParams.defaults({"frame.from_": "map"}).frame
    assert repr(frame) == "FrameGroup(from_='map')"
    assert repr(motion.MotionParams.defaults({"max_speed": 3.0})) == (
        "MotionParams(frame=FrameGroup(from_='odom'), gain=nan, joints=('a',), lambda_=0.1, "
        "max_speed=3.0, min_speed=0.5, port='/dev/ttyUSB0', weights=(1.0, nan))"
    )


class Inner(Group):
    __slots__ = ("defaults_", "from_", "value_")


class Outer(Group):
    """Hand-written, as a person could write a generated class."""

    __slots__ = ("defaults_", "from_", "inner", "int_", "lambda_", "value_")
    _DETACHED = ()


class Owned(Group):
    """A group with a slot that is not a field: a copy of it is a snapshot."""

    __slots__ = ("_owner",)
    _DETACHED = ("_owner",)


class Leaf(Owned):
    __slots__ = ("rate",)


def test_to_dict_of_a_class_no_tree_was_built_of_guesses_the_ros_names() -> None:
    """What unpickling in a process that never built a tree of these classes gives: the
    underscores genparams adds are taken off, real ones kept, top level and nested apart."""
    inner = _rebuild(Inner, ("d", "f", "v"))
    outer = _rebuild(Outer, ("D", "F", inner, 3, 0.5, "V"))
    assert to_dict(outer) == {
        "defaults": "D",  # a reserved name at the top level only
        "from": "F",
        "inner": {"defaults_": "d", "from": "f", "value_": "v"},
        "int": 3,
        "lambda": 0.5,
        "value_": "V",
    }


class Keyed(Group):
    """An in-place map, hand-written: entries by key in ``_map``, beside plain fields."""

    __slots__ = ("_map", "rate", "snapshot_")


def test_to_dict_of_in_place_entries_of_classes_no_tree_was_built_of() -> None:
    entries = GroupMap({"left": _rebuild(Inner, ("d", "f", "v"))})
    keyed = _rebuild(Keyed, (entries, 2.0, True))
    assert to_dict(keyed) == {
        "left": {"defaults_": "d", "from": "f", "value_": "v"},
        "snapshot": True,
        "rate": 2.0,
    }


def test_defaults_is_a_snapshot_of_itself(motion: types.ModuleType) -> None:
    made = motion.MotionParams.defaults()
    assert made.snapshot() is made and copy.copy(made) is made


def test_group_whose_detached_slot_was_never_set_copies_as_a_frozen_value() -> None:
    leaf = build_tree(Leaf, {}, {"rate": 2.0})
    assert copy.copy(leaf) is leaf and copy.deepcopy(leaf) is leaf
    attached = build_tree(Leaf, {}, {"rate": 2.0}, extra={"_owner": "node"})
    detached = copy.copy(attached)
    assert detached is not attached and detached.rate == 2.0  # type: ignore[attr-defined]
    assert detached._owner is None  # type: ignore[attr-defined]


class Versioned(Group):
    __slots__ = ("a", "b")


def test_unpickling_a_value_of_another_shape_of_its_class_fails() -> None:
    """A value pickled before its class gained a field is refused, not built half-filled."""
    data = pickle.dumps(build_tree(Versioned, {}, {"a": 1, "b": 2}))
    assert pickle.loads(data) == build_tree(Versioned, {}, {"a": 1, "b": 2})
    module = sys.modules[__name__]
    original = module.Versioned
    grown = type("Versioned", (Group,), {"__slots__": ("a", "b", "c"), "__module__": __name__})
    module.Versioned = grown  # type: ignore[attr-defined]
    try:
        with pytest.raises(ValueError, match="zip"):
            pickle.loads(data)
    finally:
        module.Versioned = original  # type: ignore[attr-defined]
