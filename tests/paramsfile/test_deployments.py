"""Bringup files checked node by node, and explained, with a real node as the judge.

tests/paramsfile/deployments holds bringup-style files (a controller manager
and its controllers, a /** block with nested node keys, one copy per robot, a
typo in a node name, a key shadowed by a later file, framework-owned keys)
and small schemas of the ros2_controllers these files configure.
"""

from __future__ import annotations

import math
import types
from pathlib import Path
from typing import Any

import pytest

from genparams.api import load_schema
from genparams.cli import main
from genparams.paramsfile.check_params import Bound
from genparams.paramsfile.explain import explain, overrides_document
from genparams.paramsfile.params_reader import ParamsDocument, read_params_file
from tests import corpus
from tests.paramsfile.rcl_load import overrides, plain, started
from tests.support import load_generated

HERE = Path(__file__).parent / "deployments"
SCHEMAS = HERE / "schemas"
MANIFEST = HERE / "bringup.manifest.yaml"
CONTROLLER = ["--known", "type", "--known", "update_rate"]
_MODULES: dict[Path, types.ModuleType] = {}


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    code = main(list(argv))
    return code, capsys.readouterr().out.splitlines()


def test_a_clean_bringup_file_checks_clean(capsys: pytest.CaptureFixture[str]) -> None:
    code, out = run(
        capsys, "check-deployment", "--manifest", str(MANIFEST), str(HERE / "bringup.yaml")
    )
    assert (code, out) == (0, [])


def test_every_silent_mistake_is_reported(capsys: pytest.CaptureFixture[str]) -> None:
    file = HERE / "bringup_mistakes.yaml"
    code, out = run(capsys, "check-deployment", "--manifest", str(MANIFEST), str(file))
    assert code == 1
    assert [line.split(": ", 2)[1:] for line in out] == [
        [
            "interface_nme",
            "unknown parameter (did you mean 'interface_name'?): ROS would ignore it",
        ],
        [
            "/robot_2/forward_positon_controller",
            "no node of the manifest gets this section (did you mean "
            "/*/forward_position_controller? node name 'forward_positon_controller' is close to "
            "'forward_position_controller': a typo?): nothing checks it, and ROS applies it to "
            "no node listed",
        ],
        ["reference_timeout", "wrong type: expected double, got string 'fast'"],
    ]


def test_a_map_on_the_command_line_works_like_a_manifest(
    capsys: pytest.CaptureFixture[str],
) -> None:
    file = str(HERE / "bringup.yaml")
    forward = f"/*/forward_position_controller={SCHEMAS / 'forward_command_controller.yaml'}"
    code, out = run(capsys, "check-deployment", file, "--map", forward, *CONTROLLER)
    assert code == 1  # the other nodes' sections are claimed by no schema
    assert all("no node of the manifest gets this section" in line for line in out)
    assert len(out) == 3  # controller_manager, joint_state_broadcaster, bicycle_steering_controller


def test_one_node_of_a_shared_file(capsys: pytest.CaptureFixture[str]) -> None:
    schema = str(SCHEMAS / "forward_command_controller.yaml")
    node = "/robot_1/forward_position_controller"
    file = str(HERE / "bringup.yaml")
    assert run(capsys, "check-params", schema, file, "--node", node, *CONTROLLER) == (0, [])
    code, out = run(capsys, "check-params", schema, file, "--node", node, *CONTROLLER, "-v")
    assert code == 0
    assert [line.split(": ", 1)[1] for line in out] == [
        "/**/controller_manager: skipped: for another node "
        "(not /robot_1/forward_position_controller)",
        "/robot_2/forward_position_controller: skipped: for another node "
        "(not /robot_1/forward_position_controller)",
        "/robot_2/joint_state_broadcaster: skipped: for another node "
        "(not /robot_1/forward_position_controller)",
        "/robot_1/bicycle_steering_controller: skipped: for another node "
        "(not /robot_1/forward_position_controller)",
    ]
    # Without --known, the framework's key is what ROS would ignore for this schema alone.
    code, out = run(capsys, "check-params", schema, file, "--node", node)
    assert code == 1
    assert [line.split(": ", 2)[1] for line in out] == ["type"]


def test_two_classes_on_one_node(capsys: pytest.CaptureFixture[str]) -> None:
    library = str(SCHEMAS / "steering_controllers_library.yaml")
    bicycle = str(SCHEMAS / "bicycle_steering_controller.yaml")
    node = ["--node", "/robot_1/bicycle_steering_controller", *CONTROLLER]
    file = str(HERE / "bringup.yaml")
    assert run(capsys, "check-params", library, file, "--schema", bicycle, *node) == (0, [])
    code, out = run(capsys, "check-params", library, file, *node)
    assert code == 1
    assert sorted(line.split(": ", 2)[1] for line in out) == ["traction_wheel_radius", "wheelbase"]


# ---- a real node decides -----------------------------------------------------------------

