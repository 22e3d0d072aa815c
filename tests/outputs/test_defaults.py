"""genparams defaults: the file loads into a real node and changes nothing."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

from genparams.api import load_schema
from genparams.cli import main
from genparams.outputs.yaml_text import double_text, string_text
from genparams.paramsfile.ros_yaml import ros_scalar
from genparams.runtime.core.naming import ENTRY_KEY
from tests.golden import EXAMPLE_SCHEMA, output_cases
from tests.support import RosHarness, load_generated

# A value for each required parameter, given with -p: the defaults file leaves them out.
REQUIRED = {
    "example": {"serial": "ABCD1234"},
    "tricky": {"legacy.token": "abc"},
    "mapped": {"robot_id": "arm1"},
    "rules": {"serial": "S1"},
}


@pytest.mark.parametrize("case", output_cases(), ids=lambda case: case.name)
def test_defaults_file_round_trips_through_a_node(
    case: object, ros: RosHarness, tmp_path: Path
) -> None:
    from tests.golden import OutputCase

    assert isinstance(case, OutputCase)
    schema = load_schema(case.schema)
    params_file = tmp_path / "defaults.yaml"
    assert (
        main(["defaults", str(case.schema), "--node", "/robot/driver", "-o", str(params_file)]) == 0
    )
    required = REQUIRED[case.name]
    args = ["--params-file", str(params_file)]
    for name, value in required.items():
        args += ["-p", f"{name}:={value}"]
    node = ros.node("driver", namespace="/robot", args=args)
    # Every value in the file reached the node as an override, with the declared type.
    overrides = node._parameter_overrides
    fixed = [p for p in schema.parameters if ENTRY_KEY not in p.path]  # not mapped entries
    # ROS reads the subnormal back as a string; empty lists are left out (ROS: "not set").
    empty = {p.ros_name for p in fixed if p.type.is_array and not p.required and not p.default}
    unwritable = {"numbers.subnormal"} | empty
    written = {p.ros_name for p in fixed if not p.required} - unwritable
    assert written <= set(overrides)
    assert not unwritable & set(overrides)
    params_class = getattr(load_generated(case.schema, tmp_path), schema.class_name)
    cfg = params_class.declare(node)
    assert cfg.to_dict() == params_class.defaults(required).to_dict()
    assert set(overrides) <= set(node._parameters)  # mapped entries too: none left unused
    for parameter in fixed:
        assert node.get_parameter(parameter.ros_name).type_ == Parameter.Type(
            parameter.type.ros_type
        ), parameter.ros_name


@pytest.mark.parametrize(
    ("parameters", "given", "expected"),
    [
        ("  a: {type: bool, read_only: true}\n", {"a": "true"}, {"a": True}),
        (
            "  b: {type: int, default: 1}\n  ns:\n    a: {type: bool}\n"
            "    deeper: {c: {type: string}}\n  keys: {type: string_array}\n"
            "  entries: {for_each: keys, x: {type: int, default: 2}}\n",
            {"ns.a": "true", "ns.deeper.c": "x", "keys": "[k]"},
            {
                "b": 1,
                "ns": {"a": True, "deeper": {"c": "x"}},
                "keys": ("k",),
                "entries": {"k": {"x": 2}},
            },
        ),
    ],
    ids=["every parameter required", "a namespace of required parameters"],
)
def test_defaults_file_with_nothing_to_write_in_a_section_still_loads(
    parameters: str,
    given: dict[str, str],
    expected: dict[str, object],
    ros: RosHarness,
    tmp_path: Path,
) -> None:
    """rcl refuses a section or namespace with no value under it: those are commented out."""
    schema_path = tmp_path / "sparse.yaml"
    schema_path.write_text("genparams: 1\nname: sparse\nparameters:\n" + parameters)
    params_file = tmp_path / "defaults.yaml"
    assert main(["defaults", str(schema_path), "-o", str(params_file)]) == 0
    args = ["--params-file", str(params_file)]
    for name, value in given.items():
        args += ["-p", f"{name}:={value}"]
    node = ros.node(args=args)  # rcl parses the file here, or the node cannot be created
    cfg = load_generated(schema_path, tmp_path).SparseParams.declare(node)
    assert cfg.to_dict() == expected


def test_node_section_and_wildcard(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["defaults", str(EXAMPLE_SCHEMA)]) == 0
    out = capsys.readouterr().out
    assert "\n/**:\n  ros__parameters:\n" in out
    assert "    # serial:\n" in out  # required: commented out, with the reason above it
    assert "    # Required string: no default; the node does not start without it.\n" in out
    assert "      # Unit: Hz. Constraints: within [1.0, 120.0] in steps of 0.5.\n" in out
    assert main(["defaults", str(EXAMPLE_SCHEMA), "--node", "robot/camera"]) == 0
    assert "\n/robot/camera:\n" in capsys.readouterr().out
    assert main(["defaults", str(EXAMPLE_SCHEMA), "--node", "/robot/camera-1"]) == 2
    assert "invalid node name '/robot/camera-1'" in capsys.readouterr().err


@pytest.mark.parametrize(
    "value",
    [30.0, 0.1, 1e-5, 1e16, -2.5e-300, 1.7976931348623157e308, -0.0, math.inf, -math.inf],
)
def test_doubles_are_read_back_as_the_same_double(value: float) -> None:
    text = double_text(value)
    assert "." in text
    read = ros_scalar(text, None)
    assert (
        isinstance(read, float)
        and read == value
        and math.copysign(1, read) == math.copysign(1, value)
    )


@pytest.mark.parametrize(
    "value",
    [
        "30",
        "1.5",
        "true",
        "yes",
        "on",
        "null",
        "~",
        "",
        " x",
        "0x10",
        "inf",
        "NaN",
        "a: b",
        "#x",
        "[1]",
        "*star",
        "&a",
        "!tag",
        "%x",
        "@x",
        "'q'",
        '"q"',
        "a\nb",
        "\u2028",
        "\x85",
        "\x00",
        "tab\there",
        "日本",
        "plain",
        "/sensor/data",
    ],
)
def test_strings_are_read_back_as_the_same_string(value: str) -> None:
    import yaml

    text = string_text(value)
    document = yaml.compose(f"k: {text}\n")
    assert document is not None
    node = document.value[0][1]
    assert ros_scalar(node.value, node.style) == value
    assert yaml.safe_load(f"k: {text}\n") == {"k": value}
