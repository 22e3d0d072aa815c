"""import-rclpy reads a node as its package: a driver object declaring on the node, a base
class wrapping declare_parameter, helpers declaring what they are asked, a node taking its
parameters from its params file. Each package's node runs on a real node; the class
generated from the imported schema must declare the same parameters, value by value."""

from __future__ import annotations

import importlib
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
import yaml

from genparams.cli import main
from genparams.runtime.core.naming import class_name
from tests.rclpy_import.declared import declared
from tests.support import RosHarness, load_generated

PACKAGES = Path(__file__).resolve().parent / "packages"


@dataclass(frozen=True)
class PackageCase:
    package: str  # folder under PACKAGES
    module: str  # the node's module, as the package imports it
    cls: str
    code: int  # the import's exit code
    params: str | None = None  # a params file in the package folder
    files: tuple[str, ...] = ()  # the other files the import must name as read

    @property
    def node_file(self) -> Path:
        return PACKAGES / self.package / (self.module.replace(".", "/") + ".py")

    @property
    def ros_args(self) -> list[str]:
        return ["--params-file", str(PACKAGES / self.package / self.params)] if self.params else []


CASES = [
    PackageCase(
        "gps_reader", "gps_reader.gps_node", "GpsNode", 0,
        files=("gps_reader/serial_link.py", "gps_reader/limits.py"),
    ),
    PackageCase("arm_state", "arm_state.arm_state_node", "ArmStateNode", 0,
                files=("arm_state/params.py",)),
    PackageCase("pad_teleop", "pad_teleop.pad_teleop_node", "PadTeleop", 0,
                params="pad_teleop.params.yaml"),
    # Names holding '-' and '/', and parameters named type: kept as ROS spells them.
    PackageCase("command_pad", "command_pad.command_pad_node", "CommandPad", 0,
                params="command_pad.params.yaml"),
]  # fmt: skip


