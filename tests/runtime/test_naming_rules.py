"""The naming rules: ROS parameter names, the Python names made from them, prefixes, the
keys of mapped entries, and node names in params files, each with its exact verdict."""

from __future__ import annotations

import pytest

from genparams.runtime.core.naming import (
    absolute,
    attribute_name,
    attribute_parts,
    class_name,
    entry_key_problem,
    is_entry_key,
    is_ros_name,
    is_ros_token,
    join_prefix,
    module_name,
    node_name_problem,
    node_pattern_problem,
    pascal_case,
    strip_prefix,
)


@pytest.mark.parametrize(
    ("name", "token", "dotted"),
    [
        ("speed", True, True),
        ("Max_speed2", True, True),
        ("camera.fps", False, True),
        ("a.b.c", False, True),
        ("_hidden", False, False),
        ("2d", False, False),
        ("a-b", True, True),
        ("twist-linear-x", True, True),
        ("walk.twist-linear-x.type", False, True),
        ("input_shape/height", True, True),
        ("a-", True, True),
        ("a//b", False, False),
        ("a/", False, False),
        ("/a", False, False),
        ("a/2d", False, False),
        ("-a", False, False),
        ("a b", False, False),
        ("a:b", False, False),
        ("ü", False, False),
        ("", False, False),
        ("a..b", False, False),
        ("a.", False, False),
        ("camera.2d", False, False),
    ],
)
def test_ros_names(name: str, token: bool, dotted: bool) -> None:
    assert is_ros_token(name) is token
    assert is_ros_name(name) is dotted


@pytest.mark.parametrize(
    ("keys", "problem"),
    [
        (["left", "right-arm", "1st", "wheel/pos"], None),
        ([], None),
        (
            ["left", "left"],
            "item 1 'left' repeats: each item names one entry of wheels",
        ),
        (
            ["left", "a.b"],
            "item 1 'a.b' cannot name an entry of wheels: use any text but '.', '*', "
            "spaces and control characters",
        ),
        (
            [""],
            "item 0 '' cannot name an entry of wheels: use any text but '.', '*', "
            "spaces and control characters",
        ),
        (
            ["a b"],
            "item 0 'a b' cannot name an entry of wheels: use any text but '.', '*', "
            "spaces and control characters",
        ),
    ],
)
def test_entry_keys(keys: list[str], problem: str | None) -> None:
    assert entry_key_problem(keys, "wheels") == problem


def test_entry_key_text() -> None:
    assert [is_entry_key(k) for k in ("x", "*", "a\tb", "a\x7f", "é")] == [
        True,
        False,
        False,
        False,
        True,
    ]


@pytest.mark.parametrize(
    ("token", "top_level", "attribute"),
    [
        ("speed", False, "speed"),
        ("from", False, "from_"),
        ("lambda", True, "lambda_"),
        ("int", False, "int_"),
        ("ClassVar", False, "ClassVar_"),
        ("declare", True, "declare_"),
        ("declare", False, "declare"),
        ("changes", True, "changes_"),
        ("remote", True, "remote_"),
        ("speed", True, "speed"),
        ("twist-linear-x", False, "twist_linear_x"),
        ("input_shape/height", True, "input_shape_height"),
        ("from-", False, "from_"),
        ("class-", False, "class_"),
        ("on-change", True, "on_change_"),
        ("on-change", False, "on_change"),
        ("int-", False, "int_"),
        ("type", False, "type"),
    ],
)
def test_attribute_names(token: str, top_level: bool, attribute: str) -> None:
    assert attribute_name(token, top_level=top_level) == attribute


def test_attribute_parts_reserve_method_names_at_the_top_level_only() -> None:
    assert attribute_parts("snapshot.snapshot.from") == ("snapshot_", "snapshot", "from_")
    assert attribute_parts("speed") == ("speed",)
    assert attribute_name("to_dict") == "to_dict"


