"""The test params files of ros2_controllers, checked node by node against their schemas.

deployments/controllers.manifest.yaml maps each test node to schemas written
from its controller's parameters. What check-deployment flags must be real:
a key no class of the node declares. Sections of controllers without a schema
here are reported as unclaimed, and nothing else about them.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main
from tests import corpus

HERE = Path(__file__).parent
CORPUS = corpus.folder("paramsfile")
FILES = sorted((CORPUS / "ros2_controllers").glob("*/params/*.yaml"))
MANIFEST = HERE / "deployments" / "controllers.manifest.yaml"
UNCLAIMED = "no node of the manifest gets this section"


def test_only_real_problems_are_flagged(capsys: pytest.CaptureFixture[str]) -> None:
    assert len(FILES) == 31
    code = main(["check-deployment", "--manifest", str(MANIFEST), "-v", *map(str, FILES)])
    out = capsys.readouterr().out.splitlines()
    assert code == 1
    checked = [line for line in out if ": checked against " in line]
    unclaimed = [line for line in out if UNCLAIMED in line]
    warnings = [line for line in out if ": warning: " in line]
    flagged = [line for line in out if line not in checked + unclaimed + warnings]
    assert len(checked) == 28
    assert (
        len(unclaimed) == 20
    )  # admittance, battery, chained filter, mecanum, ... : no schema here
    found = sorted(
        (str(Path(line.split(":", 1)[0]).relative_to(CORPUS)), line.split(": ")[1])
        for line in flagged
    )
    steering = "ros2_controllers/steering_controllers_library/params/"
    steering += "steering_controllers_library_params.yaml"
    assert found == [
        # gps_sensor_broadcaster declares no "service": ROS ignores the key.
        (
            "ros2_controllers/gps_sensor_broadcaster/params/gps_sensor_broadcaster_params.yaml",
            "service",
        ),
        # The library's own test node gets the Ackermann class's keys; only the library declares.
        (steering, "front_wheel_track"),
        (steering, "front_wheels_radius"),
        (steering, "rear_wheel_track"),
        (steering, "rear_wheels_radius"),
        (steering, "wheelbase"),
    ]
