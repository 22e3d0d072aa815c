"""genparams audit checks a manifest's rules across nodes on real running nodes: values
read over each node's services, with a schema or without."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import pytest

from genparams.audit.findings import NOT_CHECKED, RULE_ACROSS_NODES
from tests.support import RosHarness
from tests.tune.support import demo_nodes, run_audit, unique

SLOW, FAST, PLAIN = (f"/{unique(f'audit_rules_{s}')}" for s in ("slow", "fast", "plain"))


@pytest.fixture(scope="module")
def running(ros_harness: RosHarness) -> Iterator[None]:
    with (
        demo_nodes(f"{SLOW[1:]}:camera", ros_args=("-p", "camera.fps:=15.0")),
        demo_nodes(f"{FAST[1:]}:camera", f"{PLAIN[1:]}:plain"),
    ):
        yield


def manifest(folder: Path, rules: str) -> Path:
    path = folder / "manifest.yaml"
    path.write_text(
        f"genparams_deployment: 1\nnodes:\n  {SLOW}: {{}}\n  {FAST}: {{}}\n  {PLAIN}: {{}}\n"
        f"rules:\n{rules}",
        encoding="utf-8",
    )
    return path


def test_rules_across_running_nodes(running: None, tmp_path: Path) -> None:
    rules = (
        f"  - {{name: clock, same: use_sim_time, nodes: [{SLOW}, {FAST}, {PLAIN}]}}\n"
        f"  - {{name: one_rate, same: camera.fps, nodes: [{SLOW}, {FAST}]}}\n"
        f"  - {{name: ordered, check: '{SLOW}.camera.fps < {FAST}.camera.fps'}}\n"
        f"  - {{name: gain, check: '{PLAIN}.gain * 10 >= {FAST}.camera.fps'}}\n"
        f"  - {{name: absent, check: '/no_such_node.rate > {PLAIN}.gain'}}\n"
    )
    path = manifest(tmp_path, rules)
    done = run_audit("--format", "json", "--manifest", str(path), SLOW, FAST, PLAIN)
    assert done.returncode == 1, done.stdout + done.stderr
    report = json.loads(done.stdout)
    found = {
        f["parameter"]: (f["kind"], f["node"], f["detail"])
        for f in report["findings"]
        if f["kind"] in (RULE_ACROSS_NODES, NOT_CHECKED)
    }
    assert set(found) == {"one_rate", "gain", "absent"}
    assert found["one_rate"] == (
        RULE_ACROSS_NODES,
        f"{path}:8:28",
        f"broken: camera.fps differs across nodes: 30.0 on {FAST}; 15.0 on {SLOW}",
    )
    assert found["gain"] == (
        RULE_ACROSS_NODES,
        f"{path}:10:25",
        f"broken: {PLAIN}.gain * 10 >= {FAST}.camera.fps is false for "
        f"{PLAIN}.gain=2.0, {FAST}.camera.fps=30.0",
    )
    assert found["absent"] == (
        NOT_CHECKED,
        f"{path}:11:27",
        "not checked: /no_such_node not in this deployment",
    )


def test_rules_that_hold_exit_0(running: None, tmp_path: Path) -> None:
    rules = f"  - {{name: ordered, check: '{SLOW}.camera.fps * 2 == {FAST}.camera.fps'}}\n"
    done = run_audit("--manifest", str(manifest(tmp_path, rules)), SLOW, FAST)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "0 violation(s)" in done.stdout


def test_audit_compares_each_node_with_its_launch_file(running: None, tmp_path: Path) -> None:
    launch = tmp_path / "cameras.launch.xml"
    launch.write_text(
        "<launch>\n"
        f'  <node pkg="camera_driver" exec="camera_node" name="{SLOW[1:]}">\n'
        '    <param name="camera.fps" value="15.0"/>\n'
        "  </node>\n"
        f'  <node pkg="camera_driver" exec="camera_node" name="{FAST[1:]}">\n'
        '    <param name="camera.fps" value="20.0"/>\n'
        "  </node>\n"
        "</launch>\n",
        encoding="utf-8",
    )
    done = run_audit("--format", "json", "--launch", str(launch), SLOW, FAST)
    assert done.returncode == 0, done.stdout + done.stderr
    drift = [
        (f["node"], f["parameter"], f["expected"], f["actual"], f["detail"])
        for f in json.loads(done.stdout)["findings"]
        if f["kind"] == "drift-from-file"
    ]
    assert drift == [(FAST, "camera.fps", 20.0, 30.0, f"differs from {launch}:6:5")]


def test_audit_write_keeps_values_in_the_files_a_launch_file_names(
    running: None, tmp_path: Path
) -> None:
    params = tmp_path / "cams.yaml"
    params.write_text("/**:\n  ros__parameters:\n    camera:\n      fps: 20.0  # bench\n")
    launch = tmp_path / "cams.launch.xml"
    launch.write_text(
        f'<launch>\n  <node pkg="camera_driver" exec="camera_node" name="{FAST[1:]}">\n'
        f'    <param from="{params}"/>\n    <param name="camera.width" value="800"/>\n'
        "  </node>\n</launch>\n",
        encoding="utf-8",
    )
    done = run_audit("--launch", str(launch), "--write", FAST)
    assert done.returncode == 0, done.stdout + done.stderr
    assert params.read_text(encoding="utf-8") == (
        "/**:\n  ros__parameters:\n    camera:\n      fps: 30.0  # bench\n"
    )
    assert f"kept: {params}:4:12: {FAST}: camera.fps: 20.0 -> 30.0" in done.stderr
    assert (
        f"kept: not written, a launch file's own value: {launch}:4:5: {FAST}: camera.width: "
        "800 -> 640" in done.stderr
    )
