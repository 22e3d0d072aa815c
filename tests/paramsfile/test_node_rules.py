"""Rules across nodes, checked offline by check-deployment: one value on every node, and
checks in the rules' expression language over values of several nodes."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from genparams.paramsfile.node_rules import NodeRule, NodeValue, check_rules
from genparams.schema.errors import Location
from tests.support import ROOT

EXAMPLE = ROOT / "examples" / "deployment"
CAMERA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, (captured.out + captured.err).splitlines()


def test_the_example_breaks_each_rule_and_names_every_value(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(EXAMPLE)
    code, out = run(
        capsys, "check-deployment", "--manifest", "mobile_base_manifest.yaml", "mobile_base.yaml"
    )
    assert code == 1
    assert out == [
        "mobile_base_manifest.yaml:9:11: one_clock: broken: use_sim_time differs across nodes: "
        "true on /base_controller from mobile_base.yaml:5:5 (/**), /odometry from "
        "mobile_base.yaml:5:5 (/**); false on /planner from mobile_base.yaml:15:5 (/planner)",
        "mobile_base_manifest.yaml:11:12: one_wheel_base: broken: /base_controller.wheel_base == "
        "/odometry.wheel_base is false for /base_controller.wheel_base=0.5, "
        "/odometry.wheel_base=0.52 (/base_controller.wheel_base from mobile_base.yaml:8:5 "
        "(/base_controller), /odometry.wheel_base from mobile_base.yaml:12:5 (/odometry))",
        "mobile_base_manifest.yaml:13:12: planner_within_base: broken: /planner.max_speed <= "
        "/base_controller.max_speed is false for /planner.max_speed=1.5, "
        "/base_controller.max_speed=1.2 (/planner.max_speed from mobile_base.yaml:16:5 "
        "(/planner), /base_controller.max_speed from mobile_base.yaml:9:5 (/base_controller))",
    ]


def _files(tmp_path: Path, params: str, rules: str, schemas: str = "") -> list[str]:
    (tmp_path / "params.yaml").write_text(params, encoding="utf-8")
    manifest = tmp_path / "manifest.yaml"
    manifest.write_text(
        "genparams_deployment: 1\nknown: [rate, wheel_base, name]\nnodes:\n"
        f"  /a: {{{schemas}}}\n  /b: {{}}\n  /ns/c: {{}}\nrules:\n{rules}",
        encoding="utf-8",
    )
    return ["check-deployment", "--manifest", str(manifest), str(tmp_path / "params.yaml")]


PARAMS = """\
/a:
  ros__parameters:
    rate: 10
    wheel_base: 0.5
    name: left
/b:
  ros__parameters:
    rate: 20
    wheel_base: 0.5
/ns/c:
  ros__parameters:
    rate: 40