def imported(case: PackageCase, capsys: pytest.CaptureFixture[str], out: Path) -> str:
    params = ["--params-file", str(PACKAGES / case.package / case.params)] if case.params else []
    code = main(["import-rclpy", str(case.node_file), *params, "-o", str(out)])
    err = capsys.readouterr().err
    assert code == case.code, err
    return err


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.package)
def test_the_package_s_node_declares_what_the_generated_class_declares(
    case: PackageCase,
    ros: RosHarness,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    schema = tmp_path / f"{case.package}.yaml"
    err = imported(case, capsys, schema)
    for file in case.files:
        assert file in err.split("never run: ")[1].splitlines()[0]
    monkeypatch.syspath_prepend(str(PACKAGES / case.package))
    for name in [m for m in sys.modules if m.split(".")[0] == case.package]:
        monkeypatch.delitem(sys.modules, name)
    node_class: Any = getattr(importlib.import_module(case.module), case.cls)
    cli_args = ["--ros-args", *case.ros_args] if case.params else None
    hand = declared(ros.add_node(node_class(context=ros.context, cli_args=cli_args)))
    generated = load_generated(schema, tmp_path)
    name = yaml.safe_load(schema.read_text("utf-8"))["name"]
    params_class = getattr(generated, class_name(name))
    fresh = ros.node(hand_name(ros), args=case.ros_args)
    params_class.declare(fresh)
    assert declared(fresh) == hand


def hand_name(ros: RosHarness) -> str:
    """The name of the node just built: a params file's section names it."""
    return ros.nodes[-1].get_name()


def test_a_base_class_helper_share_paths_and_computed_defaults(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    node = PACKAGES / "sim_bridge" / "sim_bridge" / "bridge_node.py"
    out = tmp_path / "bridge.yaml"
    monkeypatch.chdir(node.parent)
    code = main(["import-rclpy", node.name, "-o", str(out)])
    err = capsys.readouterr().err
    assert code == 0  # notes only: nothing left out
    parameters = yaml.safe_load(out.read_text("utf-8"))["parameters"]
    assert parameters["use_sim_time_offset"] == {"type": "double", "default": 0.0}  # the base's
    assert parameters["rate"] == {"type": "double", "default": 30.0}  # a constant imported
    assert parameters["topics"] == {"type": "string_array", "default": ["/clock", "/tf"]}
    assert parameters["world"] == {"type": "string", "default": "empty"}  # literal loop
    assert parameters["config_file"] == {
        "type": "string", "default": "$(find-pkg-share sim_bridge)/config/bridge.yaml"
    }  # fmt: skip
    assert "config_file: note: a path in a package's share directory" in err
    assert parameters["gains"] == {"type": "double_array", "default": [55.0, 55.0]}
    assert "gains: note: a default computed from the parameter(s) 'joints'" in err
    assert parameters["input_shape/height"] == {"type": "int", "default": 480}  # as rclpy has it
    assert "sim_bridge/compat.py" in err and "sim_bridge/defaults.py" in err
    assert err.endswith("imported 9 of 9 parameters (2 approximately)\n")
    code = main(["import-rclpy", node.name, "--patch"])
    captured = capsys.readouterr()
    assert (code, captured.out) == (0, "")  # no warning: the note says why nothing changes
    assert "the base class CompatNode declares imported parameters" in captured.err
    assert "compat.py:16:32: use_sim_time_offset: note: declared by the base class" in err


def test_files_outside_the_package_are_never_read(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    outside = tmp_path / "constants.py"
    outside.write_text("RATE = 5.0\n", encoding="utf-8")
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "package.xml").write_text("<package/>\n", encoding="utf-8")
    (package / "node.py").write_text(
        "from ..constants import RATE\nfrom .missing import GAIN\n"
        "class N:\n    def __init__(self):\n"
        "        self.declare_parameter('rate', RATE)\n"
        "        self.declare_parameter('gain', GAIN)\n"
        "        self.declare_parameter('ok', 1)\n",
        encoding="utf-8",
    )
    code = main(["import-rclpy", str(package / "node.py")])
    err = capsys.readouterr().err
    assert code == 1 and "never run" not in err
    outside_files = "value defined outside the files read"
    assert f"rate: warning: {outside_files} ('RATE', imported from ..constants, a module" in err
    assert f"gain: warning: {outside_files} ('GAIN', imported from .missing, a module" in err


def test_a_file_read_alone_names_the_modules_its_defaults_come_from(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Read alone, a node's constants and class attributes from other modules of its
    package cannot be read: each warning names the module to read, not a run-time value;
    read in its package, they import."""
    _write(
        tmp_path,
        {
            "gps/setup.py": "",
            "gps/gps/__init__.py": "",
            "gps/gps/limits.py": "MAX_LENGTH = 82\nclass Client:\n    TIMEOUT = 4.0\n",
            "gps/gps/node.py": (
                "import gps.limits as lim\n"
                "from gps.limits import MAX_LENGTH, Client\n"
                "class N:\n    def __init__(self):\n"
                "        self.declare_parameter('max_length', MAX_LENGTH)\n"
                "        self.declare_parameter('timeout', Client.TIMEOUT)\n"
                "        self.declare_parameter('min_length', lim.MAX_LENGTH // 2)\n"
                "        self.declare_parameter('port', self.open_port())\n"
                "        self.declare_parameter('frame', 'gps')\n"
            ),
        },
    )
    alone = tmp_path / "alone"
    alone.mkdir()
    (alone / "node.py").write_text((tmp_path / "gps/gps/node.py").read_text(), "utf-8")
    assert main(["import-rclpy", str(alone / "node.py")]) == 1
    err = capsys.readouterr().err
    outside_files = "warning: value defined outside the files read"
    assert (
        f"max_length: {outside_files} ('MAX_LENGTH', imported from gps.limits, a module not read)"
        in err
    )
    assert f"timeout: {outside_files} ('Client.TIMEOUT', imported from gps.limits" in err
    assert f"min_length: {outside_files} ('lim.MAX_LENGTH', imported from gps.limits" in err
    assert "port: warning: value computed at run time (a call of self.open_port())" in err
    assert main(["import-rclpy", str(tmp_path / "gps/gps/node.py")]) == 1
    err = capsys.readouterr().err
    assert outside_files not in err
    assert "port: warning: value computed at run time" in err
    assert err.endswith("imported 4 of 5 parameters; 1 left out (see warnings)\n")


def _write(root: Path, files: dict[str, str]) -> None:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


def test_a_package_beside_it_star_imports_guards_and_a_node_built_by_main(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A monitor built in ``main()`` hands itself to a status publisher of a package beside
    its own (re-exported by ``from ._x import *``), which declares its period and, unless
    already declared, a flag; a driver node class the module's function builds declares
    the rest."""
    _write(tmp_path, {
        "status_tools/package.xml": "<package/>\n",
        "status_tools/status_tools/__init__.py": "from ._publisher import *  # noqa\n",
        "status_tools/status_tools/_publisher.py": (
            "class StatusPublisher:\n"
            "    def __init__(self, node, period=1.0):\n"
            "        self.node = node\n"
            "        self.key = 'status.use_fqn'\n"
            "        node.declare_parameter('status.period', period)\n"
            "        if node.has_parameter(self.key):\n"
            "            self.fqn = node.get_parameter(self.key).value\n"
            "        else:\n"
            "            self.fqn = node.declare_parameter(self.key, False).value\n"
        ),
        "watch/package.xml": "<package/>\n",
        "watch/watch/__init__.py": "",
        "watch/watch/driver.py": (
            "from rclpy.node import Node\n\n\nclass WatchDriver(Node):\n"
            "    def __init__(self):\n        super().__init__('watch')\n"
            "        self.declare_parameter('limit', 90)\n"
        ),
        "watch/watch/monitor.py": (
            "from status_tools import StatusPublisher\n\nfrom watch.driver import WatchDriver\n\n\n"
            "def main():\n    node = WatchDriver()\n    node.declare_parameter('window', 1)\n"
            "    StatusPublisher(node)\n\n\nif __name__ == '__main__':\n    main()\n"
        ),
    })  # fmt: skip
    code = main(["import-rclpy", str(tmp_path / "watch" / "watch" / "monitor.py")])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    parameters = yaml.safe_load(captured.out)["parameters"]
    assert parameters == {
        "limit": {"type": "int", "default": 90},
        "window": {"type": "int", "default": 1},
        "status": {
            "period": {"type": "double", "default": 1.0},
            "use_fqn": {"type": "bool", "default": False},
        },
    }
    read = captured.err.split("never run: ")[1].splitlines()[0]
    assert "status_tools/_publisher.py" in read and "driver.py" in read


def test_the_static_evaluator_reads_a_module_s_constants() -> None:
    """The evaluator other readers use (a launch file's values): constants, arithmetic,
    f-strings, share-directory paths; anything else names the construct."""
    import ast

    from genparams.rclpy_import.values import SharePath, UntranslatableError, evaluate_constant

    module = ast.parse("RATE = 10.0\nNAME = 'cam'\nHALF = RATE / 2\n")

    def value(text: str) -> object:
        return evaluate_constant(ast.parse(text, mode="eval").body, module)

    assert value("[HALF, np.pi / 2, f'{NAME}_link']") == [5.0, 1.5707963267948966, "cam_link"]
    # numpy rounds to a float, which rclpy declares a double; math to an int
    rounded = value("[np.floor(HALF / 2), numpy.ceil(2.1), math.floor(HALF / 2)]")
    assert rounded == [2.0, 3.0, 2] and [type(r) for r in rounded] == [float, float, int]
    path = value("os.path.join(get_package_share_directory(NAME), 'config', 'a.yaml')")
    assert isinstance(path, SharePath) and path == "$(find-pkg-share cam)/config/a.yaml"
    with pytest.raises(UntranslatableError, match="the variable 'missing'"):
        value("missing + 1")


def test_reads_of_a_node_declaring_from_its_overrides_take_the_file_s_types(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "trim.py"
    node.write_text(
        "from rclpy.node import Node\n\n\nclass Trim(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('trim', automatically_declare_parameters_from_overrides=True)\n"
        "        self.declare_parameter('joints', ['a', 'b'])\n"
        "        for joint in self.get_parameter('joints').value:\n"
        "            print(self.get_parameter(f'offsets.{joint}').value)\n"
        "        print(self.get_parameter('gain').value)\n",
        encoding="utf-8",
    )
    params = tmp_path / "trim.yaml"
    params.write_text(
        "trim:\n  ros__parameters:\n    gain: 2.5\n    offsets: {a: 0.5, b: 1.0}\n"
        "    other_node_only: {x: 1}\n",
        encoding="utf-8",
    )
    code = main(["import-rclpy", str(node)])
    without = capsys.readouterr()
    assert code == 1 and "read with .value, the params file deciding its type" in without.err
    code = main(["import-rclpy", str(node), "--params-file", str(params)])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    parameters = yaml.safe_load(captured.out)["parameters"]
    assert parameters["offsets"] == {"type": "double", "for_each": "joints"}
    assert parameters["gain"] == {"type": "double", "default": 2.5}
    assert parameters["other_node_only"] == {"x": {"type": "int", "default": 1}}


def test_a_file_of_the_package_that_cannot_be_parsed_is_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    _write(tmp_path, {
        "pkg/package.xml": "<package/>\n",
        "pkg/pkg/__init__.py": "",
        "pkg/pkg/broken.py": "RATE = (\n",
        "pkg/pkg/node.py": (
            "from .broken import RATE\n\n\nclass N:\n    def __init__(self):\n"
            "        self.declare_parameter('rate', RATE)\n        self.declare_parameter('x', 1)\n"
        ),
    })  # fmt: skip
    code = main(["import-rclpy", str(tmp_path / "pkg" / "pkg" / "node.py")])
    err = capsys.readouterr().err
    assert code == 1
    assert "note: files of the package not read" in err
    assert "pkg/broken.py: cannot be read (SyntaxError)" in err


@pytest.mark.parametrize("marker", ["setup.cfg", None])
def test_a_package_marked_by_setup_cfg_or_by_its_init_files_is_followed(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], marker: str | None
) -> None:
    """Its root is the folder holding setup.cfg, or above its last ``__init__.py``; the
    node's base class in a subpackage declares when its constructor is told to."""
    _write(tmp_path, {
        "sorter/sorter/__init__.py": "",
        "sorter/sorter/common/__init__.py": "",
        "sorter/sorter/common/base.py": (
            "from rclpy.node import Node\n\n\nclass Station(Node):\n"
            "    def __init__(self, name, with_limits=True):\n"
            "        super().__init__(name)\n        if with_limits:\n"
            "            self.limits()\n\n    def limits(self):\n"
            "        self.declare_parameter('belt_speed', 0.4)\n"
        ),
        "sorter/sorter/sorter_node.py": (
            "from .common.base import Station\n\n\nclass Sorter(Station):\n"
            "    def __init__(self):\n        super().__init__('sorter', with_limits=True)\n"
        ),
        **({f"sorter/{marker}": "[metadata]\nname = sorter\n"} if marker else {}),
    })  # fmt: skip
    code = main(["import-rclpy", str(tmp_path / "sorter" / "sorter" / "sorter_node.py")])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    assert yaml.safe_load(captured.out)["parameters"] == {
        "belt_speed": {"type": "double", "default": 0.4}
    }
    assert "never run: sorter/common/base.py" in captured.err
