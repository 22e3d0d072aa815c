"""genparams check-params on a corpus of params files, and a real node's verdict on each.

Each folder tests/cases/<schema>/check_params/<case> holds a params file, the exact report
(expected.txt), the node(s) it is checked for (args.txt) and what a real node
does when started with it (ros.txt: "starts" or "refuses"). The offline check
must never pass a file the node refuses.
"""

from __future__ import annotations

import types
from pathlib import Path

import pytest
from rclpy.impl.implementation_singleton import rclpy_implementation

from genparams.api import load_schema
from genparams.cli import main
from genparams.paramsfile.ros_yaml import absolute
from genparams.runtime import ParameterDeclarationError
from tests.golden import (
    EXAMPLE_SCHEMA,
    case_arguments,
    case_schema,
    check_params_cases,
    check_params_output,
)
from tests.support import RosHarness, load_generated

CASES = check_params_cases()
_MODULES: dict[Path, types.ModuleType] = {}


def test_corpus_is_large_enough() -> None:
    broken = [c for c in CASES if (c / "expected.txt").read_text(encoding="utf-8")]
    assert len(broken) >= 12


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_report_is_exact(case: Path) -> None:
    code, report = check_params_output(case)
    expected = (case / "expected.txt").read_text(encoding="utf-8")
    assert report == expected
    problems = [line for line in expected.splitlines() if ": warning: " not in line]
    assert code == (1 if problems else 0)


def _params_class(schema: Path, tmp_path: Path) -> type:
    if schema not in _MODULES:
        _MODULES[schema] = load_generated(schema, tmp_path)
    return getattr(_MODULES[schema], load_schema(schema).class_name)  # type: ignore[no-any-return]


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_a_real_node_agrees(case: Path, ros: RosHarness, tmp_path: Path) -> None:
    code, _report = check_params_output(case)
    args = case_arguments(case)
    node_name = absolute(args[1]) if args else "/camera_driver"
    namespace, _, name = node_name.rpartition("/")
    params_class = _params_class(case_schema(case), tmp_path)
    try:
        node = ros.node(
            name, namespace=namespace or "/", args=["--params-file", str(case / "params.yaml")]
        )
        params_class.declare(node)  # type: ignore[attr-defined]
        outcome = "starts"
    except (ParameterDeclarationError, rclpy_implementation.RCLInvalidROSArgsError):
        outcome = "refuses"
    assert outcome == (case / "ros.txt").read_text(encoding="utf-8").strip()
    if outcome == "refuses":
        assert code == 1, "check-params passed a file the node refuses"


def test_usage_errors_exit_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    params = tmp_path / "params.yaml"
    params.write_text("/**:\n  ros__parameters:\n    serial: ABCD1234\n", encoding="utf-8")
    schema = str(EXAMPLE_SCHEMA)
    assert main(["check-params", schema, str(params)]) == 0
    assert main(["check-params", schema, str(tmp_path / "missing.yaml")]) == 2
    assert "cannot read" in capsys.readouterr().err
    assert main(["check-params", schema, str(params), "--node", "/robot/cam-1"]) == 2
    assert "invalid --node '/robot/cam-1'" in capsys.readouterr().err
    assert main(["check-params", schema, str(params), "--node", "/robot/*"]) == 2
    bad_schema = tmp_path / "bad.yaml"
    bad_schema.write_text("genparams: 1\nname: x\nparameters: {a: {type: nope}}\n", "utf-8")
    assert main(["check-params", str(bad_schema), str(params)]) == 2
    assert "bad.yaml:3:" in capsys.readouterr().err
