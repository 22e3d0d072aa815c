"""A deployment manifest read by check-deployment: every mistake named at its place, word for
word, and a good manifest's schemas, prefixes and known names all taking effect."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.cli import main

CAMERA = """\
genparams: 1
name: cam
description: A camera.
parameters:
  fps: {type: double, default: 30.0, description: Frames per second.}
"""
BRINGUP = """\
/robot/cam:
  ros__parameters:
    fps: 15.0
    front.fps: 10.0
    extra.gain: 2
    rate: 5.0
/robot/gps:
  ros__parameters:
    rate: 5.0
"""
IMU_SCHEMAS = "[cam.yaml, 7, {schema: cam.yaml, prefix: 7}, {schema: cam.yaml, extra: 1}, {a: b}]"
MISTAKES = {
    "unknown_key": (
        "genparams_deployment: 1\nknown: [use_sim_time]\nnodez: {}\n",
        [
            "1:1: nodes: nodes: a mapping of node names to their schemas",
            "3:1: nodez: unknown key 'nodez' (known: known, nodes, rules)",
        ],
    ),
    "known_not_a_list": (
        "genparams_deployment: 1\nknown: use_sim_time\nnodes: {}\n",
        [
            "2:8: known: a list of parameter names (globs such as '*.type' too)",
            "3:8: nodes: nodes: a mapping of node names to their schemas",
        ],
    ),
    "nodes_a_list": (
        "genparams_deployment: 1\nnodes: [/robot/cam]\n",
        ["2:8: nodes: nodes: a mapping of node names to their schemas"],
    ),
    "no_version": (
        "nodes:\n  /robot/cam:\n",
        ["1:1: genparams_deployment: write genparams_deployment: 1 (the format version)"],
    ),
    "not_a_mapping": (
        "- /robot/cam\n",
        ["1:1: a manifest is a mapping with genparams_deployment: 1 and nodes:"],
    ),
    "empty": ("", ["1:1: a manifest is a mapping with genparams_deployment: 1 and nodes:"]),
    "node_entries": (
        "genparams_deployment: 1\nnodes:\n"
        "  /robot/c am: {schemas: [cam.yaml]}\n"
        "  /robot/gps: [cam.yaml]\n"
        "  /robot/imu:\n"
        f"    schemas: {IMU_SCHEMAS}\n"
        "    known: [a, 1]\n"
        "    skip: true\n"
        "  /robot/lidar: {schemas: cam.yaml}\n",
        [
            "3:3: nodes./robot/c am: invalid node name: node name 'c am' may hold only letters, "
            "digits and '_'",
            "4:15: nodes./robot/gps: a mapping with schemas: and known:",
            "6:25: nodes./robot/imu.schemas.1: a schema file, or {schema: FILE, prefix: "
            "dotted.name}",
            "6:28: nodes./robot/imu.schemas.2: write {schema: FILE, prefix: dotted.name}",
            "6:59: nodes./robot/imu.schemas.3: write {schema: FILE, prefix: dotted.name}",
            "6:89: nodes./robot/imu.schemas.4: a schema file, or {schema: FILE, prefix: "
            "dotted.name}",
            "7:12: nodes./robot/imu.known: a list of parameter names (globs such as '*.type' too)",
            "8:5: nodes./robot/imu.skip: unknown key 'skip' (known: schemas, known)",
            "9:27: nodes./robot/lidar.schemas: a list of schema files",
        ],
    ),
}


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    (tmp_path / "cam.yaml").write_text(CAMERA, encoding="utf-8")
    (tmp_path / "bringup.yaml").write_text(BRINGUP, encoding="utf-8")
    return tmp_path


def check(
    capsys: pytest.CaptureFixture[str], manifest: Path, *argv: str
) -> tuple[int, list[str], list[str]]:
    bringup = manifest.parent.parent / "bringup.yaml"
    code = main(["check-deployment", str(bringup), "--manifest", str(manifest), *argv])
    out, err = capsys.readouterr()
    return code, out.splitlines(), err.splitlines()


@pytest.mark.parametrize("case", MISTAKES)
def test_every_mistake_is_named_where_it_is(
    case: str, folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    text, expected = MISTAKES[case]
    manifest = folder / "deploy" / "manifest.yaml"
    manifest.parent.mkdir()
    manifest.write_text(text, encoding="utf-8")
    code, out, err = check(capsys, manifest)
    assert (code, out) == (2, [])
    assert err == [f"{manifest}:{line}" for line in expected]


GOOD = """\
genparams_deployment: 1
known: [rate]
nodes:
  /robot/cam:
    schemas: [../cam.yaml, {schema: ../cam.yaml, prefix: front}]
    known: [extra.*]
  /robot/gps: {schemas: [{schema: ../cam.yaml}]}
  /robot/imu:
"""


def test_a_good_manifest_takes_effect(folder: Path, capsys: pytest.CaptureFixture[str]) -> None:
    manifest = folder / "deploy" / "manifest.yaml"  # schema paths are relative to it
    manifest.parent.mkdir()
    manifest.write_text(GOOD, encoding="utf-8")
    bringup = folder / "bringup.yaml"
    code, out, err = check(capsys, manifest, "-v")
    assert (code, err) == (0, [])
    assert out == [
        f"{bringup}: /robot/cam: checked against cam.yaml, cam.yaml@front "
        "(manifest entry /robot/cam)",
        f"{bringup}: /robot/gps: checked against cam.yaml (manifest entry /robot/gps)",
    ]
    # Without the known names, what other code owns is what ROS would ignore.
    manifest.write_text(GOOD.replace("known: [rate]", "known: []").replace("extra.*", ""), "utf-8")
    code, out, err = check(capsys, manifest)
    assert (code, err) == (1, [])
    assert out == [
        f"{bringup}:5:5: extra.gain: unknown parameter: ROS would ignore it",
        f"{bringup}:6:5: rate: unknown parameter: ROS would ignore it",
        f"{bringup}:9:5: rate: unknown parameter: ROS would ignore it",
    ]
