"""-p rules as explain reads them, word for word: how a rule splits into node, name and value,
how its value is typed, where its problems are placed, and what rcl would refuse."""

from __future__ import annotations

from pathlib import Path

import pytest
from rclpy.impl.implementation_singleton import rclpy_implementation

from genparams.api import load_schema
from genparams.cli import main
from genparams.outputs.explain_text import text_report
from genparams.paramsfile.check_params import Bound
from genparams.paramsfile.explain import explain, overrides_document
from tests.support import ROOT, RosHarness

CAMERA = """\
genparams: 1
name: cam
description: A camera.
parameters:
  fps: {type: double, default: 30.0, description: Frames per second.}
  label: {type: string, default: "", description: A label.}
  sizes: {type: int_array, default: [1], description: Sizes.}
  names: {type: string_array, default: [a], description: Names.}
"""


@pytest.fixture
def schema(tmp_path: Path) -> str:
    path = tmp_path / "cam.yaml"
    path.write_text(CAMERA, encoding="utf-8")
    return str(path)


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str], str]:
    code = main(["explain", *argv])
    out, err = capsys.readouterr()
    return code, out.splitlines(), err


def test_rules_are_typed_and_numbered_in_order(
    schema: str, capsys: pytest.CaptureFixture[str]
) -> None:
    rules = ["fps:=5", "label:=a:=b", 'names:=["5", six]', "sizes:=[3, 4]", "cma:fps:=1.0"]
    code, out, err = run(capsys, "/cam", "--schema", schema, *(a for r in rules for a in ("-p", r)))
    assert (code, err) == (1, "")
    assert out == [
        "/cam: 4 section(s) apply, in rcl's order",
        "parameter  value       source                shadowed",
        "fps        30.0        default",
        'label      "a:=b"      -p (rule 2, for /**)  "" from default',
        'names      ["5", six]  -p (rule 3, for /**)  [a] from default',
        "sizes      [3, 4]      -p (rule 4, for /**)  [1] from default",
        "",
        "What ROS would ignore or refuse:",
        "  -p:1:1: fps: wrong type: expected double, got integer 5 (ROS does not convert: "
        "write 5.0)",
        "  -p:5:1: /cma: section for another node: node name 'cma' is close to 'cam': a typo?",
    ]


def test_an_empty_list_is_not_set_and_a_quoted_number_a_string(
    schema: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = run(capsys, "/cam", "--schema", schema, "-p", "label:=[]", "-p", 'label:="7"')
    assert (code, err) == (1, "")
    assert out == [
        "/cam: 2 section(s) apply, in rcl's order",
        "parameter  value  source                shadowed",
        "fps        30.0   default",
        'label      "7"    -p (rule 2, for /**)  "" from default',
        "names      [a]    default",
        "sizes      [1]    default",
        "",
        "What ROS would ignore or refuse:",
        '  -p:1:1: label: ROS reads an empty list as "not set", which the node refuses: leave '
        "the parameter out to keep its default",
    ]


@pytest.mark.parametrize(
    ("rule", "shown"),
    [("fps:=[]", "(not set)"), ("fps:=''", '""'), ("fps:=~", '"~"'), ("fps:=[1, '2']", '[1, "2"]')],
)
def test_without_a_schema_a_value_is_shown_as_rcl_reads_it(
    rule: str, shown: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = run(capsys, "/cam", "-p", rule)
    assert (code, err) == (0, "")
    assert out[2].split() == ["fps", *shown.split(), "-p", "(rule", "1,", "for", "/**)"]


@pytest.mark.parametrize(
    ("rule", "message"),
    [
        ("fps", "expected NAME:=VALUE or NODE:NAME:=VALUE"),
        ("cam::=1.0", "expected NAME:=VALUE or NODE:NAME:=VALUE"),
        (":=1.0", "expected NAME:=VALUE or NODE:NAME:=VALUE"),
        ("a:b:fps:=1.0", "the node is one name, without namespace or wildcard"),
        ("ns/cam:fps:=1.0", "the node is one name, without namespace or wildcard"),
        ("fps:=[1", "not a YAML value (ParserError)"),
        ("fps:=!!str", "no value"),
        ("fps:=|", "no value"),
        ("fps:=", "a value is a scalar or a flat list"),
        ("fps:={a: 1}", "a value is a scalar or a flat list"),
        ("fps:=[[1]]", "a value is a scalar or a flat list"),
    ],
)
def test_a_rule_rcl_refuses_is_named(
    rule: str, message: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = run(capsys, "/cam", "-p", rule)
    assert (code, out) == (2, [])
    assert err == f"genparams explain: -p {rule!r}: {message}\n"


def test_a_deep_rule_value_is_refused_before_it_is_composed(
    capsys: pytest.CaptureFixture[str],
) -> None:
    rule = "fps:=" + "[" * 100_000 + "]" * 100_000
    code, out, err = run(capsys, "/cam", "-p", rule)
    assert (code, out) == (2, [])
    assert err.endswith(": nested deeper than 64 levels\n")


def test_rules_given_together_are_numbered_from_one() -> None:
    bound = Bound(load_schema("cam.yaml", CAMERA), "")
    explanation = explain([bound], [overrides_document(["label:=x", "cam:fps:=2.0"])], "/cam")
    assert text_report(explanation).splitlines()[:4] == [
        "/cam: 2 section(s) apply, in rcl's order",
        "parameter  value  source                 shadowed",
        "fps        2.0    -p (rule 2, for /cam)  30.0 from default",
        'label      x      -p (rule 1, for /**)   "" from default',
    ]


@pytest.mark.parametrize(
    "name", ["max-speed", "9a", "a.9b", "input_shape/height", "a/b.c", "_a", "a.type", "a//b"]
)
def test_a_rule_name_is_read_as_rcl_reads_it(
    name: str, ros: RosHarness, capsys: pytest.CaptureFixture[str]
) -> None:
    """A name with '-' or a digit first is refused by rcl's -p parser, and by explain."""
    code, _out, err = run(capsys, "/cam", "-p", f"{name}:=1")
    try:
        node = ros.node("cam", args=["-p", f"{name}:=1"])
    except rclpy_implementation.RCLInvalidROSArgsError:
        assert (code, err) == (
            2,
            f"genparams explain: -p '{name}:=1': rcl reads a name of letters, digits and '_' "
            "between '.' and '/' here (no digit first); give other names in a params file\n",
        )
    else:
        assert name in node._parameter_overrides
        assert (code, err) == (0, "")


def test_names_holding_dashes_slashes_and_type_are_explained(
    capsys: pytest.CaptureFixture[str],
) -> None:
    case = ROOT / "tests" / "cases" / "ros_names"
    params = case / "check_params" / "ros_names_good" / "params.yaml"
    schema = str(case / "schema.yaml")
    code, out, err = run(
        capsys, "/teleop", "--schema", schema, "--params-file", str(params),
        "-p", "input_shape/height:=100",
    )  # fmt: skip
    assert (code, err) == (0, "")
    rows = {line.split()[0]: line.split()[1:3] for line in out[2:]}
    assert rows["input_shape/height"] == ["100", "-p"]
    assert rows["walk_button.axis_mappings.twist-linear-x.axis"][0] == "4"
    assert rows["walk_button.type"][0] == "action"
    assert rows["buttons.deadman-switch.type"][0] == "hold"
    assert rows["max-speed"][0] == "2.5"
