"""check-params at, just inside and just outside every kind of bound and step.

The table is the one the runtime tests use (tests/edge_values.py): a file the
node would refuse must fail the check with the parameter and the reason, and a
file it would start with must pass.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from tests.edge_values import EDGES, Edge, write_schema, yaml_value


@pytest.mark.parametrize("edge", EDGES, ids=lambda e: e.id)
def test_check_params_gives_the_nodes_verdict(
    edge: Edge, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    schema = write_schema(tmp_path)
    params = tmp_path / "params.yaml"
    line = f"    {edge.name}: {yaml_value(edge.value)}\n"
    params.write_text("/**:\n  ros__parameters:\n" + line, encoding="utf-8")
    code = main(["check-params", str(schema), str(params)])
    out = capsys.readouterr()
    report = out.out + out.err
    if edge.accepted:
        assert (code, report) == (0, ""), report
        return
    assert code == 1, report
    (problem,) = report.splitlines()
    column = len(f"    {edge.name}: ") + 1
    assert problem.startswith(f"{params}:3:{column}: {edge.name}: "), problem
    assert edge.problem in problem, problem
