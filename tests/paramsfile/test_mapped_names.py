"""check-params on names of mapped entries inside a namespace, at every depth."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main

SCHEMA = """\
genparams: 1
name: arm
parameters:
  joints: {type: string_array, default: [shoulder, elbow]}
  control:
    gains:
      for_each: joints
      p: {type: double, default: 1.0}
"""


def check(tmp_path: Path, lines: str, capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    schema = tmp_path / "arm.yaml"
    schema.write_text(SCHEMA, encoding="utf-8")
    params = tmp_path / "params.yaml"
    params.write_text("/**:\n  ros__parameters:\n" + lines, encoding="utf-8")
    code = main(["check-params", str(schema), str(params)])
    out = capsys.readouterr()
    return code, (out.out + out.err).replace(str(params), "params.yaml")


def test_entry_of_a_listed_key_passes(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert check(tmp_path, "    control.gains.shoulder.p: 3.0\n", capsys) == (0, "")


def test_entry_of_an_unlisted_key_is_a_warning(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert check(tmp_path, "    control.gains.wrist.p: 2.0\n", capsys) == (
        0,
        "params.yaml:3:5: control.gains.wrist.p: warning: 'wrist' is not among the items of "
        "joints; the node uses this only once they hold it\n",
    )


def test_a_key_no_entry_can_have_is_an_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert check(tmp_path, "    control.gains.bad*key.p: 1.0\n", capsys) == (
        1,
        "params.yaml:3:5: control.gains.bad*key.p: unknown parameter: 'bad*key' cannot be an "
        "item of joints (use any text but '.', '*', spaces and control characters): no entry would "
        "ever have this name\n",
    )


@pytest.mark.parametrize(
    ("name", "meant"),
    [
        ("control.gains.p", "control.gains.*.p"),  # one level short of the template
        ("control.gains.shoulder.p.x", "control.gains.shoulder.p"),  # one level too deep
        ("control.gain.shoulder.p", "control.gains.shoulder.p"),  # same depth, a typo
    ],
)
def test_names_of_another_shape_are_unknown(
    name: str, meant: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, report = check(tmp_path, f"    {name}: 1.0\n", capsys)
    assert (code, report) == (
        1,
        f"params.yaml:3:5: {name}: unknown parameter (did you mean {meant!r}?): "
        "ROS would ignore it\n",
    )


NESTED = """\
genparams: 1
name: nest
parameters:
  joints: {type: string_array, default: [a]}
  links: {type: string_array, default: [x]}
  gains:
    for_each: joints
    sub:
      for_each: links
      p: {type: double, default: 1.0}
"""


def test_entries_of_nested_groups_name_every_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    schema = tmp_path / "nest.yaml"
    schema.write_text(NESTED, encoding="utf-8")
    params = tmp_path / "params.yaml"
    lines = "    gains.b.sub.y.p: 2.0\n    gains.c.sub.y*.p: 2.0\n"
    params.write_text("/**:\n  ros__parameters:\n" + lines, encoding="utf-8")
    assert main(["check-params", str(schema), str(params)]) == 1
    out = capsys.readouterr()
    assert (out.out + out.err).replace(str(params), "params.yaml") == (
        "params.yaml:4:5: gains.c.sub.y*.p: unknown parameter: 'y*' cannot be an item of links "
        "(use any text but '.', '*', spaces and control characters): no entry would ever have "
        "this name\n"
        "params.yaml:3:5: gains.b.sub.y.p: warning: 'b.y' is not among the items of joints, "
        "links; the node uses this only once they hold it\n"
    )
