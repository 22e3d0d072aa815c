"""The benchmark scripts run, and compare like with like. No timing is asserted here."""

from __future__ import annotations

import csv
import os
import subprocess
import sys
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

import genparams
from bench.profile import DECLARE_STEPS, SET_STEPS
from bench.report import SECTIONS
from bench.schemas import KINDS, bench_schema
from bench.workspace import import_fresh, prepare
from tests.support import ROOT, RosHarness


@pytest.mark.parametrize(("size", "depth"), [(10, 2), (25, 2), (100, 2), (1_000, 3)])
def test_schema_has_size_unique_names_and_loads(size: int, depth: int, tmp_path: Path) -> None:
    schema = bench_schema(size)
    names = [p.name for p in schema.parameters]
    assert len(names) == len(set(names)) == size
    assert schema.depth == depth
    assert {p.kind.name for p in schema.parameters} == {k.name for k in KINDS}
    path = tmp_path / "bench.yaml"
    path.write_text(schema.yaml_text(), encoding="utf-8")
    loaded = genparams.load_schema(path)
    assert sorted(p.ros_name for p in loaded.parameters) == sorted(names)


def test_hand_written_declaration_matches_genparams(ros: RosHarness, tmp_path: Path) -> None:
    prepared = prepare(20, tmp_path)
    schema = prepared.schema
    params_cls = getattr(import_fresh(schema.module_name, tmp_path), schema.class_name)
    plain = import_fresh(schema.plain_module_name, tmp_path)
    generated_node, plain_node = ros.node(), ros.node()
    params_cls.declare(generated_node)
    plain.declare(plain_node)
    names = [p.name for p in schema.parameters]
    for generated, written in zip(
        generated_node.describe_parameters(names),
        plain_node.describe_parameters(names),
        strict=True,
    ):
        assert generated == written
    assert [generated_node.get_parameter(n).value for n in names] == [
        plain_node.get_parameter(n).value for n in names
    ]
    ranged = generated_node.describe_parameter(schema.parameters[0].name)
    assert ranged.floating_point_range[0].to_value == 100.0
    # Every "other" value the set scenarios use is accepted by both sides.
    others = [Parameter(name, value=value) for name, value in schema.values(other=True).items()]
    assert all(r.successful for r in generated_node.set_parameters(others))
    assert all(r.successful for r in plain_node.set_parameters(others))


def test_quick_benchmark_writes_every_scenario(tmp_path: Path) -> None:
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "bench",
            "--quick",
            "--sizes",
            "10",
            "--repeats",
            "1",
            "--output-dir",
            str(tmp_path),
            "--targets",
            "20,30,40",
            "--target-samples",
            "2",
            "--target-processes",
            "1",
        ],
        cwd=ROOT,
        env=dict(os.environ),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert result.returncode == 0, result.stderr
    with (tmp_path / "benchmarks.csv").open(encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    measured = {(row["scenario"], row["variant"]) for row in rows}
    expected = {(s.scenario, v) for s in SECTIONS for v in s.variants}
    assert measured == expected
    for row in rows:
        assert row["n"] == "10" and int(row["repeats"]) >= 1
        assert float(row["min"]) >= 0 and float(row["median"]) >= float(row["min"])
    report = (tmp_path / "benchmarks.md").read_text(encoding="utf-8")
    for section in SECTIONS:
        assert f"## {section.title}" in report
    assert "_not measured in this run_" not in report
    targets = report.split("## Runtime targets", 1)[1].split("\n## ", 1)[0]
    for target in (
        "one node.set_parameters, N=20 |",
        "one node.set_parameters, N=30 |",
        "declare on a fresh node, N=20 |",
        "whole process, start to declared, N=30 |",
        "RSS growth, N=40 |",
        "RSS growth, N=40, publish_schema=False |",
        "read cfg.",
        "snapshot() O(1)",
        "snapshot() never torn",
    ):
        assert f"| {target}" in targets, target
    assert targets.count(" | met |") + targets.count(" | **missed** |") == 11


def test_profile_splits_declare_and_set_into_steps() -> None:
    result = subprocess.run(
        [sys.executable, "-m", "bench.profile", "--sizes", "10", "--sets", "100"],
        cwd=ROOT,
        env=dict(os.environ),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert "## N = 10" in lines
    assert [line.split(":")[0] for line in lines if "ratio" in line] == [
        "declare",
        "one set (node.set_parameters)",
    ]
    for steps in (DECLARE_STEPS, SET_STEPS):
        for label in list(steps)[:-1]:  # the last is the whole call the shares refer to
            assert any(line.startswith(f"  - {label}: ") for line in lines), label


def test_start_profile_times_every_step_of_both_sides() -> None:
    result = subprocess.run(
        [sys.executable, "-m", "bench.start_profile", "--sizes", "10", "--samples", "1"],
        cwd=ROOT,
        env=dict(os.environ),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert result.returncode == 0, result.stderr
    sides = [line.split()[0] for line in result.stdout.splitlines() if line.startswith("  ")]
    assert (sides.count("plain"), sides.count("genparams")) == (4, 7)
    assert "  genparams  compile the class spec (first declare)" in result.stdout


def test_check_params_scale_runs_and_its_largest_file_fits_the_limit(
    capsys: pytest.CaptureFixture[str],
) -> None:
    from bench.check_params_scale import main, params_text
    from genparams.schema.loader import MAX_BYTES

    assert len(params_text(100_000).encode("utf-8")) <= MAX_BYTES
    assert main(["--sizes", "20,40"]) == 0
    rows = [line for line in capsys.readouterr().out.splitlines() if line.startswith("| 20")]
    assert len(rows) == 1 and rows[0].count("|") == 6
