"""import-rclpy on shapes that were mishandled: a script's ``__main__`` block, a
declare_parameters list imported in part, a node of which nothing imports, the
messages of a per-item parameter, names holding ``/``, ``-`` or ``type``, a parameter
held in a variable (``low = node.declare_parameter(...)``, read as ``low.value``), a
method called once under an ``if``, an ``if`` on a base constructor's argument, a read of
every parameter the node has."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from genparams.cli import main


def run(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    code = main(["import-rclpy", *args])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_declarations_under_the_main_guard_run(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "script.py"
    source.write_text(
        "import rclpy\nfrom rclpy.node import Node\n\n"
        'if __name__ == "__main__":\n'
        "    rclpy.init()\n"
        '    node = Node("script")\n'
        "    rate = 5.0\n"
        '    node.declare_parameter("rate", rate)\n'
        '    if node.get_parameter("rate").value > 1.0:\n'
        '        node.declare_parameter("fast", True)\n',
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    parameters = yaml.safe_load(out)["parameters"]
    assert parameters["rate"] == {"type": "double", "default": 5.0}
    assert "fast" not in parameters  # a condition inside the block stays one
    assert code == 1 and "declared only under a condition" in err


def test_a_list_imported_in_part_is_patched(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    source = tmp_path / "lists.py"
    source.write_text(
        "class Lists:\n"
        "    def __init__(self):\n"
        "        self.declare_parameters(\n"
        '            "",\n'
        "            [\n"
        '                ("rate", 10.0),\n'
        '                ("bad name", 1),\n'
        '                ("mode", "x"),\n'
        "            ],\n"
        "        )\n",
        encoding="utf-8",
    )
    monkeypatch.chdir(tmp_path)
    code, diff, err = run(capsys, "lists.py", "--patch")
    assert code == 1 and "the patch changes nothing" not in err
    assert '-                ("rate", 10.0),\n' in diff
    assert '-                ("mode", "x"),\n' in diff
    assert "+        self.params = ListsParams.declare(self)\n" in diff
    if shutil.which("patch"):
        subprocess.run(["patch", "-p0", "--quiet"], input=diff, text=True, check=True)
        patched = source.read_text("utf-8")
        assert '("bad name", 1)' in patched and '("rate", 10.0)' not in patched


def test_a_patch_that_changes_nothing_says_why(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    source = tmp_path / "loop.py"
    source.write_text(
        "class Loop:\n"
        "    def __init__(self):\n"
        "        for n in ['a', 'bad name']:\n"
        "            self.declare_parameter(n, 1)\n"
        "        self.declare_parameter('c', float(input()))\n",
        encoding="utf-8",
    )
    monkeypatch.chdir(tmp_path)
    code, diff, err = run(capsys, "loop.py", "--patch")
    assert code == 2 and diff == ""
    assert "no parameter could be imported: nothing written" in err


def test_nothing_imported_is_bad_input_and_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "computed.py"
    source.write_text(
        "class Computed:\n    def __init__(self):\n"
        "        self.declare_parameter('home', os.environ['HOME'])\n",
        encoding="utf-8",
    )
    out_file = tmp_path / "computed.yaml"
    code, out, err = run(capsys, str(source), "-o", str(out_file))
    assert (code, out, out_file.exists()) == (2, "", False)
    assert "imported 0 of 1 parameters" in err


def test_a_per_item_warning_names_the_parameter_as_written(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "items.py"
    source.write_text(
        "class Items:\n    def __init__(self):\n"
        "        self.declare_parameter('on', True)\n"
        "        self.declare_parameter('joints', ['a'])\n"
        "        if self.get_parameter('on').value == True:\n"
        "            for joint in self.get_parameter('joints').value:\n"
        "                self.declare_parameter(joint, 1)\n"
        "                self.declare_parameter(f'offsets.{joint}', 1)\n",
        encoding="utf-8",
    )
    code, _, err = run(capsys, str(source))
    assert code == 1
    assert ":7:40: {joint}: warning: " in err
    assert ":8:40: offsets.{joint}: warning: " in err
    assert ": *: " not in err


def test_names_holding_slashes_dashes_and_type_are_kept_as_rclpy_declares_them(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "names.py"
    source.write_text(
        "class Names:\n    def __init__(self):\n"
        "        self.declare_parameter('input_shape/height', 480)\n"
        "        self.declare_parameter('walk.type', 'topic')\n"
        "        self.declare_parameter('walk.axes.twist-linear-x', 1)\n"
        "        self.declare_parameter('speed-max', 1.0)\n"
        "        self.declare_parameter('speed_max', 2.0)\n"
        "        self.declare_parameter('bad name', 1)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    parameters = yaml.safe_load(out)["parameters"]
    assert parameters["input_shape/height"] == {"type": "int", "default": 480}
    assert parameters["walk"] == {
        "type": {"type": "string", "default": "topic"},
        "axes": {"twist-linear-x": {"type": "int", "default": 1}},
    }
    assert parameters["speed-max"] == {"type": "double", "default": 1.0}
    assert "speed_max" not in parameters and "bad name" not in parameters
    assert code == 1
    assert (
        "speed_max: warning: 'speed_max' and 'speed-max' of one namespace would share the "
        "Python attribute 'speed_max': parameter left out"
    ) in err
    assert "bad name: warning: not a name genparams declares (dotted names of letters" in err
    assert err.endswith("imported 4 of 6 parameters; 2 left out (see warnings)\n")


def test_a_default_computed_from_another_parameter_is_kept_with_a_note(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "gains.py"
    source.write_text(
        "class Gains:\n    def __init__(self):\n"
        "        self.declare_parameter('joints', ['a', 'b'])\n"
        "        self.declare_parameter('default_gain', 2.0)\n"
        "        count = len(self.get_parameter('joints').value)\n"
        "        self.declare_parameter('limits', [55.0] * count)\n"
        "        for j in self.get_parameter('joints').value:\n"
        "            gain = self.get_parameter('default_gain').value\n"
        "            self.declare_parameter(f'gains.{j}', gain)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    parameters = yaml.safe_load(out)["parameters"]
    assert code == 0 and "warning" not in err
    assert parameters["limits"] == {"type": "double_array", "default": [55.0, 55.0]}
    assert parameters["gains"] == {"type": "double", "default": 2.0, "for_each": "joints"}
    assert "limits: note: a default computed from the parameter(s) 'joints'" in err
    assert "gains.{j}: note: a default computed from the parameter(s) 'default_gain'" in err
    assert err.endswith("imported 4 of 4 parameters (2 approximately)\n")


def test_a_nested_function_only_handed_on_stays_out_with_a_warning(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "later.py"
    source.write_text(
        "class Later:\n    def __init__(self):\n"
        "        self.declare_parameter('rate', 1.0)\n"
        "        def late():\n"
        "            self.declare_parameter('late', 2.0)\n"
        "        self.create_timer(1.0, late)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    assert code == 1 and "late" not in yaml.safe_load(out)["parameters"]
    assert "late: warning: declared inside the nested definition late: parameter left out" in err


def test_a_nested_function_is_read_at_each_call_with_its_arguments(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "calls.py"
    source.write_text(
        "class Calls:\n    def __init__(self):\n"
        "        base = 'limits'\n"
        "        def limit(axis, value=1.0):\n"
        "            name = base + '.' + axis\n"
        "            self.declare_parameter(name, value)\n"
        "        limit('x')\n"
        "        limit('y', value=2.5)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    assert code == 0, err
    assert yaml.safe_load(out)["parameters"] == {
        "limits": {"x": {"type": "double", "default": 1.0}, "y": {"type": "double", "default": 2.5}}
    }
    assert ":7:9: limits.x: note: declared by the nested function limit()" in err


def test_a_per_item_name_in_a_variable_holding_more_stays_out(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "upper.py"
    source.write_text(
        "class Upper:\n    def __init__(self):\n"
        "        self.declare_parameter('joints', ['a'])\n"
        "        for joint in self.get_parameter('joints').value:\n"
        "            key = 'gains.' + joint.upper()\n"
        "            self.declare_parameter(key, 1.0)\n"
        "            key = 'offsets.' + joint\n"
        "            self.declare_parameter(key, 0.0)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    parameters = yaml.safe_load(out)["parameters"]
    assert code == 1 and "gains" not in parameters
    assert parameters["offsets"] == {"type": "double", "default": 0.0, "for_each": "joints"}
    assert ":6:36: warning: a name computed at run time (a call of joint.upper())" in err


def test_the_patch_drops_a_variable_that_only_named_a_declaration(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    source = tmp_path / "axes.py"
    source.write_text(
        "class Axes:\n    def __init__(self):\n"
        "        self.declare_parameter('axes', ['x'])\n"
        "        for axis in self.get_parameter('axes').value:\n"
        "            key = 'tolerance.' + axis\n"
        "            self.declare_parameter(key, 0.05)\n"
        "        for axis in self.get_parameter('axes').value:\n"
        "            name = 'gain.' + axis\n"
        "            self.declare_parameter(name, 1.0)\n"
        "            print(self.get_parameter(name).value)\n",
        encoding="utf-8",
    )
    monkeypatch.chdir(tmp_path)
    code, diff, _ = run(capsys, "axes.py", "--patch")
    assert code == 0
    assert "-            key = 'tolerance.' + axis\n" in diff
    assert "-            name = 'gain.' + axis\n" not in diff  # still read
    if shutil.which("patch"):
        subprocess.run(["patch", "-p0", "--quiet"], input=diff, text=True, check=True)
        lint = subprocess.run(
            [sys.executable, "-m", "ruff", "check", "--isolated", "--select", "F,E9", "axes.py"],
            capture_output=True,
            text=True,
            check=False,
        )
        assert lint.returncode == 0, lint.stdout


def test_a_base_class_defined_under_a_module_level_if_is_followed(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A compatibility package beside the node's defines its node class once per ROS
    version, under ``if``/``elif`` at module level; another name comes in a ``try``."""
    compat = tmp_path / "bridge_compat"
    (compat / "src" / "bridge_compat").mkdir(parents=True)
    (compat / "package.xml").write_text("<package/>\n", encoding="utf-8")
    (compat / "src" / "bridge_compat" / "__init__.py").write_text("", encoding="utf-8")
    (compat / "src" / "bridge_compat" / "node.py").write_text(
        "import os\n\n"
        "try:\n"
        "    DEFAULT_RATE = float(os.environ['RATE'])\n"
        "except KeyError:\n"
        "    DEFAULT_RATE = 20.0\n\n"
        "if os.environ.get('ROS_VERSION') == '1':\n"
        "    class BridgeNode(object):\n"
        "        def get_param(self, name, default):\n"
        "            return default\n"
        "elif os.environ.get('ROS_VERSION') == '2':\n"
        "    from rclpy.node import Node\n\n"
        "    class BridgeNode(Node):\n"
        "        def __init__(self, name):\n"
        "            super().__init__(name)\n"
        "            self.declare_parameter('rate', 20.0)\n\n"
        "        def get_param(self, name, default):\n"
        "            return self.declare_parameter(name, default).value\n",
        encoding="utf-8",
    )
    node_package = tmp_path / "bridge_tools"
    (node_package / "bridge_tools").mkdir(parents=True)
    (node_package / "package.xml").write_text("<package/>\n", encoding="utf-8")
    (node_package / "bridge_tools" / "__init__.py").write_text("", encoding="utf-8")
    source = node_package / "bridge_tools" / "relay.py"
    source.write_text(
        "from bridge_compat.node import BridgeNode\n\n\n"
        "class Relay(BridgeNode):\n"
        "    def __init__(self):\n"
        "        super().__init__('relay')\n"
        "        self.topic = self.get_param('topic', '/relay')\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    assert code == 0, err
    parameters = yaml.safe_load(out)["parameters"]
    assert parameters == {
        "rate": {"type": "double", "default": 20.0},
        "topic": {"type": "string", "default": "/relay"},
    }


def test_fields_of_a_mapped_group_sharing_an_attribute_are_left_out_with_the_reason(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "gains.py"
    source.write_text(
        "class Gains:\n    def __init__(self):\n"
        "        self.declare_parameter('joints', ['a', 'b'])\n"
        "        for j in self.get_parameter('joints').value:\n"
        "            self.declare_parameter(f'gains.{j}.p-max', 1.0)\n"
        "            self.declare_parameter(f'gains.{j}.p_max', 2.0)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    gains = yaml.safe_load(out)["parameters"]["gains"]
    assert gains == {"for_each": "joints", "p-max": {"type": "double", "default": 1.0}}
    assert code == 1
    assert (
        "gains.*.p_max: warning: 'p_max' and 'p-max' (of 'gains.*.p-max') of one namespace "
        "would share the Python attribute 'p_max': parameter left out"
    ) in err


def test_a_default_read_from_a_parameter_held_in_a_variable_is_kept_with_a_note(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "winch.py"
    source.write_text(
        "from rclpy.node import Node\n\n\n"
        "class Limits:\n    def __init__(self, node):\n"
        "        self.steps = node.declare_parameter('reel.steps', 4)\n"
        "        low = node.declare_parameter('reel.up_min', 0.5)\n"
        "        self.down = node.declare_parameter('reel.down_min', low.value)\n"
        "        node.declare_parameter('reel.first', self.steps.value + 1)\n"
        "        node.declare_parameter('reel.other', low.value * 2)\n\n\n"
        "class Winch(Node):\n    def __init__(self):\n"
        "        super().__init__('winch')\n        self.limits = Limits(self)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    reel = yaml.safe_load(out)["parameters"]["reel"]
    assert code == 0 and "warning" not in err, err
    assert reel["down_min"] == {"type": "double", "default": 0.5}
    assert reel["first"] == {"type": "int", "default": 5}
    assert reel["other"] == {"type": "double", "default": 1.0}
    assert "reel.down_min: note: a default computed from the parameter(s) 'reel.up_min'" in err
    assert "reel.first: note: a default computed from the parameter(s) 'reel.steps'" in err
    assert err.endswith("imported 5 of 5 parameters (3 approximately)\n")


def test_a_condition_on_a_parameter_held_in_a_variable_becomes_its_when(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "pump.py"
    source.write_text(
        "from rclpy.node import Node\n\n\n"
        "class Pump(Node):\n    def __init__(self):\n"
        "        super().__init__('pump')\n"
        "        self.mode = self.declare_parameter('mode', 'flow')\n"
        "        if self.mode.value == 'pressure':\n"
        "            self.declare_parameter('target_bar', 2.0)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    parameters = yaml.safe_load(out)["parameters"]
    assert code == 0 and "warning" not in err, err
    assert parameters["target_bar"] == {
        "type": "double", "default": 2.0, "when": {"mode": "pressure"}
    }  # fmt: skip


def test_a_truth_test_of_a_bool_parameter_becomes_its_when(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "arm.py"
    source.write_text(
        "from rclpy.node import Node\n\n\n"
        "class Arm(Node):\n    def __init__(self):\n"
        "        super().__init__('arm')\n"
        "        self.declare_parameter('simulated', False)\n"
        "        self.declare_parameter('joints', 6)\n"
        "        if self.get_parameter('simulated').value:\n"
        "            self.declare_parameter('sim_rate', 100.0)\n"
        "        live = self.get_parameter('simulated')\n"
        "        if not live.value:\n"
        "            self.declare_parameter('port', '/dev/arm')\n"
        "        if self.get_parameter('joints').value:\n"
        "            self.declare_parameter('wrist', True)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    parameters = yaml.safe_load(out)["parameters"]
    assert parameters["sim_rate"] == {"type": "double", "default": 100.0,
                                      "when": {"simulated": True}}  # fmt: skip
    assert parameters["port"] == {"type": "string", "default": "/dev/arm",
                                  "when": {"simulated": False}}  # fmt: skip
    assert "wrist" not in parameters
    assert (
        "wrist: warning: declared only under a condition (if self.get_parameter('joints')"
        ".value): a value compared with 'joints' is not a int (a truth test translates on a "
        "bool parameter only): parameter left out"
    ) in err
    assert code == 1 and err.endswith("imported 4 of 5 parameters; 1 left out (see warnings)\n")


def test_a_method_called_once_under_an_if_declares_under_that_if(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "dryer.py"
    source.write_text(
        "import os\nfrom rclpy.node import Node\n\n\n"
        "class Dryer(Node):\n    def __init__(self):\n"
        "        super().__init__('dryer')\n"
        "        self.declare_parameter('heated', False)\n"
        "        if self.get_parameter('heated').value:\n"
        "            self.heater_settings()\n"
        "        if os.environ.get('DRYER_FAN'):\n"
        "            self.fan_settings()\n\n"
        "    def heater_settings(self):\n"
        "        self.declare_parameter('temperature', 60.0)\n\n"
        "    def fan_settings(self):\n"
        "        self.declare_parameter('fan_speed', 3)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source))
    parameters = yaml.safe_load(out)["parameters"]
    assert parameters["temperature"] == {"type": "double", "default": 60.0,
                                         "when": {"heated": True}}  # fmt: skip
    assert "fan_speed" not in parameters
    assert (
        "fan_speed: warning: declared only under a condition (if os.environ.get('DRYER_FAN'))"
    ) in err
    assert code == 1 and err.endswith("imported 2 of 3 parameters; 1 left out (see warnings)\n")


@pytest.mark.parametrize(("given", "declared"), [("", True), (", False", False),
                                                 (", with_fan=True", True)])  # fmt: skip
def test_a_base_constructor_s_if_on_its_argument_follows_what_super_gives_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], given: str, declared: bool
) -> None:
    source = tmp_path / "oven.py"
    source.write_text(
        "from rclpy.node import Node\n\n\n"
        "class Appliance(Node):\n    def __init__(self, name, with_fan=True):\n"
        "        super().__init__(name)\n        if with_fan:\n"
        "            self.fan()\n        if not with_fan:\n"
        "            self.declare_parameter('vent_open', True)\n\n"
        "    def fan(self):\n        self.declare_parameter('fan_speed', 2)\n\n\n"
        "class Oven(Appliance):\n    def __init__(self):\n"
        f"        super().__init__('oven'{given})\n"
        "        self.declare_parameter('temperature', 180.0)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(source), "--class", "Oven")
    parameters = yaml.safe_load(out)["parameters"]
    assert code == 0 and "warning" not in err, err
    assert ("fan_speed" in parameters) is declared
    assert ("vent_open" in parameters) is not declared


@pytest.mark.parametrize(
    "names",
    ["sorted(self._parameters.keys())", "self._parameters", "list(self._parameter_overrides)"],
)
def test_reading_every_parameter_the_node_has_declares_nothing_more(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], names: str
) -> None:
    node = tmp_path / "mixer.py"
    node.write_text(
        "from rclpy.node import Node\n\n\nclass Mixer(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('mixer', automatically_declare_parameters_from_overrides=True)\n"
        "        self.settings = {}\n"
        f"        for name in {names}:\n"
        "            self.settings[name] = self.get_parameter(name).value\n",
        encoding="utf-8",
    )
    params = tmp_path / "mixer.yaml"
    params.write_text("mixer:\n  ros__parameters:\n    bowl: {speed: 3}\n", encoding="utf-8")
    code, out, err = run(capsys, str(node), "--params-file", str(params))
    assert code == 0 and "warning" not in err, err
    assert yaml.safe_load(out)["parameters"] == {"bowl": {"speed": {"type": "int", "default": 3}}}
    assert err.endswith("imported 1 of 1 parameters\n")


_DRIVER = (
    "from rclpy.node import Node\n\n\nclass Driver(Node):\n"
    "    def __init__(self):\n"
    "        super().__init__('driver')\n"
    "        self.port = self.declare_parameter('port', '/dev/ttyUSB0').value\n"
    "        self.create_timer(1.0, self.poll)\n"
    "        self.check()\n\n"
    "    def check(self):\n"
    "        self.declare_parameter('strict', False)\n\n"
    "    @property\n"
    "    def baud(self):\n"
    "        return self.declare_parameter('baud', 4800).value\n\n"
    "    def on_configure(self, state):\n"
    "        self.declare_parameter('retries', 3)\n\n"
    "    def poll(self):\n"
    "        self.declare_parameter('poll_rate', 2.0)\n\n"
    "    def get_frame_id(self):\n"
    "        return self.declare_parameter('frame_id', 'gps').value\n"
)


def test_a_method_nothing_read_calls_declares_approximately_with_a_note(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """rclpy declares ``frame_id`` when a script outside the files read calls
    ``get_frame_id()``, and ``poll_rate`` when the timer first fires; the schema declares
    them with the others, so they import approximately. A method the constructor calls,
    a property and a lifecycle callback are not such methods; read with the script that
    calls ``get_frame_id()``, ``frame_id`` is exact."""
    package = tmp_path / "gps"
    (package / "gps").mkdir(parents=True)
    (package / "setup.py").write_text("", encoding="utf-8")
    (package / "gps" / "__init__.py").write_text("", encoding="utf-8")
    driver = package / "gps" / "driver.py"
    driver.write_text(_DRIVER, encoding="utf-8")
    code, out, err = run(capsys, str(driver))
    assert code == 0, err
    notes = {line.split(": ")[1] for line in err.splitlines() if "no file read calls" in line}
    assert notes == {"poll_rate", "frame_id"}, err
    assert "declared when get_frame_id() runs, which no file read calls" in err
    assert err.endswith("imported 6 of 6 parameters (2 approximately)\n")
    assert set(yaml.safe_load(out)["parameters"]) == {
        "port", "strict", "baud", "retries", "poll_rate", "frame_id"
    }  # fmt: skip
    script = package / "gps" / "serial_node.py"
    script.write_text(
        "import rclpy\nfrom gps.driver import Driver\n\n\ndef main():\n"
        "    rclpy.init()\n    driver = Driver()\n"
        "    baud = driver.declare_parameter('line_baud', 9600).value\n"
        "    frame = driver.get_frame_id()\n"
        "    rclpy.spin(driver)\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(script))
    assert code == 0, err
    notes = {line.split(": ")[1] for line in err.splitlines() if "no file read calls" in line}
    assert notes == {"poll_rate"}, err
    assert err.endswith("imported 7 of 7 parameters (1 approximately)\n")


def test_values_too_large_to_work_out_are_left_to_run_time(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The limits the launch reader keeps (one rule, genparams.rclpy_import.limits): a
    power's exponent over 64 and a list repeated past 4096 items are not computed."""
    node = tmp_path / "big.py"
    node.write_text(
        "class Big:\n    def __init__(self):\n"
        "        self.declare_parameter('huge', 10 ** 10 ** 9)\n"
        "        self.declare_parameter('long', [0.0] * 5000)\n"
        "        self.declare_parameter('fine', [0.0] * 3 + [2.0 ** 10])\n",
        encoding="utf-8",
    )
    code, out, err = run(capsys, str(node))
    assert code == 1, err
    assert "huge: warning: value computed at run time" in err
    assert "long: warning: value computed at run time" in err
    assert yaml.safe_load(out)["parameters"] == {
        "fine": {"type": "double_array", "default": [0.0, 0.0, 0.0, 1024.0]}
    }
