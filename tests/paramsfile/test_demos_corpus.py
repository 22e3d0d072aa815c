"""Every bringup file of ros2_control_demos checks clean against its controllers' schemas.

The manifest (deployments/demos.manifest.yaml) maps each node of the demos to
hand-written schemas of its controller; ros2_control's own keys (``type``,
``update_rate``, the controller manager's table) are declared known there.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from tests import corpus

HERE = Path(__file__).parent
DEMOS = sorted((corpus.folder("paramsfile") / "ros2_control_demos").glob("*/params/*.yaml"))
MANIFEST = HERE / "deployments" / "demos.manifest.yaml"


def test_every_demo_file_checks_clean(capsys: pytest.CaptureFixture[str]) -> None:
    assert len(DEMOS) == 35
    code = main(["check-deployment", "--manifest", str(MANIFEST), "-v", *map(str, DEMOS)])
    out = capsys.readouterr().out.splitlines()
    checked = [line for line in out if ": checked against " in line]
    assert code == 0, [line for line in out if line not in checked]
    assert len(checked) == 81  # 83 sections reach 81 nodes (wildcard + per-robot sections merge)
    assert not [
        line
        for line in checked
        if "checked against no schema" in line and "controller_manager" not in line
    ]
