"""Where check-params places a problem with no line of its own, and how it names a duplicate."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.api import load_schema
from genparams.paramsfile.check_params import Bound, check_files
from genparams.paramsfile.explain import explain
from genparams.paramsfile.params_reader import read_params_file
from tests.paramsfile.rcl_load import overrides

CAMERA = load_schema(
    "camera.yaml",
    "genparams: 1\nname: camera\nparameters:\n"
    "  fps: {type: int, default: 30}\n  serial: {type: string}\n",
)
NESTED = "/a:\n  ros__parameters:\n    ros__parameters:\n      x: 1\n      x: 2\n"
MISSING = "serial: required parameter is not set (it has no default: add serial: <string>)"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("", [f"p.yaml:1:1: {MISSING}"]),
        ("# nothing yet\n", [f"p.yaml:1:1: {MISSING}"]),
        (
            "/**:\n  ros__parameters:\n    fps: 10\n    fps: 12\n",
            [
                f"p.yaml:2:3: {MISSING}",
                "p.yaml:4:5: fps: duplicate key (first defined at line 3, column 5); "
                "ROS keeps the later value",
            ],
        ),
    ],
    ids=["empty", "comment", "duplicate"],
)
def test_a_missing_required_parameter_is_reported_in_any_readable_file(
    text: str, expected: list[str]
) -> None:
    report = check_files([Bound(CAMERA)], [read_params_file(text, "p.yaml")])
    assert [str(p) for p in report.problems] == expected


def test_without_a_file_the_place_is_a_dash() -> None:
    explanation = explain([Bound(CAMERA)], [], "/camera")
    assert [str(p) for p in explanation.report.problems] == [
        f"-:1:1: {MISSING.replace('not set', 'not set for /camera')}"
    ]


def test_a_duplicate_is_named_as_ros_names_the_parameter() -> None:
    document = read_params_file(NESTED, "p.yaml")
    assert [str(p) for p in document.problems] == [
        "p.yaml:5:7: ros__parameters.x: duplicate key (first defined at line 4, column 7); "
        "ROS keeps the later value"
    ]


def test_rcl_names_a_nested_ros_parameters_key_as_a_parameter(tmp_path: Path) -> None:
    params = tmp_path / "p.yaml"
    params.write_text(NESTED, encoding="utf-8")
    assert overrides("/a", ["--params-file", str(params)]) == {"ros__parameters.x": 2}


def test_a_duplicate_node_key_is_named_by_the_node() -> None:
    text = "/a:\n  ros__parameters:\n    x: 1\n/a:\n  ros__parameters:\n    x: 2\n"
    document = read_params_file(text, "p.yaml")
    assert [p.key for p in document.problems] == ["/a"]


@pytest.mark.parametrize(
    ("line", "problem"),
    [
        ("    x: !!set {a}\n", "p.yaml:3:8: x: unsupported YAML tag tag:yaml.org,2002:set"),
        ("    ? [a]\n    : 1\n", "p.yaml:3:7: /a.ros__parameters: keys must be plain strings"),
        ('    "x\\0": 1\n', "p.yaml:3:5: x\\x00: text cannot contain NUL"),
    ],
    ids=["tag", "key not a string", "NUL in a key"],
)
def test_only_a_duplicate_key_says_ros_keeps_the_later_value(line: str, problem: str) -> None:
    text = "/a:\n  ros__parameters:\n" + line + "    y: 1\n    y: 2\n"
    other, duplicate = (str(p) for p in read_params_file(text, "p.yaml").problems)
    assert other.startswith(problem) and "later value" not in other
    assert "y: duplicate key" in duplicate and duplicate.endswith("; ROS keeps the later value")