@pytest.mark.parametrize(
    ("schema", "pascal", "cls", "module"),
    [
        ("motion", "Motion", "MotionParams", "motion_params"),
        ("my_robot_x", "MyRobotX", "MyRobotXParams", "my_robot_x_params"),
        ("a__b_", "AB", "ABParams", "a__b__params"),
        ("lidar2d", "Lidar2d", "Lidar2dParams", "lidar2d_params"),
    ],
)
def test_generated_names(schema: str, pascal: str, cls: str, module: str) -> None:
    assert pascal_case(schema) == pascal
    assert class_name(schema) == cls
    assert module_name(schema) == module


def test_group_class_words_split_at_dashes_and_slashes() -> None:
    assert pascal_case("twist-linear-x") == "TwistLinearX"
    assert pascal_case("input_shape/height") == "InputShapeHeight"


@pytest.mark.parametrize(
    ("prefix", "name", "joined"),
    [
        ("", "fps", "fps"),
        ("front", "fps", "front.fps"),
        (".front.", "fps", "front.fps"),
        ("a.b", "c.d", "a.b.c.d"),
        (".", "fps", "fps"),
        ("Xarm.", "fps", "Xarm.fps"),
        ("armX", "fps", "armX.fps"),
    ],
)
def test_join_prefix(prefix: str, name: str, joined: str) -> None:
    assert join_prefix(prefix, name) == joined


@pytest.mark.parametrize(
    ("prefix", "full_name", "relative"),
    [
        ("", "camera.fps", "camera.fps"),
        (".", "fps", "fps"),
        ("front", "front.fps", "fps"),
        ("front.", "front.camera.fps", "camera.fps"),
        ("front", "frontal.fps", None),
        ("front", "rear.fps", None),
        ("front", "front", None),
        ("a.b", "a.b.c", "c"),
        ("Xarm", "Xarm.fps", "fps"),
        ("armX.", "armX.fps", "fps"),
    ],
)
def test_strip_prefix(prefix: str, full_name: str, relative: str | None) -> None:
    assert strip_prefix(prefix, full_name) == relative


def test_absolute() -> None:
    assert absolute("camera") == "/camera"
    assert absolute("/ns/camera") == "/ns/camera"


@pytest.mark.parametrize(
    ("name", "as_node", "as_pattern"),
    [
        ("/ns/camera", None, None),
        ("camera", None, None),
        ("_private/_cam2", None, None),
        ("/", "node name must not be empty", "node name must not be empty"),
        ("", "node name must not be empty", "node name must not be empty"),
        ("ns/", "node name must not be empty", "node name must not be empty"),
        (
            "/ns//camera",
            "contains repeated forward slash",
            "contains repeated forward slash",
        ),
        (
            "/ns/*",
            "node name '*' may hold only letters, digits and '_'",
            None,
        ),
        (
            "/**/camera",
            "namespace '**' may hold only letters, digits and '_'",
            None,
        ),
        (
            "/1ns/camera",
            "namespace must not start with a number: '1ns'",
            "namespace must not start with a number: '1ns'",
        ),
        (
            "/ns/2cam",
            "node name must not start with a number: '2cam'",
            "node name must not start with a number: '2cam'",
        ),
        (
            "/ns/cam-1",
            "node name 'cam-1' may hold only letters, digits and '_'",
            "node name 'cam-1' may hold only letters, digits and '_'",
        ),
        (
            "/**/*/cam-1",
            "namespace '**' may hold only letters, digits and '_'",
            "node name 'cam-1' may hold only letters, digits and '_'",
        ),
        (
            "/*a/cam",
            "namespace '*a' may hold only letters, digits and '_'",
            "namespace '*a' may hold only letters, digits and '_'",
        ),
    ],
)
def test_node_names(name: str, as_node: str | None, as_pattern: str | None) -> None:
    assert node_name_problem(name) == as_node
    assert node_pattern_problem(name) == as_pattern
