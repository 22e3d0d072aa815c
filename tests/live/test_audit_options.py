"""The audit's options and output, against real nodes.

- ``--params-file``: a value the file sets is judged against the file only; the node holding
  the file's value is no finding (it was a drift-from-default), a node holding another value
  is a drift-from-file.
- ``--only KIND`` and ``--skip KIND`` pick the findings reported; the exit status follows them.
- A list value prints one way, expected and found alike (a default was printed as a tuple).
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.support import RosHarness
from tests.tune.support import demo_nodes, run_audit, set_values_its_schema_forbids, unique

CAM, LOOSE = f"/{unique('options_cam')}", f"/{unique('options_loose')}"


@pytest.fixture(scope="module")
def running(ros_harness: RosHarness) -> Iterator[None]:
    with (
        demo_nodes(f"{CAM[1:]}:camera", ros_args=("-p", "camera.fps:=15.0")),
        demo_nodes(f"{LOOSE[1:]}:loose"),
    ):
        set_values_its_schema_forbids(ros_harness, LOOSE)
        yield


@pytest.fixture(scope="module")
def deployment(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("options") / "deploy.yaml"
    path.write_text(
        f"{CAM}:\n  ros__parameters:\n    camera:\n      fps: 15.0\n      width: 800\n",
        encoding="utf-8",
    )
    return path


def findings(*args: str) -> tuple[int, list[dict[str, Any]]]:
    done = run_audit("--format", "json", *args, settle=1.0)
    assert "Traceback" not in done.stderr, done.stderr
    return done.returncode, json.loads(done.stdout)["findings"]


def test_values_the_file_sets_are_judged_against_the_file(running: None, deployment: Path) -> None:
    _, found = findings("--params-file", str(deployment), CAM)
    kinds = {(f["parameter"], f["kind"]) for f in found}
    assert ("camera.fps", "drift-from-default") not in kinds, found
    assert ("camera.width", "drift-from-file") in kinds, found
    assert ("camera.fps", "drift-from-file") not in kinds, found
    # Without the file, the same value is a drift from the default.
    _, without = findings(CAM)
    assert ("camera.fps", "drift-from-default") in {(f["parameter"], f["kind"]) for f in without}


def test_only_and_skip_pick_the_kinds_reported(running: None) -> None:
    status, everything = findings(LOOSE, CAM)
    assert status == 1 and {"violation", "drift-from-default"} <= {f["kind"] for f in everything}
    status, only = findings("--only", "drift-from-default", LOOSE, CAM)
    assert status == 0 and {f["kind"] for f in only} == {"drift-from-default"}
    status, skipped = findings("--skip", "drift-from-default", LOOSE, CAM)
    assert status == 1 and "drift-from-default" not in {f["kind"] for f in skipped}
    assert {f["kind"] for f in skipped} == {f["kind"] for f in everything} - {"drift-from-default"}


def test_a_list_prints_one_way(running: None) -> None:
    done = run_audit("--only", "drift-from-default", LOOSE, settle=1.0)
    line = next(line for line in done.stdout.splitlines() if ": weights:" in line)
    assert "(expected [" in line and "found [0.5])" in line, line
