"""bench.import_rates_select on a repository made here: the wide sample's rule picks the
node classes that declare or read parameters, outside test folders, on the Jazzy branch,
with the params file of the node's package, and the scripts whose functions build a plain
node and declare or read parameters on it."""

from __future__ import annotations

import subprocess
from pathlib import Path
from typing import Any

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
    return _mirrored(tmp_path, FILES)


def _mirrored(tmp_path: Path, files: dict[str, str]) -> tuple[Path, str]:
    """The mirrors folder holding acme/mixer, whose jazzy branch holds ``files``, and
    that branch's commit."""
    work = tmp_path / "work"
    work.mkdir()
    _git("init", "-q", "-b", "rolling", cwd=work)
    (work / "README.md").write_text("mixer\n", encoding="utf-8")
    _git("add", "-A", cwd=work)
    _git("commit", "-qm", "start", cwd=work)
    _git("checkout", "-qb", "jazzy", cwd=work)
    for path, text in files.items():
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


SCRIPTS = {
    "pump/package.xml": "<package/>\n",
    # main() builds a plain node and declares on it: a script node, with its params file
    "pump/pump/pump_script.py": (
        "import rclpy\n\n\n"
        "def main():\n"
        "    rclpy.init()\n"
        "    node = rclpy.create_node('pump')\n"
        "    flow = node.declare_parameter('flow', 2.0).value\n"
        "    rclpy.spin(node)\n"
    ),
    "pump/config/pump.yaml": "pump:\n  ros__parameters:\n    flow: 4.0\n",
    # the __main__ block, with Node imported under another name, reading a parameter
    "pump/pump/valve.py": (
        "import rclpy\n"
        "from rclpy.node import Node as RosNode\n\n"
        "if __name__ == '__main__':\n"
        "    rclpy.init()\n"
        "    valve: RosNode = RosNode('valve')\n"
        "    print(valve.get_parameter('use_sim_time').value)\n"
    ),
    # rclpy.node.Node(...) with a name made at run time: no params file
    "pump/pump/tank.py": (
        "import sys\n\nimport rclpy.node\n\n\n"
        "def run(name):\n"
        "    tank = rclpy.node.Node(f'tank_{name}')\n"
        "    tank.declare_parameter('level', 1)\n\n\n"
        "run(sys.argv[1])\n"
    ),
    # a Node that is not rclpy's (a launch description's), asked for a parameter
    "pump/pump/launcher.py": (
        "from launch_ros.actions import Node\n\n\n"
        "def main():\n"
        "    node = Node(package='pump', executable='pump')\n"
        "    node.get_parameter('flow')\n"
    ),
    # main() asks a node class it builds: the class is the node, and declares nothing
    "pump/pump/drain.py": (
        "import rclpy\nfrom rclpy.node import Node\n\n\n"
        "class Drain(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('drain')\n\n\n"
        "def main():\n"
        "    drain = Drain()\n"
        "    drain.get_parameter('use_sim_time')\n"
    ),
    # a plain node whose parameters a client reads, and one built but never asked
    "pump/pump/asker.py": (
        "import rclpy\nfrom rclpy.node import Node\n"
        "from rclpy.parameter_client import AsyncParameterClient\n\n\n"
        "def main():\n"
        "    node = Node('asker')\n"
        "    client = AsyncParameterClient(node, 'pump')\n"
        "    client.get_parameters(['flow'])\n\n\n"
        "def other():\n"
        "    quiet = rclpy.create_node('quiet')\n"
        "    return quiet\n"
    ),
    # a file whose node class is picked: its main() is no second entry
    "pump/pump/meter.py": (
        "import rclpy\nfrom rclpy.node import Node\n\n\n"
        "class Meter(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('meter')\n"
        "        self.declare_parameter('unit', 'l')\n\n\n"
        "def main():\n"
        "    helper = Node('meter_helper')\n"
        "    helper.declare_parameter('unit', 'l')\n"
    ),
    # a script of a test folder
    "pump/test/probe.py": (
        "import rclpy\n\n\n"
        "def main():\n"
        "    probe = rclpy.create_node('probe')\n"
        "    probe.declare_parameter('depth', 2)\n"
    ),
}


def _selected(copies: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> Any:
    manifest = tmp_path / "nodes.yaml"
    manifest.write_text("repositories: [acme/mixer]\ntable: []\nwide: []\n", encoding="utf-8")
    assert main(["--mirrors", str(copies), "--manifest", str(manifest)]) == 0
    return yaml.safe_load(capsys.readouterr().out)


def test_the_rule_picks_scripts_declaring_on_a_plain_node_they_build(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    copies, commit = _mirrored(tmp_path, SCRIPTS)
    assert _selected(copies, tmp_path, capsys) == [
        {"repo": "acme/mixer", "commit": commit, "file": "pump/pump/meter.py"},
        {"repo": "acme/mixer", "commit": commit, "file": "pump/pump/pump_script.py",
         "params": "pump/config/pump.yaml"},
        {"repo": "acme/mixer", "commit": commit, "file": "pump/pump/tank.py"},
        {"repo": "acme/mixer", "commit": commit, "file": "pump/pump/valve.py"},
    ]  # fmt: skip


def test_scripts_take_the_room_the_classes_leave_under_the_cap(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    classes = {
        f"pump/pump/{name}.py": (
            "from rclpy.node import Node\n\n\n"
            f"class {name.title()}(Node):\n"
            "    def __init__(self):\n"
            f"        super().__init__('{name}')\n"
            "        self.declare_parameter('rate', 1.0)\n"
        )
        for name in ("zeta", "zulu")  # after every script by path: counted first all the same
    }
    copies, _ = _mirrored(tmp_path, {**SCRIPTS, **classes})
    monkeypatch.setattr("bench.import_rates_select.MOST_PER_REPOSITORY", 4)
    files = [entry["file"] for entry in _selected(copies, tmp_path, capsys)]
    assert files == [
        "pump/pump/meter.py", "pump/pump/pump_script.py", "pump/pump/zeta.py",
        "pump/pump/zulu.py",
    ]  # fmt: skip
