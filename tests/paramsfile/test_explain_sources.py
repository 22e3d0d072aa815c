"""explain's table, word for word: each value's source and what it shadows, across files, an
old name, mapped entries, a prefixed class, values the node refuses, and who owns the keys no
schema declares (rclpy, other code, nobody)."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.api import load_schema
from genparams.cli import main
from genparams.paramsfile.check_params import Bound
from genparams.paramsfile.explain import explain as explain_node
from genparams.paramsfile.params_reader import read_params_file

ARM = """\
genparams: 1
name: arm
description: An arm.
parameters:
  max_speed: {type: double, default: 1.0, aliases: [speed_limit], description: Top speed.}
  joints: {type: string_array, default: [shoulder], description: Joints.}
  mode: {type: string, description: Mode.}
  gains:
    for_each: joints
    p: {type: double, default: 1.0, description: Gain.}
"""
TOOL = """\
genparams: 1
name: tool
description: A tool.
parameters:
  grip: {type: double, default: 0.5, description: Grip force.}
"""
BASE = """\
/arm:
  ros__parameters:
    speed_limit: 2.0
    joints: [shoulder, wrist]
    gains:
      wrist: {p: 3.0}
    use_sim_time: true
    qos_overrides./tf.publisher.depth: 5
    plugin.rate: 10
    colour: red
