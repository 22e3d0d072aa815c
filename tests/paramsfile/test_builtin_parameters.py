"""Parameters every rclpy node declares itself: checked for their type, never "unknown"."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from tests.support import ROOT

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"


def check(tmp_path: Path, lines: str, capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    params = tmp_path / "params.yaml"
    text = "/**:\n  ros__parameters:\n    serial: ABCD1234\n" + lines
    params.write_text(text, encoding="utf-8")
    code = main(["check-params", str(SCHEMA), str(params)])
    out = capsys.readouterr()
    return code, (out.out + out.err).replace(str(params), "params.yaml")


@pytest.mark.parametrize(
    "lines",
    [
        "    use_sim_time: true\n",
        "    start_type_description_service: false\n",
        "    qos_overrides./camera/image.publisher.depth: 5\n",
    ],
)
def test_builtin_parameters_of_the_right_type_pass(
    lines: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert check(tmp_path, lines, capsys) == (0, "")


@pytest.mark.parametrize(
    ("value", "got"),
    [("1", "integer 1"), ("'yes'", "string 'yes'"), ("[true]", "a list [True]")],
)
def test_builtin_parameters_of_a_wrong_type_are_refused(
    value: str, got: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, report = check(tmp_path, f"    use_sim_time: {value}\n", capsys)
    assert (code, report) == (
        1,
        f"params.yaml:4:19: use_sim_time: wrong type: expected bool, got {got}\n",
    )