NODES = {
    "/robot_1/forward_position_controller": [("forward_command_controller", "")],
    "/robot_2/forward_position_controller": [("forward_command_controller", "")],
    "/robot_2/joint_state_broadcaster": [("joint_state_broadcaster", "")],
    "/robot_1/bicycle_steering_controller": [
        ("steering_controllers_library", ""),
        ("bicycle_steering_controller", ""),
    ],
}
INPUTS = {
    "bringup": ["--params-file", "bringup.yaml"],
    "shadowed": ["--params-file", "bringup.yaml", "--params-file", "sim_overrides.yaml"],
    "with_p": [
        "--params-file",
        "bringup.yaml",
        "-p",
        "interface_name:=effort",
        "-p",
        "forward_position_controller:joints:=[a, b]",
    ],
    "p_first": [
        "-p",
        "reference_timeout:=4.0",
        "--params-file",
        "bringup.yaml",
        "--params-file",
        "sim_overrides.yaml",
    ],
    "mistakes": ["--params-file", "bringup_mistakes.yaml"],
}


def _documents(args: list[str]) -> list[ParamsDocument]:
    documents = []
    rules = 0
    for flag, value in zip(args[::2], args[1::2], strict=True):
        if flag == "-p":
            rules += 1
            documents.append(overrides_document([value], start=rules))
        else:
            path = HERE / value
            documents.append(read_params_file(path.read_text(encoding="utf-8"), value))
    return documents


def _rcl_args(args: list[str]) -> list[str]:
    return [str(HERE / a) if a.endswith(".yaml") else a for a in args]


def _classes(node: str, tmp_path: Path) -> list[tuple[type, str]]:
    classes = []
    for name, prefix in NODES[node]:
        schema = SCHEMAS / f"{name}.yaml"
        if schema not in _MODULES:
            _MODULES[schema] = load_generated(schema, tmp_path)
        classes.append((getattr(_MODULES[schema], load_schema(schema).class_name), prefix))
    return classes


def _same(one: Any, other: Any) -> bool:
    if isinstance(one, float) and isinstance(other, float) and math.isnan(one):
        return math.isnan(other)
    return bool(one == other) and type(one) is type(other)


@pytest.mark.parametrize("inputs", INPUTS, ids=str)
@pytest.mark.parametrize("node", NODES, ids=lambda n: n.strip("/").replace("/", "."))
def test_explain_matches_a_real_node(node: str, inputs: str, tmp_path: Path) -> None:
    args = INPUTS[inputs]
    bounds = [Bound(load_schema(SCHEMAS / f"{n}.yaml"), p) for n, p in NODES[node]]
    explanation = explain(bounds, _documents(args), node, ["type", "update_rate"])
    rows = {row.name: row for row in explanation.rows}
    # What rcl hands the node: exactly the values explain says came from files or -p.
    given = {n: plain(r.value) for n, r in rows.items() if r.source and r.source.text != "default"}
    real = overrides(node, _rcl_args(args))
    wrong_type = {p.key for p in explanation.report.problems if "wrong type" in p.message}
    assert {n: v for n, v in real.items() if n not in wrong_type} == given
    # What the node holds once the classes are declared: every typed value, defaults too.
    values = started(node, _rcl_args(args), _classes(node, tmp_path))
    refusing = [p for p in explanation.report.problems if "unknown parameter" not in p.message]
    assert (values is None) == bool(refusing), explanation.report.problems
    if values is None:
        return
    for name, row in rows.items():
        if row.owner == "schema":
            assert _same(plain(row.value), values[name]), name


def test_a_list_of_mappings_is_read_as_rcl_reads_it(capsys: pytest.CaptureFixture[str]) -> None:
    """example_10's gpio_controller: command_interfaces: {vacuum: [{interfaces: [..]}]}."""
    file = corpus.folder("paramsfile") / "ros2_control_demos" / "example_10" / "params"
    schema = str(SCHEMAS / "gpio_command_controller.yaml")
    node = ["--node", "/gpio_controller", *CONTROLLER]
    code, out = run(capsys, "check-params", schema, str(file / "rrbot_controllers.yaml"), *node)
    assert (code, out) == (0, [])
    real = overrides("/gpio_controller", ["--params-file", str(file / "rrbot_controllers.yaml")])
    assert real["command_interfaces.flange_vacuum.interfaces"] == ["vacuum"]


def test_a_section_meant_for_the_node_is_a_warning(capsys: pytest.CaptureFixture[str]) -> None:
    schema = str(SCHEMAS / "forward_command_controller.yaml")
    node = ["--node", "/robot_2/forward_position_controller", *CONTROLLER]
    code, out = run(capsys, "check-params", schema, str(HERE / "bringup_mistakes.yaml"), *node)
    assert code == 0  # a warning: the section may be another node's
    assert [line.split(": ", 1)[1] for line in out] == [
        "/robot_2/forward_positon_controller: warning: ROS applies this section to another node, "
        "not /robot_2/forward_position_controller: node name 'forward_positon_controller' is "
        "close to 'forward_position_controller': a typo?"
    ]


def test_a_bad_manifest_is_bad_input(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    manifest = tmp_path / "manifest.yaml"
    manifest.write_text(
        "genparams_deployment: 1\nnodes:\n  /robot/cam:\n"
        "    schemas: [cam.yaml]\n    knwon: [type]\n",
        encoding="utf-8",
    )
    code = main(["check-deployment", "--manifest", str(manifest), str(HERE / "bringup.yaml")])
    assert code == 2
    assert f"{manifest}:5:5: nodes./robot/cam.knwon: unknown key 'knwon'" in capsys.readouterr().err
    assert main(["check-deployment", str(HERE / "bringup.yaml"), "--map", "/robot/cam"]) == 2
    assert main(["explain", "/robot/cam", "-p", "ns/cam:fps:=1.0"]) == 2
