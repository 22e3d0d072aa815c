"""A generated module's compact layout: shared options rows, one class per group shape.

Groups of one shape share their class at run time while type checkers keep one
class per group; parameters of the same rules share one ``ParamOptions``.
"""

from __future__ import annotations

import pickle
import subprocess
import sys
import types
from pathlib import Path

import pytest

import genparams
from genparams.runtime import ParamOptions, ParamSpec
from genparams.runtime.core.spec import compile_schema
from tests.golden import ROOT
from tests.support import load_generated

SCHEMA = """genparams: 1
name: shapes
parameters:
  front:
    x: {type: int, default: 1, range: {min: 0, max: 10}}
    frame: {type: string, default: front_link}
  rear:
    x: {type: int, default: 2, range: {min: 0, max: 10}, description: The rear one.}
    frame: {type: string, default: rear_link}
  wide:
    x: {type: double, default: 1.0}
    frame: {type: string, default: wide_link}
  left:
    lambda: {type: int, default: 3}
  right:
    lambda_: {type: int, default: 4}
  arm:
    front:
      x: {type: int, default: 5, range: {min: 0, max: 10}}
      frame: {type: string, default: arm_front}
  leg:
    front:
      x: {type: int, default: 6, range: {min: 0, max: 10}}
      frame: {type: string, default: leg_front}
"""


def _module(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "shapes.yaml"
    schema.write_text(SCHEMA, encoding="utf-8")
    return load_generated(schema, tmp_path)


def test_groups_of_one_shape_share_a_class_and_keep_their_values(tmp_path: Path) -> None:
    module = _module(tmp_path)
    assert module.RearGroup is module.FrontGroup  # the same attributes, ROS names and types
    assert module.WideGroup is not module.FrontGroup  # x is a double there
    assert module.RightGroup is not module.LeftGroup  # ROS `lambda` against `lambda_`
    assert module.ArmFrontGroup is module.FrontGroup
    assert module.LegGroup is module.ArmGroup  # parents whose children share a class share
    cfg = module.ShapesParams.defaults()
    assert (cfg.front.x, cfg.rear.x, cfg.arm.front.frame, cfg.leg.front.frame) == (
        1,
        2,
        "arm_front",
        "leg_front",
    )
    assert isinstance(cfg.rear, module.RearGroup)
    assert cfg.left.lambda_ == 3
    assert cfg.right.lambda_ == 4
    assert cfg.to_dict()["right"] == {"lambda_": 4}
    assert cfg.to_dict()["left"] == {"lambda": 3}
    assert pickle.loads(pickle.dumps(cfg.rear)) == cfg.rear


def test_a_shared_class_names_no_one_group(tmp_path: Path) -> None:
    """rear's value must not print, nor refuse a write, as front's class."""
    module = _module(tmp_path)
    cfg = module.ShapesParams.defaults()
    assert repr(cfg.rear).startswith("Group(") and "x=2" in repr(cfg.rear)
    assert repr(cfg.front).startswith("Group(")
    assert repr(cfg.wide).startswith("WideGroup(")  # a shape of its own keeps its name
    with pytest.raises(AttributeError, match=r"^Group\b") as refused:
        cfg.rear.x = 5
    assert "FrontGroup" not in str(refused.value)


def test_type_checkers_see_one_class_per_group(tmp_path: Path) -> None:
    module = _module(tmp_path)
    user = tmp_path / "use_shapes.py"
    user.write_text(
        f"from {module.__name__} import FrontGroup, RearGroup, ShapesParams\n"
        "def rear_x(group: RearGroup) -> int:\n"
        "    return group.x\n"
        "cfg = ShapesParams.defaults()\n"
        "rear_x(cfg.rear)\n"
        "front: FrontGroup = cfg.front\n"
        "rear_x(cfg.front)\n",
        encoding="utf-8",
    )
    config = str(ROOT / "pyproject.toml")
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--config-file", config, str(user)],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        check=False,
    )
    out = result.stdout
    assert result.returncode == 1, out + result.stderr
    assert "use_shapes.py:7: error" in out and '"FrontGroup"' in out and '"RearGroup"' in out, out
    assert out.count("error:") == 1, out


def test_parameters_of_the_same_rules_share_their_options(tmp_path: Path) -> None:
    spec = _module(tmp_path).ShapesParams._SPEC
    by_name = {p.name: p for p in spec.parameters}
    assert by_name["front.x"].options is by_name["arm.front.x"].options
    assert by_name["front.x"].options is not by_name["rear.x"].options  # its description
    assert by_name["front.frame"].options is by_name["rear.frame"].options
    rear = by_name["rear.x"]
    assert (rear.type, rear.default, rear.range, rear.description) == (
        "int",
        2,
        (0, 10),
        "The rear one.",
    )


def test_a_param_spec_reads_and_copies_as_one_record() -> None:
    spec = ParamSpec("camera.fps", "double", default=30.0, range=(1.0, 60.0), unit="Hz")
    assert spec.options == ParamOptions("double", range=(1.0, 60.0), unit="Hz")
    assert pickle.loads(pickle.dumps(spec)) == spec
    renamed = spec.replaced(name="camera.rate")
    assert (renamed.name, renamed.default, renamed.options) == ("camera.rate", 30.0, spec.options)
    assert renamed.options is spec.options
    assert spec.replaced(unit="kHz").unit == "kHz" and spec.unit == "Hz"
    assert ParamSpec.row("camera.fps", 30.0, spec.options) == spec
    assert spec != ParamSpec("camera.fps", "double", default=30.0, range=(1.0, 60.0))


def test_compiled_parameters_share_a_kind_and_keep_only_paths_of_their_own(
    tmp_path: Path,
) -> None:
    compiled = compile_schema(_module(tmp_path).ShapesParams._SPEC).parameters
    assert compiled["front.x"].kind is compiled["arm.front.x"].kind
    assert compiled["front.x"].checks is compiled["leg.front.x"].checks
    assert compiled["arm.front.x"].attribute_path == ("arm", "front", "x")
    left, right = compiled["left.lambda"], compiled["right.lambda_"]
    assert left.spec.options is right.spec.options  # both a plain int
    assert left.attribute_path == ("left", "lambda_")  # a keyword: its own path, kept
    assert right.attribute_path == ("right", "lambda_")
    assert left.kind.own_path == ("left", "lambda_") and right.kind.own_path is None


def test_a_table_of_one_parameter_is_laid_out_as_ruff_lays_it_out(tmp_path: Path) -> None:
    # A one-item tuple's comma is no magic trailing comma: ruff joins it when it fits.
    long_default = f'["{"a" * 60}", "{"b" * 60}"]'
    # Two groups of one shape whose names make the alias line longer than a line.
    twins = "".join(f"  {c * 50}:\n    x: {{type: int, default: 1}}\n" for c in "pq")
    for name, kind, default in (
        ("only", "string", '"x"'),
        ("long_" * 9, "string_array", long_default),
    ):
        entry = f"{{type: {kind}, default: {default}}}"
        schema = f"genparams: 1\nname: one\nparameters:\n  {name}: {entry}\n{twins}"
        module = tmp_path / "one_params.py"
        module.write_text(genparams.generate("one.yaml", schema), encoding="utf-8")
        result = subprocess.run(
            [
                sys.executable,
                "-m",
                "ruff",
                "format",
                "--check",
                "--diff",
                "--no-cache",
                str(module),
            ],
            cwd=ROOT,
            capture_output=True,
            text=True,
            timeout=120,
            check=False,
        )
        assert result.returncode == 0, result.stdout + result.stderr
