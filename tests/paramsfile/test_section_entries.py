"""Entries of a node's section that the schema checks only in part: custom validators it cannot
import, open namespaces, key lists given a wrong value, required names inside groups."""

from __future__ import annotations

from genparams.api import load_schema
from genparams.paramsfile.check_params import check_params
from genparams.paramsfile.params_reader import read_params_file

ARM = load_schema(
    "arm.yaml",
    """\
genparams: 1
name: arm
parameters:
  speed:
    type: int
    default: 1
    validators: [{custom: 'no_such_pkg.checks:is_even'}, {bounds: [0, 10]}]
  plugins: {open: true}
  motor:
    limit: {type: int}
  joints: {type: string_array, default: [shoulder]}
  links: {type: string_array, default: [base]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0}
  limits:
    for_each: links
    max: {type: double, default: 1.0}
""",
)
NOT_CHECKED = (
    "p.yaml:1:1: speed: warning: custom validator no_such_pkg.checks:is_even not checked "
    "(cannot import it here: ModuleNotFoundError)"
)


def _report(*entries: str) -> list[str]:
    text = "/arm:\n  ros__parameters:\n" + "".join(f"    {e}\n" for e in entries)
    report = check_params(ARM, read_params_file(text, "p.yaml"))
    return [str(p) for p in (*report.problems, *report.warnings, *report.skipped)]


def test_the_checks_after_a_custom_validator_it_cannot_import_still_run() -> None:
    assert _report("motor.limit: 1", "speed: 20") == [
        "p.yaml:4:12: speed: must be within [0, 10] (bounds), got 20",
        NOT_CHECKED,
    ]


def test_entries_under_an_open_namespace_are_other_codes() -> None:
    assert _report("motor.limit: 1", "plugins.grip.force: 3", "plugins.x: 1") == [NOT_CHECKED]


def test_a_key_list_after_a_wrong_one_still_gives_the_items() -> None:
    assert _report("motor.limit: 1", "joints: 5", "links: [wrist]", "limits.wrist.max: 2.0") == [
        "p.yaml:4:13: joints: wrong type: expected string_array, got integer 5",
        NOT_CHECKED,
    ]


def test_a_required_parameter_in_a_group_is_written_by_its_last_name() -> None:
    assert _report("speed: 2") == [
        "p.yaml:2:3: motor.limit: required parameter is not set "
        "(it has no default: add limit: <int>)",
        NOT_CHECKED,
    ]
