"""The pre-commit hooks of .pre-commit-hooks.yaml, installed and run by real pre-commit."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from pre_commit.clientlib import load_manifest

from genparams.cli import main
from tests.build_support import EXAMPLES, copy_repository, run, tool_env
from tests.support import ROOT

GIT_IDENTITY = {
    "GIT_AUTHOR_NAME": "genparams tests",
    "GIT_AUTHOR_EMAIL": "tests@example.com",
    "GIT_COMMITTER_NAME": "genparams tests",
    "GIT_COMMITTER_EMAIL": "tests@example.com",
}


def test_manifest_is_valid_for_pre_commit() -> None:
    hooks = {hook["id"]: hook for hook in load_manifest(str(ROOT / ".pre-commit-hooks.yaml"))}
    assert hooks["genparams-check"]["entry"] == "genparams generate --check"
    assert hooks["genparams-check"]["pass_filenames"] is False
    assert hooks["genparams-check-params"]["entry"] == "genparams check-params"
    assert {hook["language"] for hook in hooks.values()} == {"python"}


GOOD_PARAMS = "/**:\n  ros__parameters:\n    serial: ABCD1234\n"
BAD_PARAMS = "/**:\n  ros__parameters:\n    serial: ABCD1234\n    camera.encoding: yuv422\n"


def test_check_params_takes_the_several_files_pre_commit_passes(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    good, bad = tmp_path / "good.yaml", tmp_path / "bad.yaml"
    good.write_text(GOOD_PARAMS)
    bad.write_text(BAD_PARAMS)
    schema = str(EXAMPLES / "camera_node" / "camera_driver.yaml")
    assert main(["check-params", schema, str(good), str(good)]) == 0
    assert main(["check-params", schema, str(good), str(bad), str(good)]) == 1
    assert capsys.readouterr().out == (
        f"{bad}:4:22: camera.encoding: must be one of ['rgb8', 'mono8', 'bgr8'] (one_of), "
        "got 'yuv422'\n"
    )
    assert main(["check-params", schema, str(bad), str(tmp_path / "missing.yaml")]) == 2


@pytest.mark.slow
def test_check_hook_passes_on_fresh_modules_and_fails_with_diff(tmp_path: Path) -> None:
    env = tool_env(PRE_COMMIT_HOME=str(tmp_path / "cache"), **GIT_IDENTITY)
    hooks_repo = copy_repository(tmp_path / "genparams")
    run(["git", "init", "--quiet"], hooks_repo, env)
    run(["git", "add", "--all"], hooks_repo, env)
    run(["git", "commit", "--quiet", "--message", "genparams"], hooks_repo, env)
    revision = run(["git", "rev-parse", "HEAD"], hooks_repo, env).stdout.strip()

    project = tmp_path / "project"
    shutil.copytree(EXAMPLES / "camera_node", project, ignore=shutil.ignore_patterns("__pycache__"))
    (project / "params").mkdir()
    (project / "params" / "good.yaml").write_text(GOOD_PARAMS)
    (project / ".pre-commit-config.yaml").write_text(
        f"repos:\n- repo: {hooks_repo}\n  rev: {revision}\n  hooks:\n"
        "  - id: genparams-check\n"
        "  - id: genparams-check-params\n"
        "    args: [camera_driver.yaml]\n"
        "    files: ^params/\n"
    )
    run(["git", "init", "--quiet"], project, env)
    run(["git", "add", "--all"], project, env)

    fresh = run(["pre-commit", "run", "--all-files"], project, env)
    assert "genparams modules are up to date" in fresh.stdout
    assert "genparams params files match their schema" in fresh.stdout
    assert "Failed" not in fresh.stdout

    schema = project / "camera_driver.yaml"
    schema.write_text(schema.read_text().replace("default: 640", "default: 800"))
    (project / "params" / "bad.yaml").write_text(BAD_PARAMS)
    run(["git", "add", "--all"], project, env)
    stale = subprocess.run(
        ["pre-commit", "run", "--all-files"],
        cwd=project,
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    assert stale.returncode == 1
    assert "Failed" in stale.stdout
    assert "--- camera_node/camera_driver_params.py (on disk)" in stale.stdout
    assert '+            ("camera.width", 800, ' in stale.stdout
    assert "params/bad.yaml:4:22: camera.encoding: must be one of" in stale.stdout
    assert "params/good.yaml" not in stale.stdout