"""
OVER = """\
/**:
  ros__parameters:
    max_speed: fast
    tool.grip: 0.7
/arm:
  ros__parameters:
    max_speed: 4.0
    gains.wrist.p: 4
"""


@pytest.fixture(autouse=True)
def files(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for name, text in {
        "arm.yaml": ARM,
        "tool.yaml": TOOL,
        "base.yaml": BASE,
        "over.yaml": OVER,
    }.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    monkeypatch.chdir(tmp_path)  # file names in the table stay short and fixed


def explain(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    code = main(["explain", "/arm", "--params-file", "base.yaml", *argv])
    out, err = capsys.readouterr()
    assert err == ""
    return code, out.splitlines()


def test_each_value_names_its_source_and_what_it_shadows(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, out = explain(
        capsys,
        *("--schema", "arm.yaml", "--schema", "tool.yaml@tool"),
        *("--params-file", "over.yaml", "-p", "mode:=fast", "--known", "plugin.*"),
    )
    assert code == 1
    assert out == [
        "/arm: 4 section(s) apply, in rcl's order",
        "parameter                          value              source"
        "                                    shadowed",
        "colour                             red                base.yaml:10:5 (/arm) "
        "[unknown: ignored]",
        "gains.shoulder.p                   1.0                default",
        "gains.wrist.p                      3.0                base.yaml:6:15 (/arm)"
        "                     1.0 from default",
        "joints                             [shoulder, wrist]  base.yaml:4:5 (/arm)"
        "                      [shoulder] from default",
        "max_speed                          4.0                over.yaml:7:5 (/arm)"
        "                      2.0 from base.yaml:3:5 (/arm); 1.0 from default",
        "mode                               fast               -p (rule 1, for /**)",
        "plugin.rate                        10                 base.yaml:9:5 (/arm) [other code]",
        "qos_overrides./tf.publisher.depth  5                  base.yaml:8:5 (/arm) [rclpy]",
        "tool.grip                          0.7                over.yaml:4:5 (/**)"
        "                       0.5 from default",
        "use_sim_time                       true               base.yaml:7:5 (/arm) [rclpy]",
        "",
        "What ROS would ignore or refuse:",
        "  base.yaml:3:5: speed_limit: old name of max_speed, which is given another value: "
        "keep only max_speed",
        "  base.yaml:10:5: colour: unknown parameter: ROS would ignore it",
        "  over.yaml:3:16: max_speed: wrong type: expected double, got string 'fast'",
        "  over.yaml:8:20: gains.wrist.p: wrong type: expected double, got integer 4 "
        "(ROS does not convert: write 4.0)",
        "",
        "Warnings:",
        "  base.yaml:3:5: speed_limit: warning: deprecated: old name of max_speed; write max_speed",
    ]


def test_a_required_parameter_and_unknown_keys_of_one_schema(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, out = explain(capsys, "--schema", "arm.yaml")
    assert code == 1
    assert out == [
        "/arm: 1 section(s) apply, in rcl's order",
        "parameter                          value              source"
        "                                    shadowed",
        "colour                             red                base.yaml:10:5 (/arm) "
        "[unknown: ignored]",
        "gains.shoulder.p                   1.0                default",
        "gains.wrist.p                      3.0                base.yaml:6:15 (/arm)"
        "                     1.0 from default",
        "joints                             [shoulder, wrist]  base.yaml:4:5 (/arm)"
        "                      [shoulder] from default",
        "max_speed                          2.0                base.yaml:3:5 (/arm)"
        "                      1.0 from default",
        "mode                               (not set)          required, not set",
        "plugin.rate                        10                 base.yaml:9:5 (/arm) "
        "[unknown: ignored]",
        "qos_overrides./tf.publisher.depth  5                  base.yaml:8:5 (/arm) [rclpy]",
        "use_sim_time                       true               base.yaml:7:5 (/arm) [rclpy]",
        "",
        "What ROS would ignore or refuse:",
        "  base.yaml:2:3: mode: required parameter is not set for /arm (it has no default: "
        "add mode: <string>)",
        "  base.yaml:9:5: plugin.rate: unknown parameter: ROS would ignore it",
        "  base.yaml:10:5: colour: unknown parameter: ROS would ignore it",
        "",
        "Warnings:",
        "  base.yaml:3:5: speed_limit: warning: deprecated: old name of max_speed; write max_speed",
    ]


def test_without_a_schema_every_key_is_listed_unchecked(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, out = explain(capsys, "-p", "arm:mode:=fast")
    assert code == 0
    assert out == [
        "/arm: 2 section(s) apply, in rcl's order",
        "parameter                          value              source                 shadowed",
        "colour                             red                base.yaml:10:5 (/arm)",
        "gains.wrist.p                      3.0                base.yaml:6:15 (/arm)",
        "joints                             [shoulder, wrist]  base.yaml:4:5 (/arm)",
        "mode                               fast               -p (rule 1, for /arm)",
        "plugin.rate                        10                 base.yaml:9:5 (/arm)",
        "qos_overrides./tf.publisher.depth  5                  base.yaml:8:5 (/arm)",
        "speed_limit                        2.0                base.yaml:3:5 (/arm)",
        "use_sim_time                       true               base.yaml:7:5 (/arm)",
    ]


WITH_SCHEMA = {
    "colour": ("", "nobody"),
    "gains.shoulder.p": ("double", "schema"),
    "gains.wrist.p": ("double", "schema"),
    "joints": ("string_array", "schema"),
    "max_speed": ("double", "schema"),
    "mode": ("string", "schema"),
    "plugin.rate": ("", "known"),
    "qos_overrides./tf.publisher.depth": ("", "rclpy"),
    "use_sim_time": ("", "rclpy"),
}
NAMES = ["colour", "gains.wrist.p", "joints", "plugin.rate", "qos_overrides./tf.publisher.depth"]
WITHOUT_SCHEMA = {name: ("", "unchecked") for name in [*NAMES, "speed_limit", "use_sim_time"]}


@pytest.mark.parametrize(
    ("schemas", "expected"),
    [(["arm.yaml"], WITH_SCHEMA), ([], WITHOUT_SCHEMA)],
    ids=["schema", "no_schema"],
)
def test_each_row_names_its_type_and_owner(
    schemas: list[str], expected: dict[str, tuple[str, str]]
) -> None:
    bounds = [Bound(load_schema(s, ARM), "") for s in schemas]
    documents = [read_params_file(BASE, "base.yaml")]
    explanation = explain_node(bounds, documents, "/arm", ["plugin.*"])
    assert {r.name: (r.type_name, r.owner) for r in explanation.rows} == expected


def test_a_prefixed_class_expands_its_mapped_entries_from_the_file(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    (tmp_path / "left.yaml").write_text(
        "/arm:\n  ros__parameters:\n    left.joints: [wrist]\n    left.gains.wrist.p: 2.0\n",
        encoding="utf-8",
    )
    code = main(["explain", "/arm", "--params-file", "left.yaml", "--schema", "arm.yaml@left"])
    assert code == 1
    assert capsys.readouterr().out.splitlines()[1:6] == [
        "parameter           value      source                shadowed",
        "left.gains.wrist.p  2.0        left.yaml:4:5 (/arm)  1.0 from default",
        "left.joints         [wrist]    left.yaml:3:5 (/arm)  [shoulder] from default",
        "left.max_speed      1.0        default",
        "left.mode           (not set)  required, not set",
    ]


def test_an_optional_parameter_reads_not_set_until_a_file_gives_it(
    capsys: pytest.CaptureFixture[str],
) -> None:
    Path("optional.yaml").write_text(
        "genparams: 1\nname: opt\ndescription: Optional ones.\nparameters:\n"
        "  frame_id: {type: string, optional: true, description: Frame.}\n"
        "  retries: {type: int, optional: true, description: Retries.}\n",
        encoding="utf-8",
    )
    Path("retries.yaml").write_text("/arm:\n  ros__parameters:\n    retries: 3\n", encoding="utf-8")
    code = main(["explain", "/arm", "--schema", "optional.yaml", "--params-file", "retries.yaml"])
    out, err = capsys.readouterr()
    assert (code, err) == (0, "")
    assert out.splitlines() == [
        "/arm: 1 section(s) apply, in rcl's order",
        "parameter  value      source                   shadowed",
        "frame_id   (not set)  optional, not set",
        "retries    3          retries.yaml:3:5 (/arm)",
    ]
    code = main(["explain", "/arm", "--schema", "optional.yaml", "--format", "yaml"])
    out, err = capsys.readouterr()
    assert (code, err) == (0, "")
    assert "frame_id" not in out and "retries" not in out  # a params file leaves unset ones out
