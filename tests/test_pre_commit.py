"""The pre-commit hooks of .pre-commit-hooks.yaml, installed and run by real pre-commit."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from pre_commit.clientlib import load_manifest

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
    (project / ".pre-commit-config.yaml").write_text(
        f"repos:\n- repo: {hooks_repo}\n  rev: {revision}\n  hooks:\n  - id: genparams-check\n"
    )
    run(["git", "init", "--quiet"], project, env)
    run(["git", "add", "--all"], project, env)

    fresh = run(["pre-commit", "run", "--all-files", "genparams-check"], project, env)
    assert "genparams modules are up to date" in fresh.stdout and "Passed" in fresh.stdout

    schema = project / "camera_driver.yaml"
    schema.write_text(schema.read_text().replace("default: 640", "default: 800"))
    run(["git", "add", "--all"], project, env)
    stale = subprocess.run(
        ["pre-commit", "run", "--all-files", "genparams-check"],
        cwd=project,
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    assert stale.returncode == 1
    assert "Failed" in stale.stdout
    assert "--- camera_node/camera_driver_params.py (on disk)" in stale.stdout
    assert "+                default=800," in stale.stdout
