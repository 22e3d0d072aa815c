"""Integers too long for Python to convert (past 4,300 digits) are problems, not tracebacks.

ROS reads such a value as strtol does (out of range), then strtod (out of range),
and keeps the text: a params file gets a wrong-type problem, a schema an invalid value.
"""

from __future__ import annotations

import contextlib
import io
from pathlib import Path

import pytest

from genparams.cli import main
from genparams.paramsfile.ros_yaml import ros_scalar
from tests.golden import ROOT, run_cli

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"
LONG = {
    "decimal": "9" * 5000,
    "negative": "-" + "9" * 5000,
    "hex": "0x" + "f" * 5000,
    "octal": "0" + "7" * 5000,
    "tiny double": "1." + "0" * 5000 + "1e-310",
}


@pytest.mark.parametrize("text", LONG.values(), ids=LONG.keys())
def test_ros_keeps_a_number_out_of_every_range_as_text(text: str) -> None:
    assert ros_scalar(text, None) == text


def run_printing(argv: list[str]) -> tuple[int, str]:
    """The command in-process: (exit code, what it printed on stdout and stderr)."""
    printed = io.StringIO()
    with contextlib.redirect_stderr(printed), contextlib.redirect_stdout(printed):
        code = main(argv)
    return code, printed.getvalue()


@pytest.mark.parametrize("text", LONG.values(), ids=LONG.keys())
def test_each_command_reports_the_value_as_a_wrong_type(text: str, tmp_path: Path) -> None:
    params = tmp_path / "long.yaml"
    params.write_text(
        f"/camera:\n  ros__parameters:\n    serial: ABCD1234\n    camera:\n      fps: {text}\n",
        encoding="utf-8",
    )
    shown = repr(text[:20])[:-1]  # the start of the value as the problem shows it
    problem = f"{params}:5:12: camera.fps: wrong type: expected double, got string {shown}"
    for argv in (
        ["check-params", str(SCHEMA), str(params)],
        ["check-deployment", str(params), "--map", f"/camera={SCHEMA}"],
        ["explain", "/camera", "--schema", str(SCHEMA), "--params-file", str(params)],
    ):
        code, output = run_printing(argv)
        assert code == 1, (argv, output)
        assert problem in output, (argv, output)


@pytest.mark.parametrize(
    ("place", "line"),
    [
        ("{type: int, default: VALUE}", "parameters.a.default"),
        ("{type: double, default: VALUE}", "parameters.a.default"),
        ("{type: int, default: 1, range: {min: 0, max: VALUE}}", "parameters.a.range.max"),
        ("{type: int, default: 1, validators: [{gt: VALUE}]}", "parameters.a.validators[0].gt"),
        ("{type: int_array, default: [VALUE]}", "parameters.a.default[0]"),
    ],
)
@pytest.mark.parametrize(
    "value", ["0x" + "f" * 5000, "-0x" + "f" * 5000, "0" + "7" * 5000, "0b" + "1" * 15_000]
)
def test_a_schema_integer_too_long_for_any_type_is_invalid(
    place: str, line: str, value: str, tmp_path: Path
) -> None:
    schema = tmp_path / "long.yaml"
    leaf = place.replace("VALUE", value)
    schema.write_text(f"genparams: 1\nname: x\nparameters:\n  a: {leaf}\n", encoding="utf-8")
    code, stderr = run_cli("validate", str(schema))
    assert code == 2, stderr
    assert f"{line}: invalid value: " in stderr, stderr
    assert " too large for any parameter type" in stderr, stderr
    assert "Traceback" not in stderr


def test_an_integer_past_int64_is_shown_cut(tmp_path: Path) -> None:
    schema = tmp_path / "long.yaml"
    value = "0b" + "1" * 5000  # 1,506 decimal digits: Python writes it, the message cuts it
    schema.write_text(
        f"genparams: 1\nname: x\nparameters:\n  a: {{type: int, default: {value}}}\n",
        encoding="utf-8",
    )
    code, stderr = run_cli("validate", str(schema))
    assert code == 2
    assert stderr.endswith(f"integer {str(int(value, 2))[:57]}... does not fit in int64\n")