"""


def test_rules_that_hold_pass(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    rules = (
        "  - {name: clock, same: use_sim_time}\n"  # rclpy's default on every node: false
        "  - {name: base, same: wheel_base}\n"
        "  - {name: faster, check: '/a.rate * 2 <= /b.rate and /b.rate < /ns/c.rate'}\n"
        "  - {name: halves, check: '/ns/c.rate / 2 == /b.rate'}\n"
        "  - {name: text, check: \"/a.name in ['left', 'right']\"}\n"
    )
    assert run(capsys, *_files(tmp_path, PARAMS, rules)) == (0, [])


def test_a_node_left_to_the_default_differs_from_one_set(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    params = PARAMS + "    use_sim_time: true\n"
    code, out = run(capsys, *_files(tmp_path, params, "  - {name: clock, same: use_sim_time}\n"))
    assert code == 1
    assert out == [
        f"{tmp_path / 'manifest.yaml'}:8:25: clock: broken: use_sim_time differs across nodes: "
        "false on /a from rclpy's default, /b from rclpy's default; "
        f"true on /ns/c from {tmp_path / 'params.yaml'}:13:5 (/ns/c)"
    ]


def test_same_covers_only_the_nodes_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    rules = "  - {name: rate, same: rate, nodes: [/a, /b]}\n"
    code, out = run(capsys, *_files(tmp_path, PARAMS, rules))
    assert code == 1
    assert out[0].endswith(
        f"rate differs across nodes: 10 on /a from {tmp_path / 'params.yaml'}:3:5 (/a); "
        f"20 on /b from {tmp_path / 'params.yaml'}:8:5 (/b)"
    )
    rules = "  - {name: rate, same: rate, nodes: ['/ns/*']}\n"  # one node: nothing to compare
    assert run(capsys, *_files(tmp_path, PARAMS, rules)) == (0, [])


def test_a_schema_types_and_defaults_the_values(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    params = PARAMS.replace(
        "/a:\n  ros__parameters:\n", "/a:\n  ros__parameters:\n    serial: ABCD1234\n"
    )
    params = params.replace("    rate: 10\n", "")
    schemas = f"schemas: [{CAMERA}]"
    # camera.fps is not in the file: its schema default, 30.0, is compared.
    rules = "  - {name: fps, check: '/a.camera.fps <= /b.rate'}\n"
    code, out = run(capsys, *_files(tmp_path, params, rules, schemas))
    assert code == 1
    assert out == [
        f"{tmp_path / 'manifest.yaml'}:8:24: fps: broken: /a.camera.fps <= /b.rate is false for "
        "/a.camera.fps=30.0, /b.rate=20 (/a.camera.fps from default, /b.rate from "
        f"{tmp_path / 'params.yaml'}:8:5 (/b))"
    ]


def test_what_cannot_be_read_is_a_problem_at_the_rule(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    rules = (
        "  - {name: unset, check: '/b.name == /a.name'}\n"
        "  - {name: kinds, check: '/a.name < /b.rate'}\n"
    )
    code, out = run(capsys, *_files(tmp_path, PARAMS, rules))
    assert code == 1
    manifest = tmp_path / "manifest.yaml"
    assert out == [
        f"{manifest}:8:26: unset: cannot be checked: /b.name not set",
        f"{manifest}:9:26: kinds: < compares two numbers or two strings, "
        "not a string and a number (at character 1)",
    ]


def test_a_rule_on_a_node_not_deployed_is_a_note(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    args = _files(tmp_path, PARAMS, "  - {name: lidar, check: '/lidar.rate >= /a.rate'}\n")
    assert run(capsys, *args) == (0, [])
    code, out = run(capsys, *args, "-v")
    assert code == 0
    assert out[-1].endswith("manifest.yaml:8:26: lidar: not checked: /lidar not in this deployment")


@pytest.mark.parametrize(
    ("rule", "message"),
    [
        ("{name: r, check: '/a.rate <= /b.rate', sme: x}", "8:44: rules.0.sme: unknown key 'sme'"),
        ("{name: r, check: '/a.rate <', same: rate}", "8:5: rules.0: give exactly one of check"),
        ("{name: r, check: 'rate <= 3'}", "8:22: rules.0.check: a check reads parameters of nodes"),
        ("{name: r, check: '/a.rate <= (3'}", "8:22: rules.0.check: invalid expression: '('"),
        ("{name: r, check: '/*/x.rate > 1'}", "8:22: rules.0.check: a rule reads nodes named in"),
        ("{name: r, same: 'a b'}", "8:21: rules.0.same: same: takes one parameter name"),
        ("{name: r, same: rate, nodes: [a//b]}", "8:35: rules.0.nodes.0: invalid node name"),
    ],
)
def test_a_bad_rule_is_bad_input_at_its_place(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], rule: str, message: str
) -> None:
    code, out = run(capsys, *_files(tmp_path, PARAMS, f"  - {rule}\n"))
    assert code == 2
    assert any(line.startswith(f"{tmp_path / 'manifest.yaml'}:{message}") for line in out), out


def test_nan_equals_nan_and_a_bool_is_not_a_number() -> None:
    where = Location("m.yaml", 1, 1)
    rule = NodeRule("r", where, same="x")
    nan = {"/a": {"x": NodeValue(float("nan"), "")}, "/b": {"x": NodeValue(float("nan"), "")}}
    assert check_rules([rule], nan).problems == ()
    mixed = {"/a": {"x": NodeValue(True, "")}, "/b": {"x": NodeValue(1, "")}}
    (problem,) = check_rules([rule], mixed).problems
    assert problem.message == "broken: x differs across nodes: true on /a; 1 on /b"


def test_same_reads_a_name_holding_a_dash(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    params = (
        "/a:\n  ros__parameters:\n    max-speed: 1.0\n/b:\n  ros__parameters:\n    max-speed: 2.0\n"
    )
    rules = "  - {name: speed, same: max-speed, nodes: [/a, /b]}\n"
    code, out = run(capsys, *_files(tmp_path, params, rules))
    assert code == 1
    assert out[0].endswith(
        f"max-speed differs across nodes: 1.0 on /a from {tmp_path / 'params.yaml'}:3:5 (/a); "
        f"2.0 on /b from {tmp_path / 'params.yaml'}:6:5 (/b)"
    )


def test_a_check_reads_names_holding_dashes_and_slashes_by_their_attribute_spelling(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``-`` in a check is a minus, so a check reads ``axes.twist-linear-x`` and
    ``input_shape/height`` as a schema's rules do: ``axes.twist_linear_x``,
    ``input_shape_height``. A name the node holds as written comes first; two names
    spelled alike are read as neither."""
    params = (
        "/a:\n  ros__parameters:\n    axes: {twist-linear-x: 1}\n    input_shape/height: 480\n"
        "    max-speed: 1.0\n    max_speed: 2.0\n    gain-x: 1.0\n    gain/x: 2.0\n"
        "/b:\n  ros__parameters:\n    axes: {twist-linear-x: 2}\n    input_shape/height: 480\n"
    )
    rules = (
        "  - {name: axes, check: /a.axes.twist_linear_x == /b.axes.twist_linear_x}\n"
        "  - {name: shape, check: /a.input_shape_height == /b.input_shape_height}\n"
        "  - {name: written, check: /a.max_speed == 2.0}\n"
        "  - {name: alike, check: /a.gain_x == 1.0}\n"
    )
    code, out = run(capsys, *_files(tmp_path, params, rules))
    assert code == 1
    problems = [line.split(": ", 1)[1] for line in out if ": broken" in line or "cannot" in line]
    assert problems == [
        "axes: broken: /a.axes.twist_linear_x == /b.axes.twist_linear_x is false for "
        f"/a.axes.twist_linear_x=1, /b.axes.twist_linear_x=2 (/a.axes.twist_linear_x from "
        f"{tmp_path / 'params.yaml'}:3:12 (/a), /b.axes.twist_linear_x from "
        f"{tmp_path / 'params.yaml'}:11:12 (/b))",
        "alike: cannot be checked: /a.gain_x not set",
    ]
