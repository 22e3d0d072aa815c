"""check-deployment's report, word for word: the -v notes, the unclaimed sections, --map and
manifest mistakes, each with the exit code the user gets."""

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
    front:
      fps: 10.0
/robot/cma:
  ros__parameters:
    fps: 5.0
/robot/gps:
  ros__parameters:
    rate: 5.0
"""


@pytest.fixture
def files(tmp_path: Path) -> Path:
    """cam.yaml (one parameter, fps) in a folder whose name holds '='."""
    folder = tmp_path / "v=2"
    folder.mkdir()
    (folder / "cam.yaml").write_text(CAMERA, encoding="utf-8")
    (tmp_path / "bringup.yaml").write_text(BRINGUP, encoding="utf-8")
    return folder


def check(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str], str]:
    code = main(["check-deployment", *argv])
    out, err = capsys.readouterr()
    return code, out.splitlines(), err


def test_verbose_names_each_nodes_schemas_and_prefixes(
    files: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bringup = files.parent / "bringup.yaml"
    schema = files / "cam.yaml"
    code, out, err = check(
        capsys,
        str(bringup),
        "--map",
        f"/robot/cam={schema},{schema}@front",
        "--map",
        "/robot/gps=",
        "--map",
        f"/*/lidar={schema}",  # a pattern no section reaches configures nothing here
        "--known",
        "rate",
        "-v",
    )
    assert (code, err) == (1, "")
    assert out == [
        f"{bringup}:6:1: /robot/cma: no node of the manifest gets this section (did you mean "
        "/robot/cam? node name 'cma' is close to 'cam': a typo?): nothing checks it, and ROS "
        "applies it to no node listed",
        f"{bringup}: /robot/cam: checked against cam.yaml, cam.yaml@front "
        "(manifest entry /robot/cam)",
        f"{bringup}: /robot/gps: checked against no schema (manifest entry /robot/gps)",
    ]


def test_a_section_close_to_no_node_gets_no_hint(
    files: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bringup = files.parent / "bringup.yaml"
    code, out, err = check(capsys, str(bringup), "--map", f"/robot/cam={files / 'cam.yaml'}")
    assert (code, err) == (1, "")
    assert out == [
        f"{bringup}:5:7: front.fps: unknown parameter (did you mean 'fps'?): ROS would ignore it",
        f"{bringup}:6:1: /robot/cma: no node of the manifest gets this section (did you mean "
        "/robot/cam? node name 'cma' is close to 'cam': a typo?): nothing checks it, and ROS "
        "applies it to no node listed",
        f"{bringup}:9:1: /robot/gps: no node of the manifest gets this section: nothing checks "
        "it, and ROS applies it to no node listed",
    ]


@pytest.mark.parametrize("prefix", ["sensors.front", "front"], ids=["dotted", "plain"])
def test_a_schema_under_a_prefix_claims_the_prefixed_keys(
    prefix: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    schema = tmp_path / "at@x" / "cam.yaml"  # only the last '@' starts a prefix
    schema.parent.mkdir()
    schema.write_text(CAMERA, encoding="utf-8")
    bringup = tmp_path / "prefixed.yaml"
    bringup.write_text(
        f"/robot/cam:\n  ros__parameters:\n    {prefix}.fps: 12.0\n    fps: 1.0\n",
        encoding="utf-8",
    )
    code, out, err = check(capsys, str(bringup), "--map", f"/robot/cam={schema}@{prefix}")
    assert (code, err) == (1, "")
    assert out == [
        f"{bringup}:4:5: fps: unknown parameter (did you mean '{prefix}.fps'?): ROS would ignore it"
    ]


@pytest.mark.parametrize(
    ("spec", "message"),
    [
        ("/robot/cam", "expected NODE=SCHEMA[@PREFIX][,SCHEMA...], got '/robot/cam'"),
        ("=cam.yaml", "expected NODE=SCHEMA[@PREFIX][,SCHEMA...], got '=cam.yaml'"),
        (
            "/robot/c am=cam.yaml",
            "invalid node '/robot/c am': node name 'c am' may hold only letters, digits and '_'",
        ),
        ("/robot/cam=cam.yaml@bad..x", "invalid prefix 'bad..x' in '/robot/cam=cam.yaml@bad..x'"),
        ("/robot/cam=a.yaml,cam.yaml@9x", "invalid prefix '9x' in '/robot/cam=a.yaml,cam.yaml@9x'"),
    ],
)
def test_a_bad_map_is_named(spec: str, message: str, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = check(capsys, "bringup.yaml", "--map", spec)
    assert (code, out) == (2, [])
    assert err == f"genparams check-deployment: --map: {message}\n"


def test_a_manifest_names_each_mistake_where_it_is(
    tmp_path: Path, files: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    manifest = tmp_path / "manifest.yaml"
    manifest.write_text(
        "genparams_deployment: 2\n"
        "nodes:\n"
        "  /robot/cam:\n"
        "    schemas: cam.yaml\n"
        "    known: type\n"
        "  /robot/gps:\n"
        "    schemas: [{schema: cam.yaml, prefix: bad..prefix}]\n",
        encoding="utf-8",
    )
    code, out, err = check(capsys, str(files.parent / "bringup.yaml"), "--manifest", str(manifest))
    assert (code, out) == (2, [])
    assert err.splitlines() == [
        f"{manifest}:1:23: genparams_deployment: write genparams_deployment: 1 "
        "(the format version)",
        f"{manifest}:4:14: nodes./robot/cam.schemas: a list of schema files",
        f"{manifest}:5:12: nodes./robot/cam.known: a list of parameter names (globs such as "
        "'*.type' too)",
        f"{manifest}:7:15: nodes./robot/gps.schemas.0: write {{schema: FILE, prefix: dotted.name}}",
    ]


def test_a_manifest_prefix_may_be_dotted(
    tmp_path: Path, files: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    manifest = files / "manifest.yaml"
    manifest.write_text(
        "genparams_deployment: 1\nnodes:\n"
        "  /robot/cam:\n    schemas: [{schema: cam.yaml, prefix: sensors.front}]\n",
        encoding="utf-8",
    )
    bringup = tmp_path / "dotted.yaml"
    bringup.write_text("/robot/cam:\n  ros__parameters:\n    sensors.front.fps: 1\n", "utf-8")
    code, out, err = check(capsys, str(bringup), "--manifest", str(manifest), "-v")
    assert (code, err) == (1, "")
    assert out == [
        f"{bringup}:3:24: sensors.front.fps: wrong type: expected double, got integer 1 "
        "(ROS does not convert: write 1.0)",
        f"{bringup}: /robot/cam: checked against cam.yaml@sensors.front "
        "(manifest entry /robot/cam)",
    ]


@pytest.mark.parametrize("text", ["- /robot/cam\n", ""], ids=["list", "empty"])
def test_a_manifest_that_is_no_mapping_is_named(
    text: str, tmp_path: Path, files: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    manifest = tmp_path / "manifest.yaml"
    manifest.write_text(text, encoding="utf-8")
    code, out, err = check(capsys, str(files.parent / "bringup.yaml"), "--manifest", str(manifest))
    assert (code, out) == (2, [])
    assert (
        err == f"{manifest}:1:1: a manifest is a mapping with genparams_deployment: 1 and nodes:\n"
    )
