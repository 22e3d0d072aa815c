"""What the importers share: the record's report, the schema's name, writing all or nothing,
and the exit codes of the command steps (import-gpl here; import-node runs them the same)."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from genparams.errors import ParameterProblem
from genparams.importing import APPROXIMATE, EXACT, LEFT_OUT, Imported, Outcome, schema_name
from genparams.importing.writer import write_outputs
from genparams.schema.errors import Location, SchemaProblem


@pytest.mark.parametrize(
    ("owner", "prefix", "expected"),
    [
        ("JointTrajectoryController", "gpl", "joint_trajectory_controller"),
        ("HTTPServer", "node", "http_server"),
        ("diff_drive_controller", "gpl", "diff_drive_controller"),
        ("camera-driver.v2", "node", "camera_driver_v2"),
        ("2d_lidar", "node", "node_2d_lidar"),
        ("__", "gpl", "gpl"),
    ],
)
def test_schema_name(owner: str, prefix: str, expected: str) -> None:
    assert schema_name(owner, prefix) == expected


def test_summary_counts_each_fate() -> None:
    imported = Imported(
        "n",
        {},
        outcomes=(
            Outcome("a", EXACT, "a"),
            Outcome("b", APPROXIMATE, "b"),
            Outcome("c", LEFT_OUT),
        ),
    )
    assert (imported.parameters, imported.imported) == (3, 2)
    assert imported.summary() == (
        "imported 2 of 3 parameters (1 approximately); 1 left out (see warnings)"
    )
    assert Imported("n", {}, outcomes=(Outcome("a", EXACT, "a"),)).summary() == (
        "imported 1 of 1 parameters"
    )


def test_findings_by_place_line_and_column_as_numbers_notes_first() -> None:
    def at(line: int, message: str) -> SchemaProblem:
        return SchemaProblem(Location("f.yaml", line, 3), "k", message)

    imported = Imported(
        "n",
        {},
        warnings=(at(10, "warning: w10"), at(9, "warning: w9")),
        notes=(at(10, "note: n10"),),
    )
    assert [p.message for p in imported.findings()] == ["warning: w9", "note: n10", "warning: w10"]
    node = Imported(
        "n",
        {},
        warnings=(ParameterProblem("a.b", "warning: w", place="/n"),),
        notes=(ParameterProblem("z", "note: n", place="/n"),),
    )
    assert [p.key for p in node.findings()] == ["z", "a.b"]  # a node's notes come first


def test_nothing_is_written_when_one_output_cannot_be(tmp_path: Path) -> None:
    (tmp_path / "blocked").write_text("a file where a folder should be", encoding="utf-8")
    schema = tmp_path / "out" / "schema.yaml"
    with pytest.raises(OSError):
        write_outputs({schema: "genparams: 1\n", tmp_path / "blocked" / "checks.py": "x = 1\n"})
    assert not schema.exists()
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == []  # no temporary file left


def test_an_import_that_keeps_no_parameter_writes_nothing_and_exits_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "lost.yaml"
    source.write_text("lost:\n  speed:\n    type: float\n    default_value: 1.0\n", "utf-8")
    output = tmp_path / "lost_schema.yaml"
    code = main(["import-gpl", str(source), "-o", str(output)])
    err = capsys.readouterr().err.splitlines()
    assert code == 2
    assert not output.exists()
    assert err == [
        f"{source}:3:5: lost.speed.type: warning: unknown type 'float': parameter left out",
        "imported 0 of 1 parameters; 1 left out (see warnings)",
        f"genparams import-gpl: {source}: no parameter could be imported: nothing written",
    ]
