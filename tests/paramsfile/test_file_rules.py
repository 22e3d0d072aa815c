"""Rules checked over a params file: the defaults, then the file's values, each problem once."""

from __future__ import annotations

from collections.abc import Sequence

import pytest

from genparams.api import load_schema
from genparams.paramsfile.check_params import check_params
from genparams.paramsfile.params_reader import read_params_file

DRIVE = load_schema(
    "drive.yaml",
    """\
genparams: 1
name: drive
parameters:
  limit: {type: int}
  min_speed: {type: double, default: 0.5}
  max_speed: {type: double, default: 2.0}
rules:
  - {name: limit_positive, check: limit >= 1}
  - {name: speed_order, check: min_speed <= max_speed}
""",
)
BROKEN = "rule 'speed_order' broken: min_speed <= max_speed is false for min_speed=3.0"


def _report(entries: list[str], nodes: Sequence[str] = (), section: str = "/drive") -> list[str]:
    text = f"{section}:\n  ros__parameters:\n" + "".join(f"    {e}\n" for e in entries)
    report = check_params(DRIVE, read_params_file(text, "p.yaml"), nodes)
    return [str(p) for p in (*report.problems, *report.warnings, *report.skipped)]


def test_a_file_value_breaks_a_rule_with_a_default() -> None:
    assert _report(["limit: 2", "min_speed: 3.0"]) == [
        f"p.yaml:4:5: min_speed: {BROKEN}, max_speed=2.0",
    ]


def test_a_rule_is_checked_when_an_earlier_rule_lacks_a_value() -> None:
    assert _report(["min_speed: 3.0"], ["/drive"]) == [
        "p.yaml:2:3: limit: required parameter is not set for /drive "
        "(it has no default: add limit: <int>)",
        f"p.yaml:3:5: min_speed: {BROKEN}, max_speed=2.0 (for /drive)",
    ]


@pytest.mark.parametrize("wrong", ["limit: fast", "limit: 0.5", "unknown: 1"])
def test_values_after_a_wrong_one_are_still_checked(wrong: str) -> None:
    problems = _report([wrong, "min_speed: 3.0"])
    assert problems[-1] == f"p.yaml:4:5: min_speed: {BROKEN}, max_speed=2.0"


def test_a_broken_rule_names_the_first_of_its_parameters_given() -> None:
    assert _report(["limit: 2", "max_speed: 0.1", "min_speed: 3.0"], ["/drive"]) == [
        f"p.yaml:5:5: min_speed: {BROKEN}, max_speed=0.1 (for /drive)",
    ]


def test_a_wrong_value_is_reported_once_and_its_rules_are_skipped() -> None:
    assert _report(["limit: 2", "min_speed: fast"]) == [
        "p.yaml:4:16: min_speed: wrong type: expected double, got string 'fast'",
    ]


def test_a_node_without_a_section_misses_its_required_values_at_the_top() -> None:
    assert _report(["limit: 2"], ["/drive"], section="/other") == [
        "p.yaml:1:1: /drive: no section of the file names this node, so nothing checks it; "
        "sections seen: /other",
        "p.yaml:1:1: limit: required parameter is not set for /drive "
        "(it has no default: add limit: <int>)",
        "p.yaml:1:1: /other: skipped: for another node (not /drive)",
    ]
