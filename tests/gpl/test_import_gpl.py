"""`genparams import-gpl`: the command, its messages and exit codes, and golden imports.

Update the golden files after an intended change: python -m tests.gpl.test_import_gpl
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

from genparams.cli import main
from tests import corpus
from tests.support import RosHarness, load_generated

GOLDEN = Path(__file__).parent / "golden"
SOURCES = Path(__file__).parent / "sources"
# GPL files written for these tests, in real packages' shapes: each construct the import maps
# (maps at the top and beside parameters, custom validators with and without arguments, NaN
# defaults, a `defaults` namespace, required and open parameters). The real schemas of the
# corpus are imported in tests/gpl/test_corpus.py.
CASES = {"conveyor_controller": SOURCES / "conveyor_controller_parameters.yaml"}
CONVEYOR = CASES["conveyor_controller"]
# GPL's own files that GPL refuses, in the corpus (tests/corpus.py).
INVALID = "generate_parameter_library/generate_parameter_library_py_test/schema_invalid"


def run(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    code = main(["import-gpl", *args])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


@pytest.mark.parametrize("name", sorted(CASES))
def test_import_matches_golden(
    name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(capsys, str(CASES[name]), "--out-dir", str(tmp_path))
    assert code == 0, err
    written = sorted(p.name for p in tmp_path.iterdir())
    expected = sorted(p.name for p in GOLDEN.glob(f"{name}*"))
    assert written == expected
    for file in written:
        assert (tmp_path / file).read_text("utf-8") == (GOLDEN / file).read_text("utf-8"), file


def test_report_lists_custom_validators_and_required_parameters(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(capsys, str(CONVEYOR), "-o", str(tmp_path / "c.yaml"))
    assert code == 0
    assert (
        f"{CONVEYOR}:6:5: conveyor_controller.belts.default_value: note: default [] "
        "breaks its own validator (must not be empty (not_empty)): imported as a required "
        "parameter"
    ) in err.splitlines()
    assert (
        "custom validators to implement in conveyor_controller_checks (stubs in "
        f"{tmp_path / 'conveyor_controller_checks.py'}): gt_eq_or_nan, interface_combinations, "
        "lt_eq_or_nan"
    ) in err
    assert err.rstrip().endswith("imported 13 of 13 parameters")


def test_stdout_when_no_output_is_given(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, str(CONVEYOR))
    assert code == 0
    assert out == (GOLDEN / "conveyor_controller.yaml").read_text("utf-8")


def test_what_cannot_be_mapped_is_a_warning_at_its_place(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "gpl.yaml"
    source.write_text(
        "ctrl:\n"
        "  joints: {type: string_array, default_value: [a]}\n"
        "  gains:\n"
        "    __map_joints:\n"
        "      p: {type: double, default_value: 1.0}\n"
        "    __map_joints2:\n"
        "      i: {type: double, default_value: 1.0}\n"
        "  odd: {type: quaternion, default_value: 1}\n"
        "  lim: {type: double_array, default_value: [1.0], validation: {gt<>: [0.0]}}\n"
        "  rate: {type: double, default_value: 1.0, unit: Hz}\n",
        encoding="utf-8",
    )
    out = tmp_path / "ctrl.yaml"
    code, _, err = run(capsys, str(source), "-o", str(out))
    assert code == 1  # written, but something was left out
    assert err.splitlines()[:4] == [
        f"{source}:6:5: ctrl.gains.__map_joints2: warning: a second map in one namespace: ROS "
        "names could not tell the two maps' entries apart; its parameters are left out",
        f"{source}:8:9: ctrl.odd.type: warning: unknown type 'quaternion': parameter left out",
        f"{source}:9:64: ctrl.lim.validation.gt<>: warning: gt on an array has no genparams form "
        "(strict bound): validator left out",
        f"{source}:10:44: ctrl.rate.unit: warning: unknown GPL key 'unit': left out",
    ]
    assert err.rstrip().endswith("imported 4 of 6 parameters; 2 left out (see warnings)")
    assert "gains:\n    for_each: joints\n    p:" in out.read_text("utf-8")


@pytest.mark.parametrize(
    "text, message",
    [
        ("a: 1\nb: 2\n", "exactly one top-level key"),
        ("a: [1]\n", "does not hold parameters"),
        ("a: {b: 1\n", "expected ',' or '}'"),
    ],
)
def test_bad_input_exits_2_and_writes_nothing(
    text: str, message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "bad.yaml"
    source.write_text(text, encoding="utf-8")
    code, out, err = run(capsys, str(source), "--out-dir", str(tmp_path / "out"))
    assert (code, out) == (2, "")
    assert message in err and err.startswith(str(source))
    assert not (tmp_path / "out").exists()


def test_adopt_marks_the_parameter(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "conveyor.yaml"
    code, _, _ = run(capsys, str(CONVEYOR), "-o", str(target), "--adopt", "diagnostics.verbose")
    assert code == 0
    assert "  diagnostics:\n    verbose:\n      type: bool\n" in target.read_text("utf-8")
    assert "      adopt: true\n" in target.read_text("utf-8")
    assert "adopt" not in (GOLDEN / "conveyor_controller.yaml").read_text("utf-8")


def test_runs_as_a_command() -> None:
    result = subprocess.run(
        [sys.executable, "-m", "genparams", "import-gpl", str(CONVEYOR)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0 and result.stdout.startswith("# genparams schema imported")


def write_goldens() -> None:
    GOLDEN.mkdir(exist_ok=True)
    for old in GOLDEN.iterdir():
        old.unlink()
    for source in CASES.values():
        main(["import-gpl", str(source), "--out-dir", str(GOLDEN)])


if __name__ == "__main__":
    write_goldens()


@pytest.mark.parametrize(
    "name, first_line",
    [
        ("wrong_default_type", "4:20: namespace.param_name.default_value: wrong default: "
         "expected double, got string 'string type'"),
        ("invalid_parameter_type", "3:5: namespace.param_name.type: warning: unknown type "
         "'string_non-type': parameter left out"),
        ("missing_type", "3:5: namespace.param_name.description: warning: neither a parameter "
         "(no type:) nor a namespace: left out"),
        ("invalid_syntax", "5:3: invalid YAML: while parsing a block mapping did not find "
         "expected key"),
    ],
)  # fmt: skip
def test_files_gpl_refuses_are_refused_at_their_place(
    name: str, first_line: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = corpus.folder("gpl") / INVALID / f"{name}.yaml"
    code, out, err = run(capsys, str(source), "--out-dir", str(tmp_path))
    assert (code, out, list(tmp_path.iterdir())) == (2, "", [])
    assert err.splitlines()[0] == f"{source}:{first_line}"


def test_a_custom_validator_with_one_argument_not_in_a_list(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """GPL takes `"ns::above<>": 0.5` as the argument list [0.5], as it does for built-ins."""
    source = tmp_path / "scalar.yaml"
    source.write_text(
        "c:\n  n:\n    type: double\n    default_value: 1.0\n"
        '    validation:\n      "ns::above<>": 0.5\n',
        encoding="utf-8",
    )
    code, _, err = run(capsys, str(source), "--out-dir", str(tmp_path))
    assert code == 0, err
    schema = (tmp_path / "c.yaml").read_text("utf-8")
    assert "{custom: {function: 'c_checks:above', args: [0.5]}}" in schema
    assert "def above(value: Any, arg0: Any) -> str | None:" in (
        tmp_path / "c_checks.py"
    ).read_text("utf-8")


def test_a_parameter_named_type_is_kept_and_declared(
    ros: RosHarness, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """GPL reads a mapping whose first value is a mapping as a namespace, so `type:` can name
    a parameter; the import keeps it, and the generated class declares it there."""
    source = tmp_path / "teleop.yaml"
    source.write_text(
        "teleop:\n"
        "  walk:\n"
        "    type:\n"
        "      type: string\n"
        "      default_value: topic\n"
        "      validation:\n"
        '        one_of<>: [["topic", "action"]]\n'
        "    topic_name: {type: string, default_value: cmd_vel}\n",
        encoding="utf-8",
    )
    target = tmp_path / "teleop_schema.yaml"
    code, _, err = run(capsys, str(source), "-o", str(target))
    assert (code, err) == (0, "imported 2 of 2 parameters\n")
    module = load_generated(target, tmp_path)
    node = ros.node()
    cfg = module.TeleopParams.declare(node)
    assert (cfg.walk.type, node.get_parameter("walk.type").value) == ("topic", "topic")
    (refused,) = ros.client(node).set(Parameter("walk.type", value="jump"))
    assert not refused.successful and cfg.walk.type == "topic"
