"""check_params() called as a library: its schema, others under prefixes, known names, nodes."""

from __future__ import annotations

from genparams.api import load_schema
from genparams.paramsfile.check_params import Bound, check_params
from genparams.paramsfile.params_reader import read_params_file

CAMERA = load_schema(
    "camera.yaml",
    "genparams: 1\nname: camera\nparameters:\n  fps: {type: int, default: 30}\n",
)
LIGHT = load_schema(
    "light.yaml",
    "genparams: 1\nname: light\nparameters:\n  power: {type: double, default: 1.0}\n",
)
PARAMS = """\
/camera:
  ros__parameters:
    fps: 15
    light.power: 0.5
    type: usb
    extra: 1
/other:
  ros__parameters:
    fps: fast
"""


def _report(**kwargs: object) -> list[str]:
    document = read_params_file(PARAMS, "params.yaml")
    report = check_params(CAMERA, document, **kwargs)  # type: ignore[arg-type]
    return [str(p) for p in (*report.problems, *report.warnings, *report.skipped)]


def test_every_section_is_the_nodes_without_nodes() -> None:
    assert _report() == [
        "params.yaml:4:5: light.power: unknown parameter: ROS would ignore it",
        "params.yaml:5:5: type: unknown parameter: ROS would ignore it",
        "params.yaml:6:5: extra: unknown parameter: ROS would ignore it",
        "params.yaml:9:10: fps: wrong type: expected integer, got string 'fast'",
    ]


def test_other_classes_and_known_names_own_their_entries() -> None:
    assert _report(nodes=["/camera"], also=[Bound(LIGHT, "light")], known=["ty*"]) == [
        "params.yaml:6:5: extra: unknown parameter: ROS would ignore it",
        "params.yaml:7:1: /other: skipped: for another node (not /camera)",
    ]


def test_a_prefixed_class_checks_its_values() -> None:
    text = PARAMS.replace("light.power: 0.5", "light.power: bright")
    document = read_params_file(text, "params.yaml")
    report = check_params(CAMERA, document, ["/camera"], also=[Bound(LIGHT, "light")])
    assert [str(p) for p in report.problems] == [
        "params.yaml:4:18: light.power: wrong type: expected double, got string 'bright'",
        "params.yaml:5:5: type: unknown parameter: ROS would ignore it",
        "params.yaml:6:5: extra: unknown parameter: ROS would ignore it",
    ]


LAMP = load_schema(
    "lamp.yaml",
    "genparams: 1\nname: lamp\nparameters:\n"
    "  level: {type: int}\n"
    "  old: {type: int, default: 1, deprecated: use level}\n",
)


def test_a_prefixed_class_reports_its_required_and_deprecated_names() -> None:
    text = "/camera:\n  ros__parameters:\n    lamp.old: 2\n"
    report = check_params(CAMERA, read_params_file(text, "p.yaml"), also=[Bound(LAMP, "lamp")])
    assert [str(p) for p in (*report.problems, *report.warnings)] == [
        "p.yaml:2:3: lamp.level: required parameter is not set "
        "(it has no default: add level: <int>)",
        "p.yaml:3:5: lamp.old: warning: deprecated: use level",
    ]


def test_a_skipped_section_gives_the_first_nodes_reason() -> None:
    report = check_params(CAMERA, read_params_file(PARAMS, "params.yaml"), ["/camera", "/ns/light"])
    assert [str(p) for p in report.skipped] == [
        "params.yaml:7:1: /other: skipped: for another node (not /camera)"
    ]


def test_a_near_miss_is_a_warning_at_the_section() -> None:
    text = "/camra:\n  ros__parameters:\n    fps: 15\n"
    report = check_params(CAMERA, read_params_file(text, "p.yaml"), ["/camera"])
    assert [str(p) for p in report.warnings] == [
        "p.yaml:1:1: /camra: warning: ROS applies this section to another node, not /camera: "
        "node name 'camra' is close to 'camera': a typo?"
    ]


def test_a_prefixed_class_finds_its_required_value() -> None:
    text = "/camera:\n  ros__parameters:\n    lamp.level: 3\n"
    report = check_params(CAMERA, read_params_file(text, "p.yaml"), also=[Bound(LAMP, "lamp")])
    assert report.problems == ()
