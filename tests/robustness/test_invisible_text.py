"""Text that does not show is escaped wherever a message repeats it.

A key ``gain`` + U+200B (zero-width space) must not read as ``gain`` next to
"did you mean 'gain'?", and U+202E (right-to-left override) must not reverse
the terminal line it is printed on.
"""

from __future__ import annotations

import contextlib
import io
from pathlib import Path

import pytest

from genparams.cli import main
from genparams.runtime.core.visible import visible
from genparams.schema.errors import Location, SchemaProblem
from tests.golden import ROOT

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"
ZWSP, RLO = "\u200b", "\u202e"


@pytest.mark.parametrize(
    ("text", "shown"),
    [
        ("gain" + ZWSP, "gain\\u200b"),
        ("x" + RLO + "cba", "x\\u202ecba"),
        ("\u202a\u2066\u200f\u061c", "\\u202a\\u2066\\u200f\\u061c"),  # other bidi controls
        ("a\nb\tc\rd\x00\x1b[2J", "a\\nb\\tc\\rd\\x00\\x1b[2J"),  # line breaks, escapes
        ("nb\xa0sp\u3000", "nb\\xa0sp\\u3000"),  # spaces other than the space
        ("soft\xadhy\ufeffbom", "soft\\xadhy\\ufeffbom"),
        ("a\u034fb\u3164c\ufe0f", "a\\u034fb\\u3164c\\ufe0f"),  # printable, yet invisible
        ("tag\U000e0041", "tag\\U000e0041"),
        ("\ud800", "\\ud800"),  # a lone surrogate
        ("\u2028\u2029", "\\u2028\\u2029"),
    ],
)
def test_what_does_not_show_is_escaped(text: str, shown: str) -> None:
    assert visible(text) == shown
    assert visible(shown) == shown  # escaping twice changes nothing


@pytest.mark.parametrize("text", ["camera.fps", "café", "π ≥ 3", "日本語", "✓ done", "a\\u200b"])
def test_text_that_shows_is_left_as_written(text: str) -> None:
    assert visible(text) == text


def test_every_schema_problem_is_one_visible_line() -> None:
    problem = SchemaProblem(Location("p.yaml", 3, 5), "gain" + ZWSP, "bad\nvalue " + RLO)
    assert str(problem) == "p.yaml:3:5: gain\\u200b: bad\\nvalue \\u202e"


def run(*argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(argv))
    return code, out.getvalue(), err.getvalue()


@pytest.fixture
def params(tmp_path: Path) -> Path:
    file = tmp_path / "params.yaml"
    file.write_text(
        "/**:\n  ros__parameters:\n    serial: ABCD1234\n"
        f"    robot_name{ZWSP}: r2\n    camera:\n      f{RLO}spf: 2.0\n",
        encoding="utf-8",
    )
    return file


def no_raw(*texts: str) -> bool:
    return not any(char in text for text in texts for char in (ZWSP, RLO))


def test_check_params_shows_the_difference_from_its_suggestion(params: Path) -> None:
    code, out, err = run("check-params", str(SCHEMA), str(params))
    assert code == 1 and err == ""
    assert out.splitlines() == [
        f"{params}:4:5: robot_name\\u200b: unknown parameter (did you mean 'robot_name'?): "
        "ROS would ignore it",
        f"{params}:6:7: camera.f\\u202espf: unknown parameter (did you mean 'camera.fps'?): "
        "ROS would ignore it",
    ]


def test_explain_escapes_its_table_and_its_problems(params: Path) -> None:
    code, out, err = run("explain", "/cam", "--schema", str(SCHEMA), "--params-file", str(params))
    assert code == 1 and err == "" and no_raw(out)
    lines = out.splitlines()
    column = lines[1].index("value")  # the header; the columns line up on the escaped text
    rows = {line.split()[0]: line[column:].split()[0] for line in lines[2:] if line.strip()}
    assert rows["robot_name\\u200b"] == "r2"
    assert rows["camera.f\\u202espf"] == "2.0"
    assert rows["robot_name"] == "my_robot"
    assert "  " + f"{params}:4:5: robot_name\\u200b: unknown parameter" in out


def test_check_deployment_escapes_params_keys(params: Path) -> None:
    params.write_text(params.read_text(encoding="utf-8").replace("/**", "/cam"), "utf-8")
    code, out, err = run("check-deployment", str(params), "--map", f"/cam={SCHEMA}")
    assert code == 1 and err == "" and no_raw(out)
    assert "robot_name\\u200b: unknown parameter (did you mean 'robot_name'?)" in out


def test_schema_errors_escape_names_and_values(tmp_path: Path) -> None:
    schema = tmp_path / "cam.yaml"
    schema.write_text(
        "genparams: 1\nname: cam\nparameters:\n"
        f"  gain{ZWSP}: {{type: double, default: 1.0}}\n"
        f'  mode: {{type: string, default: "a{RLO}b", choices: [a, b]}}\n',
        encoding="utf-8",
    )
    code, _, err = run("validate", str(schema))
    assert code == 2 and no_raw(err)
    assert f"{schema}:4:3: parameters.gain\\u200b: invalid name 'gain\\u200b'" in err
    assert "got 'a\\u202eb'" in err


def test_import_gpl_escapes_names(tmp_path: Path) -> None:
    gpl = tmp_path / "ctl.yaml"
    gpl.write_text(
        f"ctl:\n  gain{RLO}:\n    type: double\n    default_value: 1.0\n    description: g\n",
        encoding="utf-8",
    )
    code, out, err = run("import-gpl", str(gpl))
    assert code == 2 and out == "" and no_raw(err)
    assert "parameters.gain\\u202e: invalid name 'gain\\u202e'" in err
    assert f"genparams import-gpl: {gpl}: the imported schema is not valid" in err


def test_command_line_text_is_escaped(tmp_path: Path) -> None:
    code, _, err = run("explain", "/cam", "-p", f"gain{RLO}:=[")
    assert code == 2 and err.startswith("genparams explain: -p 'gain\\u202e:=[': ")
    code, _, err = run("check-params", str(SCHEMA), str(tmp_path / "p.yaml"), "--node", f"/a{ZWSP}")
    assert code == 2 and err.startswith("genparams check-params: invalid --node '/a\\u200b': ")
    assert no_raw(err)


def test_a_file_name_that_does_not_show_is_escaped(tmp_path: Path) -> None:
    missing = tmp_path / f"params{RLO}lmay.yaml"
    code, _, err = run("check-params", str(SCHEMA), str(missing))
    assert code == 2
    assert err.startswith(f"{tmp_path}/params\\u202elmay.yaml:1:1: cannot read params file: ")
