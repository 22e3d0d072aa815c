"""bench.import_rates end to end on a repository made here: exported at its commit from
a bare git copy, each node imported file by file and whole, its generated class and its
own code run on real rclpy nodes, the rows and totals counted."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from bench.import_rates import main
from bench.import_rates_report import share_text

DRIVER = """\
import rclpy
from rclpy.node import Node

from gauge_driver.limits import MAX_RATE


class Gauge(Node):
    def __init__(self):
        super().__init__("gauge")
        self.declare_parameter("port", "/dev/ttyUSB0")
        self.declare_parameter("rate", MAX_RATE)
        self.declare_parameter("sensors", ["left", "right"])
        for sensor in self.get_parameter("sensors").value:
            self.declare_parameter(f"{sensor}.scale", 1.0)


def main():
    rclpy.init()
    rclpy.spin(Gauge())


if __name__ == "__main__":
    main()
"""


def _git(*args: str, cwd: Path) -> str:
    return subprocess.run(
        ["git", *args], cwd=cwd, check=True, capture_output=True, text=True
    ).stdout.strip()


@pytest.fixture
def mirrors(tmp_path: Path) -> tuple[Path, str]:
    work = tmp_path / "work"
    package = work / "gauge_driver"
    (package / "gauge_driver").mkdir(parents=True)
    (package / "package.xml").write_text("<package/>\n", encoding="utf-8")
    (package / "gauge_driver" / "__init__.py").write_text("", encoding="utf-8")
    (package / "gauge_driver" / "limits.py").write_text("MAX_RATE = 50.0\n", encoding="utf-8")
    (package / "gauge_driver" / "gauge.py").write_text(DRIVER, encoding="utf-8")
    (package / "config").mkdir()
    (package / "config" / "gauge.yaml").write_text(
        "gauge:\n  ros__parameters:\n    rate: 20.0\n    sensors: [front]\n", encoding="utf-8"
    )
    _git("init", "-q", cwd=work)
    _git("add", "-A", cwd=work)
    _git("-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "gauge", cwd=work)
    commit = _git("rev-parse", "HEAD", cwd=work)
    copies = tmp_path / "mirrors"
    copies.mkdir()
    _git("clone", "-q", "--bare", str(work), str(copies / "acme+gauges"), cwd=tmp_path)
    return copies, commit


def test_rows_and_totals_of_a_node_checked_on_real_nodes(
    mirrors: tuple[Path, str], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    copies, commit = mirrors
    manifest = tmp_path / "nodes.yaml"
    manifest.write_text(
        "table:\n"
        f"  - {{repo: acme/gauges, commit: {commit}, file: gauge_driver/gauge_driver/gauge.py,"
        " params: gauge_driver/config/gauge.yaml}\n"
        "wide: []\n",
        encoding="utf-8",
    )
    code = main(["--mirrors", str(copies), "--manifest", str(manifest), "--sample", "table",
                 "--details"])  # fmt: skip
    out = capsys.readouterr().out
    assert code == 0, out
    row = next(line for line in out.splitlines() if "gauge.py" in line and line.startswith("|"))
    cells = [c.strip() for c in row.strip("|").split("|")]
    # file by file: the constant from limits.py is not in the file alone
    assert cells[4] == "3 of 4"
    # whole: port, rate, sensors and {sensor}.scale; all four exact on a real node, which
    # declares front.scale as the params file names one sensor: each checked there
    assert cells[5:10] == ["4", "4", "4", "0", "0"]
    assert cells[10] == "4 declared"
    assert "declared by the node's own run only: rate" in out  # the file alone lacks it
    assert "crashes: 0" in out


@pytest.mark.parametrize(
    ("part", "whole", "shown"),
    [(245, 258, "245 of 258 (94.9%)"), (2, 3, "2 of 3 (66.6%)"), (0, 0, "0 of 0")],
)
def test_a_share_is_cut_to_one_decimal_never_rounded_up(part: int, whole: int, shown: str) -> None:
    assert share_text(part, whole) == shown  # 94.96% is below a 95% target, and reads so
