"""The tour of docs/runtime-guide.md (make tour): rules, classes, threads, remote, lifecycle."""

from __future__ import annotations

import sys

from tests.patience import run_patiently
from tests.support import ROOT

TOUR = ROOT / "examples" / "motion" / "tour.py"


def test_tour_runs_every_part() -> None:
    # Nodes, services and threads in one process: the budget is in idle-machine seconds.
    result = run_patiently([sys.executable, str(TOUR)], budget_s=120)
    assert result.returncode == 0, result.stderr
    out = result.stdout
    for line in (
        "set min_speed := 2.0 -> rejected: rule 'speed_order' broken: min_speed <= max_speed "
        "is false for min_speed=2.0, max_speed=1.0",
        "set 1920x1080, aspect_ratio 1.7778 atomically -> accepted",
        "/base_bad: cannot declare motion parameters (2 problems):",
        "  motion heard: max_speed 1.0 -> 2.0",
        "  safety heard: stop_distance 0.5 -> 1.5",
        "set use_sim_time := True\nset base.min_speed",  # nobody heard use_sim_time
        "every committed snapshot keeps min_speed <= max_speed: True",
        "on_change calls chain in commit order: True; node and cfg agree: True",
        "set max_speed=9.0 -> rejected before sending: max_speed: must be within",
        "watch heard: min_speed 0.5 -> 1.25",
        "configured with max_speed=4.0",
        "set min_speed := 4.5 -> rejected: rule 'speed_order' broken",
    ):
        assert line in out, out


def test_tour_names_its_parts() -> None:
    result = run_patiently([sys.executable, str(TOUR), "warp"], budget_s=60)
    assert result.returncode == 2
    assert "unknown part 'warp': choose from rules, several, threads, remote, lifecycle" in (
        result.stderr
    )
