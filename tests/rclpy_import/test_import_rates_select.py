"""bench.import_rates_select on a repository made here: the wide sample's rule picks the
node classes that declare or read parameters, outside test folders, on the Jazzy branch,
with the params file of the node's package."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
import yaml

from bench.import_rates_select import main

FILES = {
    "mixer/package.xml": "<package/>\n",
    "mixer/mixer/__init__.py": "",
    # a node base class whose helper declares: its subclasses read parameters through it
    "mixer/mixer/base.py": (
        "from rclpy.node import Node\n\n\n"
        "class Station(Node):\n"
        "    def setting(self, name, default):\n"
        "        return self.declare_parameter(name, default).value\n"
    ),
    "mixer/mixer/blender.py": (
        "from mixer.base import Station\n\n\n"
        "class Blender(Station):\n"
        "    def __init__(self):\n"
        "        super().__init__('blender')\n"
        "        self.speed = self.setting('speed', 3)\n"
    ),
    # two node classes reading parameters in one file: one entry each
    "mixer/mixer/pair.py": (
        "import rclpy.node\n\n\n"
        "class Left(rclpy.node.Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('left')\n"
        "        self.declare_parameter('gain', 1.0)\n\n\n"
        "class Right(rclpy.node.Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('right')\n"
        "        self.get_parameter('gain')\n"
    ),
    # a node without parameters, and a class that is no node
    "mixer/mixer/quiet.py": (
        "from rclpy.node import Node\n\n\n"
        "class Quiet(Node):\n    pass\n\n\n"
        "class Table:\n"
        "    def get_parameter(self, name):\n        return name\n"
    ),
    "mixer/config/blender.yaml": "blender:\n  ros__parameters:\n    speed: 5\n",
    "mixer/config/other.yaml": "someone_else:\n  ros__parameters:\n    speed: 1\n",
    # a test package's node: left out
    "mixer_system_tests/probe.py": (
        "from rclpy.node import Node\n\n\n"
        "class Probe(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('probe')\n"
        "        self.declare_parameter('depth', 2)\n"
    ),
}


def _git(*args: str, cwd: Path) -> str:
    return subprocess.run(
        ["git", "-c", "user.name=t", "-c", "user.email=t@t", *args],
        cwd=cwd, check=True, capture_output=True, text=True,
    ).stdout.strip()  # fmt: skip


@pytest.fixture
def mirrors(tmp_path: Path) -> tuple[Path, str]:
    """A repository whose default branch lacks the nodes its jazzy branch holds."""
    work = tmp_path / "work"
    work.mkdir()
    _git("init", "-q", "-b", "rolling", cwd=work)
    (work / "README.md").write_text("mixer\n", encoding="utf-8")
    _git("add", "-A", cwd=work)
    _git("commit", "-qm", "start", cwd=work)
    _git("checkout", "-qb", "jazzy", cwd=work)
    for path, text in FILES.items():
        (work / path).parent.mkdir(parents=True, exist_ok=True)
        (work / path).write_text(text, encoding="utf-8")
    _git("add", "-A", cwd=work)
    _git("commit", "-qm", "nodes", cwd=work)
    commit = _git("rev-parse", "HEAD", cwd=work)
    _git("checkout", "-q", "rolling", cwd=work)
    copies = tmp_path / "mirrors"
    copies.mkdir()
    _git("clone", "-q", "--bare", str(work), str(copies / "acme+mixer"), cwd=tmp_path)
    return copies, commit


def test_the_rule_picks_parameter_reading_node_classes_of_the_jazzy_branch(
    mirrors: tuple[Path, str], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    copies, commit = mirrors
    manifest = tmp_path / "nodes.yaml"
    manifest.write_text(
        "repositories: [acme/mixer]\n"
        f"table:\n  - {{repo: acme/mixer, commit: {commit}, file: mixer/mixer/other.py}}\n"
        "wide: []\n",
        encoding="utf-8",
    )
    assert main(["--mirrors", str(copies), "--manifest", str(manifest)]) == 0
    entries = yaml.safe_load(capsys.readouterr().out)
    assert entries == [
        {"repo": "acme/mixer", "commit": commit, "file": "mixer/mixer/blender.py",
         "params": "mixer/config/blender.yaml"},
        {"repo": "acme/mixer", "commit": commit, "file": "mixer/mixer/pair.py", "class": "Left"},
        {"repo": "acme/mixer", "commit": commit, "file": "mixer/mixer/pair.py", "class": "Right"},
    ]  # fmt: skip


def test_a_table_file_is_left_to_the_table(
    mirrors: tuple[Path, str], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    copies, commit = mirrors
    manifest = tmp_path / "nodes.yaml"
    manifest.write_text(
        f"repositories: [acme/mixer]\ntable:\n"
        f"  - {{repo: acme/mixer, commit: {commit}, file: mixer/mixer/pair.py, class: Left}}\n"
        "wide: []\n",
        encoding="utf-8",
    )
    assert main(["--mirrors", str(copies), "--manifest", str(manifest)]) == 0
    files = [e["file"] for e in yaml.safe_load(capsys.readouterr().out)]
    assert files == ["mixer/mixer/blender.py"]
