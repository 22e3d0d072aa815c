"""Schema checks of for_each targets and aliases: every problem, with file:line:col."""

from __future__ import annotations

from pathlib import Path

import pytest

import genparams
from genparams.schema.errors import SchemaError
from genparams.schema.model import Schema


def problems(tmp_path: Path, body: str) -> list[str]:
    path = tmp_path / "bad.yaml"
    path.write_text("genparams: 1\nname: bad\nparameters:\n" + body)
    with pytest.raises(SchemaError) as caught:
        genparams.generate(path)
    return [str(p).replace(f"{path}:", "bad.yaml:") for p in caught.value.problems]


def load(tmp_path: Path, body: str) -> Schema:
    path = tmp_path / "good.yaml"
    path.write_text("genparams: 1\nname: good\nparameters:\n" + body)
    return genparams.load_schema(path)


def test_for_each_must_name_a_fixed_string_array_parameter(tmp_path: Path) -> None:
    body = """\
  joints: {type: string_array, default: [a]}
  rate: {type: double, default: 1.0}
  camera:
    fps: {type: double, default: 1.0}
  gains:
    for_each: jionts
    p: {type: double, default: 1.0}
    names: {type: string_array, default: [x]}
  by_rate:
    for_each: rate
    p: {type: double, default: 1.0}
  by_namespace:
    for_each: camera
    p: {type: double, default: 1.0}
  by_entry:
    for_each: gains.names
    p: {type: double, default: 1.0}
  by_bad_name:
    for_each: "joints 2"
    p: {type: double, default: 1.0}
"""
    assert problems(tmp_path, body) == [
        "bad.yaml:9:15: parameters.gains.for_each: for_each names 'jionts', "
        "which is not a parameter (did you mean 'joints'?)",
        "bad.yaml:13:15: parameters.by_rate.for_each: for_each names 'rate', which is of "
        "type double; it must name a string_array parameter",
        "bad.yaml:16:15: parameters.by_namespace.for_each: for_each names 'camera', "
        "a namespace; it must name a string_array parameter",
        "bad.yaml:19:15: parameters.by_entry.for_each: for_each names 'gains.names', inside "
        "mapped group 'gains', where every entry has its own copy; it must name a parameter "
        "outside every mapped group",
        "bad.yaml:22:15: parameters.by_bad_name.for_each: for_each must be a dotted "
        "parameter name, got 'joints 2'",
    ]


def test_for_each_default_keys_must_be_able_to_name_entries(tmp_path: Path) -> None:
    body = """\
  joints: {type: string_array, default: [left-arm, left.arm]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0}
"""
    assert problems(tmp_path, body) == [
        "bad.yaml:4:41: parameters.joints.default: default violates for_each: item 1 "
        "'left.arm' cannot name an entry of gains: use any text but '.', '*', spaces and "
        "control characters",
    ]


def test_top_level_cannot_be_mapped_and_for_each_is_a_string(tmp_path: Path) -> None:
    assert problems(tmp_path, "  for_each: joints\n  a: {type: int, default: 1}\n") == [
        "bad.yaml:4:3: parameters.for_each: the top level cannot be mapped: "
        "put for_each in a namespace",
    ]
    assert problems(tmp_path, "  g:\n    for_each: [a]\n    a: {type: int, default: 1}\n") == [
        'bad.yaml:5:15: parameters.g.for_each: must be a string, got ["a"]',
    ]


def test_bad_aliases(tmp_path: Path) -> None:
    body = """\
  rate: {type: double, default: 1.0, aliases: [old rate, joints, rate.old, gains.x, speed]}
  top_speed: {type: double, default: 1.0, aliases: [speed]}
  joints: {type: string_array, default: [a]}
  camera:
    fps: {type: double, default: 1.0, aliases: [camera]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0, aliases: [gains_p]}
"""
    assert problems(tmp_path, body) == [
        "bad.yaml:4:48: parameters.rate.aliases[0]: invalid alias 'old rate': dot-separated "
        "names of letters, digits, '_' and '-', starting with a letter, in parts joined by "
        "single '/'",
        "bad.yaml:4:58: parameters.rate.aliases[1]: alias 'joints' collides with parameter "
        "'joints'",
        "bad.yaml:4:66: parameters.rate.aliases[2]: alias 'rate.old' lies under parameter "
        "'rate'; a name cannot be both a value and a namespace",
        "bad.yaml:4:76: parameters.rate.aliases[3]: alias 'gains.x' collides with the entries "
        "of mapped group 'gains'",
        "bad.yaml:5:53: parameters.top_speed.aliases[0]: alias 'speed' collides with alias "
        "'speed' of 'rate'",
        "bad.yaml:8:49: parameters.camera.fps.aliases[0]: alias 'camera' is a namespace of "
        "parameter 'camera.fps'; a name cannot be both a value and a namespace",
        "bad.yaml:11:47: parameters.gains.p.aliases[0]: aliases are not supported inside a "
        "mapped group ('gains.*.p')",
    ]


def test_model_of_a_mapped_group(tmp_path: Path) -> None:
    schema = load(
        tmp_path,
        """\
  joints: {type: string_array, default: [a]}
  fingers: {type: string_array, default: [f]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0, aliases: []}
    tips:
      for_each: fingers
      force: {type: double, default: 0.5}
""",
    )
    gains, tips = schema.root.groups[0], schema.root.groups[0].groups[0]
    assert (gains.mapped_over, gains.spec_path, gains.class_name) == (
        "joints",
        "gains.*",
        "GainsGroup",
    )
    assert (tips.ros_name, tips.spec_path, tips.class_name) == (
        "gains.*.tips",
        "gains.*.tips.*",
        "GainsTipsGroup",
    )
    assert [f.annotation for f in schema.root.fields if f.attribute == "gains"] == [
        "_Mapping[str, GainsGroup]"
    ]
    assert [p.ros_name for p in schema.parameters] == [
        "fingers",
        "gains.*.p",
        "gains.*.tips.*.force",
        "joints",
    ]
    assert schema.maps == (("gains.*.tips", "fingers"), ("gains", "joints"))
