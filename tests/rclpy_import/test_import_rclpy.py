"""`genparams import-rclpy`: golden schemas, warnings and patches; messages and exit codes.

Update the golden files after an intended change: make golden (python -m tests.update_golden rclpy)
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
import yaml

from genparams.cli import main
from genparams.rclpy_import.values import RCLPY_ENUMS
from tests.rclpy_import.cases import CASES, GOLDEN, NODES, Case


def run(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    code = main(["import-rclpy", *args])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def outputs(case: Case, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> dict[str, str]:
    """Schema, messages and patch of one case, run from the nodes' folder as a user would."""
    schema = tmp_path / f"{case.name}.yaml"
    code, out, err = run(capsys, *case.args, "-o", str(schema))
    assert (code, out) == (case.code, ""), err
    code, diff, patch_err = run(capsys, *case.args, "--patch")
    assert code == case.code and patch_err.startswith(err.rstrip("\n").split("\n")[0])
    return {".yaml": schema.read_text("utf-8"), ".stderr": err, ".diff": diff}


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_import_matches_golden(
    case: Case, tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(NODES)
    for suffix, text in outputs(case, tmp_path, capsys).items():
        assert text == (GOLDEN / f"{case.name}{suffix}").read_text("utf-8"), suffix


def test_every_untranslatable_construct_is_a_warning_at_its_place(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.chdir(NODES)
    code, _, err = run(capsys, "legacy_bridge.py", "-o", str(tmp_path / "s.yaml"))
    assert code == 1
    lines = err.splitlines()
    assert (  # the node keeps the option, which changes nothing the schema states
        "legacy_bridge.py:14:43: note: allow_undeclared_parameters=True: the node keeps it"
    ) in lines[0]
    expected = {
        "legacy_bridge.py:25:32: home: warning: value computed": "environment",
        "legacy_bridge.py:27:13: limit: warning: descriptor field description": "imported",
        "legacy_bridge.py:30:13: retries: warning: integer_range on a double": "imported",
        "legacy_bridge.py:35:36: fast_mode: warning: declared only under": "!=, in or not",
        "legacy_bridge.py:46:9: warning: set_descriptor() changes a descriptor": "declared one",
    }
    for start, word in expected.items():
        assert any(line.startswith(start) and word in line for line in lines), start
    assert len([line for line in lines if ": warning: " in line]) == len(expected)
    assert lines[-1] == "imported 10 of 12 parameters (2 approximately); 2 left out (see warnings)"
    written = yaml.safe_load((tmp_path / "s.yaml").read_text("utf-8"))
    assert written["parameters"]["serial"] == {"type": "string", "optional": True}
    assert written["parameters"]["port"] == {"type": "int", "optional": True}
    assert written["parameters"]["anything"] == {"type": "any", "default": 1}
    assert written["parameters"]["*"] == {"type": "double", "default": 0.0, "for_each": "joints"}
    assert written["parameters"]["gains"] == {
        "for_each": "joints", "p": {"type": "double", "default": 1.0}
    }  # fmt: skip
    assert sorted(written["parameters"]) == [
        "*", "anything", "baud", "gains", "joints", "limit", "port", "rate", "retries", "serial"
    ]  # fmt: skip


def test_stdout_without_output(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, str(NODES / "key_teleop.py"))
    assert code == 0 and err.endswith("imported 9 of 9 parameters\n")
    assert out == (GOLDEN / "key_teleop.yaml").read_text("utf-8")


@pytest.mark.parametrize(
    "text, message",
    [
        ("x = 1\ndef f(:\n", "cannot parse as Python"),
        ("class A:\n  def f(self):\n    self.declare_parameter('a', 1)\n\x00", "cannot parse"),
        (
            "class A:\n  def f(self):\n    self.declare_parameter('a', " + "-" * 20000 + "1)\n",
            "1:1: cannot parse as Python",
        ),
        ("import rclpy\n\nprint('no parameters here')\n", "1:1: no parameter declaration"),
        (
            "class N:\n    def __init__(self):\n"
            "        super().__init__('n', automatically_declare_parameters_from_overrides=True)\n",
            "3:31: no parameter declaration found: "
            "automatically_declare_parameters_from_overrides=True",
        ),
    ],
)
def test_bad_input_exits_2_and_writes_nothing(
    text: str, message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "node.py"
    source.write_text(text, encoding="utf-8")
    out_file = tmp_path / "out.yaml"
    code, out, err = run(capsys, str(source), "-o", str(out_file))
    assert (code, out, out_file.exists()) == (2, "", False)
    assert err.startswith(f"{source}:") and message in err


def test_several_classes_need_class(capsys: pytest.CaptureFixture[str]) -> None:
    source = NODES / "two_nodes.py"
    code, _, err = run(capsys, str(source))
    assert code == 2
    assert err == (
        f"{source}:1:1: several parts declare parameters (ClientNode, ServiceNode): "
        "pick a class with --class\n"
    )
    code, _, err = run(capsys, str(source), "--class", "Missing")
    assert code == 2 and "no class Missing declaring parameters" in err
    code, out, _ = run(capsys, str(source), "--class", "ClientNode")
    assert code == 0 and "name: client\n" in out and "client_configure_introspection" in out


def test_an_imported_schema_genparams_refuses_is_not_written(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "node.py"
    source.write_text(
        "class N:\n    def __init__(self):\n"
        "        self.declare_parameter('speed', 5.0, ParameterDescriptor("
        "floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0)]))\n",
        encoding="utf-8",
    )
    out_file = tmp_path / "n.yaml"
    code, _, err = run(capsys, str(source), "-o", str(out_file))
    assert code == 2 and not out_file.exists()
    assert "speed" in err and "the imported schema is not valid" in err


def test_runs_as_a_command() -> None:
    result = subprocess.run(
        [sys.executable, "-m", "genparams", "import-rclpy", str(NODES / "camera_driver.py")],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0 and result.stdout.startswith("# genparams schema imported")


def write_goldens() -> None:
    import contextlib
    import io
    import tempfile

    with contextlib.chdir(NODES), tempfile.TemporaryDirectory() as folder:
        for case in CASES:
            schema = Path(folder) / f"{case.name}.yaml"
            err = io.StringIO()
            with contextlib.redirect_stderr(err):
                main(["import-rclpy", *case.args, "-o", str(schema)])
            diff = io.StringIO()
            with contextlib.redirect_stdout(diff), contextlib.redirect_stderr(io.StringIO()):
                main(["import-rclpy", *case.args, "--patch"])
            (GOLDEN / f"{case.name}.yaml").write_text(schema.read_text("utf-8"), "utf-8")
            (GOLDEN / f"{case.name}.stderr").write_text(err.getvalue(), "utf-8")
            (GOLDEN / f"{case.name}.diff").write_text(diff.getvalue(), "utf-8")


if __name__ == "__main__":
    write_goldens()


def test_rclpy_enum_values_are_rclpy_s() -> None:
    from rclpy import qos

    for name, value in RCLPY_ENUMS.items():
        enum, member = name.split(".")
        assert getattr(getattr(qos, enum), member).value == value, name


def test_a_statement_declaring_several_stays_whole_when_one_is_left_out(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    source = tmp_path / "mixed.py"
    source.write_text(
        "class M:\n"
        "    def __init__(self):\n"
        "        for n in ['a', 'bad name']:\n"
        "            self.declare_parameter(n, 1)\n"
        "        self.declare_parameter('keep', 2)",  # no newline at the end
        encoding="utf-8",
    )
    monkeypatch.chdir(tmp_path)
    code, diff, err = run(capsys, "mixed.py", "--patch")
    assert code == 1
    assert (
        "mixed.py:4:36: a: warning: declared by the same statement as a parameter left out" in err
    )
    assert "imported 1 of 3 parameters; 2 left out (see warnings)" in err
    assert "-            self.declare_parameter(n, 1)" not in diff
    assert diff.endswith(
        "-        self.declare_parameter('keep', 2)\n\\ No newline at end of file\n"
        "+        self.params = MParams.declare(self)\n"
    )
    if shutil.which("patch"):
        subprocess.run(["patch", "-p0", "--quiet"], input=diff, text=True, check=True)
        assert source.read_text("utf-8").endswith("        self.params = MParams.declare(self)\n")


def _imported(tmp_path: Path, body: str, capsys: pytest.CaptureFixture[str]) -> tuple[Any, str]:
    """The schema and messages of a class whose ``__init__`` is ``body``."""
    source = tmp_path / "node.py"
    lines = "".join(f"        {line}\n" for line in body.strip("\n").splitlines())
    source.write_text(f"class N:\n    def __init__(self):\n{lines}", encoding="utf-8")
    code, out, err = run(capsys, str(source))
    assert code in (0, 1, 2), err  # 2: nothing could be imported, nothing written
    return (yaml.safe_load(out)["parameters"] if out else {}), err


def test_conditions_and_loops_read_through_variables(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    parameters, err = _imported(
        tmp_path,
        """
mode = self.declare_parameter('mode', 'fast').value
names = self.get_parameter_or('x', None)
self.declare_parameter('scale', 1.5)
wheels = self.declare_parameter('wheels', ['left', 'right']).value
for wheel in wheels:
    self.declare_parameter('radius.' + wheel, 0.1)
if mode == 'fast':
    self.declare_parameter('boost', True)
if self.get_parameter('scale').value in [1, 2.5]:
    self.declare_parameter('note', 'x')
""",
        capsys,
    )
    assert "warning" not in err
    assert parameters["radius"] == {"type": "double", "default": 0.1, "for_each": "wheels"}
    assert parameters["boost"]["when"] == {"mode": "fast"}
    assert parameters["note"]["when"] == {"scale": [1.0, 2.5]}


@pytest.mark.parametrize(
    "body, message",
    [
        (  # the else of a test that does not translate
            "self.declare_parameter('n', 1)\n"
            "if self.get_parameter('n').value > 0:\n    pass\n"
            "else:\n    self.declare_parameter('x', 1)",
            "declared only under a condition (if self.get_parameter('n').value > 0): "
            "only ==, !=, in or not in",
        ),
        (  # another comparison
            "self.declare_parameter('n', 1)\nif self.get_parameter('n').value > 0:\n"
            "    self.declare_parameter('x', 1)",
            "only ==, !=, in or not in",
        ),
        (  # an elif testing another parameter
            "self.declare_parameter('n', 1)\nself.declare_parameter('m', 1)\n"
            "if self.get_parameter('n').value == 1:\n    pass\n"
            "elif self.get_parameter('m').value == 2:\n    self.declare_parameter('x', 1)",
            "declared only under a condition (if self.get_parameter('n').value == 1): only",
        ),
        (  # a branch no value reaches
            "self.declare_parameter('n', 1)\n"
            "if self.get_parameter('n').value != 1:\n    pass\n"
            "elif self.get_parameter('n').value == 2:\n    self.declare_parameter('x', 1)",
            "no value of 'n' passes the tests around it: it is never declared",
        ),
        (  # a parameter not imported before
            "if self.get_parameter('later').value == 1:\n    self.declare_parameter('x', 1)\n"
            "self.declare_parameter('later', 1)",
            "'later' is not a parameter imported before it",
        ),
        (  # a value of another type
            "self.declare_parameter('n', 1)\nif self.get_parameter('n').value == 'a':\n"
            "    self.declare_parameter('x', 1)",
            "a value compared with 'n' is not a int",
        ),
        (  # an optional parameter decides nothing at startup
            "self.declare_parameter('n', Parameter.Type.INTEGER)\n"
            "if self.get_parameter('n').value == 1:\n    self.declare_parameter('x', 1)",
            "'n' must be a bool, int, double or string parameter with a value",
        ),
        (  # a variable assigned twice
            "self.declare_parameter('n', 1)\nv = self.get_parameter('n').value\nv = 2\n"
            "if v == 1:\n    self.declare_parameter('x', 1)",
            "only ==, !=, in or not in",
        ),
        (  # a loop over a list that is not a string_array parameter
            "self.declare_parameter('ids', [1, 2])\n"
            "for i in self.get_parameter('ids').value:\n    self.declare_parameter(f'w.{i}', 1)",
            "must run over a string_array parameter declared before it",
        ),
        (  # a per-item parameter under a condition
            "self.declare_parameter('on', True)\nself.declare_parameter('js', ['a'])\n"
            "if self.get_parameter('on').value == True:\n"
            "    for j in self.get_parameter('js').value:\n        self.declare_parameter(j, 1)",
            "a per-item parameter has no when",
        ),
        (  # the item is part of a name's token, not a token of its own
            "self.declare_parameter('js', ['a'])\nfor j in self.get_parameter('js').value:\n"
            "    self.declare_parameter(f'gain_{j}.x', 1.0)",
            "only a name holding the item as one whole part between dots translates",
        ),
        (
            "self.declare_parameter('x', Parameter.Type.INTEGER, "
            "ParameterDescriptor(dynamic_typing=True))",
            "a type with dynamic_typing=True: rclpy refuses it",
        ),
        ("self.declare_parameter('x', [], ParameterDescriptor(dynamic_typing=True))", "empty list"),
    ],
)
def test_what_the_new_features_cannot_state_stays_a_warning(
    body: str, message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    parameters, err = _imported(tmp_path, body, capsys)
    assert message in err
    assert "x" not in parameters


def test_declared_by_name_only_is_dynamically_typed_and_optional(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    parameters, err = _imported(
        tmp_path,
        "self.declare_parameter('free')\n"
        "self.declare_parameter('scale', 0.5, ParameterDescriptor(dynamic_typing=True, "
        "floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0)]))",
        capsys,
    )
    assert parameters["free"] == {"type": "any", "optional": True}
    assert parameters["scale"] == {"type": "any", "default": 0.5}
    assert "floating_point_range on a dynamically typed parameter" in err


def test_a_group_per_item_becomes_a_mapped_group(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    parameters, err = _imported(
        tmp_path,
        """
joints = self.declare_parameter('joints', ['a', 'b']).value
self.declare_parameter('cams', ['front'])
for joint in joints:
    self.declare_parameter('pid.' + joint + '.p', 2.0)
    self.declare_parameters(f'pid.{joint}.limits', [('low', -1.0), ('high', 1.0)])
for cam in self.get_parameter('cams').get_parameter_value().string_array_value:
    self.declare_parameter(f'{cam}.topic', '/image')
""",
        capsys,
    )
    assert "warning" not in err
    assert parameters["pid"] == {
        "for_each": "joints",
        "p": {"type": "double", "default": 2.0},
        "limits": {"low": {"type": "double", "default": -1.0},
                   "high": {"type": "double", "default": 1.0}},
    }  # fmt: skip
    assert parameters["*"] == {"for_each": "cams", "topic": {"type": "string", "default": "/image"}}
    assert "joints: note: its items name entries of 'pid' (a mapped group)" in err
    assert "cams: note: its items name entries of the top level (a mapped group)" in err


JS = "self.declare_parameter('js', ['a'])\nself.declare_parameter('ks', ['k'])\n"
GP = "for j in self.get_parameter('js').value:\n    self.declare_parameter(f'g.{j}.p', 1.0)\n"


@pytest.mark.parametrize(
    "body, message, kept",
    [
        (  # a parameter of its own in a mapped group
            f"{JS}{GP}self.declare_parameter('g.extra', 1)",
            "g.extra: warning: 'g' holds one entry per item of 'js': a parameter of its own "
            "cannot sit in it: parameter left out",
            {"for_each": "js", "p": {"type": "double", "default": 1.0}},
        ),
        (  # a namespace holding parameters of its own first
            f"{JS}self.declare_parameter('g.extra', 1)\n"
            "for j in self.get_parameter('js').value:\n    self.declare_parameter(f'g.{j}.p', 1.0)",
            "g.*.p: warning: 'g' already holds parameters of its own: a mapped group holds only "
            "its entries: parameter left out",
            {"extra": {"type": "int", "default": 1}},
        ),
        (  # one namespace keyed by two lists
            f"{JS}{GP}"
            "for k in self.get_parameter('ks').value:\n    self.declare_parameter(f'g.{k}.q', 1.0)",
            "g.*.q: warning: 'g' already holds one entry per item of 'js': parameter left out",
            {"for_each": "js", "p": {"type": "double", "default": 1.0}},
        ),
        (  # a mapped group inside another one's entry
            f"{JS}{GP}"
            "for k in self.get_parameter('ks').value:\n"
            "    self.declare_parameter(f'g.x.{k}.q', 1.0)",
            "'g' holds one entry per item of 'js': a mapped group inside it is not written",
            {"for_each": "js", "p": {"type": "double", "default": 1.0}},
        ),
        (  # under a condition
            f"{JS}self.declare_parameter('on', True)\n"
            "if self.get_parameter('on').value == True:\n"
            "    for j in self.get_parameter('js').value:\n"
            "        self.declare_parameter(f'g.{j}.p', 1.0)",
            "under a condition: a parameter of a mapped group has no when",
            None,
        ),
        (  # two items in one name
            f"{JS}for j in self.get_parameter('js').value:\n"
            "    for k in self.get_parameter('ks').value:\n"
            "        self.declare_parameter(f'g.{j}.{k}', 1.0)",
            "a name computed at run time",
            None,
        ),
    ],
)
def test_a_mapped_group_the_schema_cannot_hold_stays_a_warning(
    body: str, message: str, kept: Any, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    parameters, err = _imported(tmp_path, body, capsys)
    assert message in err
    assert parameters.get("g") == kept


KEYS = "{n.split('.')[1] for n in self._parameter_overrides if n.startswith('s.')}"


def test_keys_found_under_a_prefix_in_the_overrides_make_an_open_group(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    parameters, err = _imported(
        tmp_path,
        f"""
names = sorted({KEYS})
for name in names:
    self.declare_parameter(f's.{{name}}.rate', 5.0)
    self.declare_parameter('s.' + name + '.frame', name + '_link')
for key in list(k.split('.', 1)[0] for k in self.get_parameters_by_prefix('t')):
    self.declare_parameters(f't.{{key}}', [('on', True)])
""",
        capsys,
    )
    assert parameters["s"] == {
        "for_each": "overrides",
        "rate": {"type": "double", "default": 5.0},
        "frame": {"type": "string"},
    }
    assert parameters["t"] == {"for_each": "overrides", "on": {"type": "bool", "default": True}}
    warnings = [line for line in err.splitlines() if ": warning: " in line]
    assert warnings == [
        f"{tmp_path / 'node.py'}:6:36: s.*.frame: warning: a default computed from the item "
        "(name + '_link'): one schema default serves every entry: imported with none, so "
        "each entry must be given a value"
    ]


@pytest.mark.parametrize(
    "body, message",
    [
        (  # one value per key: an open group holds groups
            f"for name in {KEYS}:\n    self.declare_parameter(f's.{{name}}', 1.0)",
            "one value per key found under 's' in the overrides: an open group holds parameters "
            "of each key (s.<key>.<field>)",
        ),
        (  # keys found under one prefix, entries under another
            f"for name in {KEYS}:\n    self.declare_parameter(f'other.{{name}}.x', 1.0)",
            "the keys are found under 's' in the overrides, the name puts them under 'other'",
        ),
        (  # the segment does not follow the prefix
            "for name in {n.split('.')[2] for n in self._parameter_overrides "
            "if n.startswith('s.')}:\n    self.declare_parameter(f's.{name}.x', 1.0)",
            "self._parameter_overrides: reads what the params file brings: only a loop over the "
            "keys found under a prefix",
        ),
        (  # keys from a by-prefix call, on a node that does not declare its overrides
            "for k in self.get_parameters_by_prefix('s'):\n    self.declare_parameter(k, 1.0)",
            "get_parameters_by_prefix(): reads what the params file brings",
        ),
        (  # a read on a node declaring what its overrides name: its name is computed
            "super().__init__('n', automatically_declare_parameters_from_overrides=True)\n"
            "self.declare_parameter('y', 1)\n"
            "for k in ['a']:\n    self.get_parameter(self.prefix + k)",
            "automatically_declare_parameters_from_overrides=True: declares whatever the params "
            "file names, which a schema cannot state",
        ),
    ],
)
def test_what_an_open_group_cannot_hold_stays_a_warning(
    body: str, message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    parameters, err = _imported(tmp_path, body, capsys)
    assert message in err
    assert ": warning: " in err and "x" not in parameters and "s" not in parameters


def test_the_patch_keeps_lines_within_100_columns(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    source = tmp_path / "long.py"
    source.write_text(
        "class LongNamesNode:\n"
        "    def __init__(self):\n"
        "        self.declare_parameter('sides', ['left', 'right'])\n"
        "        for side in self.get_parameter('sides').value:\n"
        "            first, second, third = self.declare_parameters(\n"
        "                f'a_rather_long_namespace.{side}',\n"
        "                [('first_setting', 1), ('second_setting', 2), ('third_setting', 3)],\n"
        "            )\n"
        "            print(first, second, third)\n"
        "        value = self.declare_parameter('a_parameter_whose_name_is_long_enough_to_"
        "wrap_on_a_line_of_its_own', 1.0).type_\n",
        encoding="utf-8",
    )
    monkeypatch.chdir(tmp_path)
    code, diff, err = run(capsys, "long.py", "--patch")
    assert code == 0, err
    assert (
        "+            first, second, third = self.get_parameters(\n"
        "+                [\n"
        "+                    f'a_rather_long_namespace.{side}.first_setting',\n"
    ) in diff
    assert (
        "+        value = self.get_parameter(\n"
        "+            'a_parameter_whose_name_is_long_enough_to_wrap_on_a_line_of_its_own'\n"
        "+        ).type_\n"
    ) in diff
    added = [line[1:] for line in diff.splitlines() if line.startswith("+")]
    assert max(len(line) for line in added) <= 100
