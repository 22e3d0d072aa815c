"""find_package(genparams) and genparams_generate_python in plain CMake: build, install, redo."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import genparams
from genparams.cmake import cmake_dir
from tests.build_support import EXAMPLES, run, tool_env

PYTHON_DIR = f"lib/python{sys.version_info.major}.{sys.version_info.minor}/site-packages"
INSTALLED = f"{PYTHON_DIR}/demo_pkg/config/camera_params.py"

pytestmark = pytest.mark.skipif(shutil.which("cmake") is None, reason="needs cmake")


@pytest.fixture
def project(tmp_path: Path) -> Path:
    source = tmp_path / "src"
    (source / "schema").mkdir(parents=True)
    shutil.copy(EXAMPLES / "camera_node" / "camera_driver.yaml", source / "schema")
    (source / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.17)\n"
        "project(demo_pkg NONE)\n"
        "find_package(genparams 0.1 REQUIRED)\n"
        "genparams_generate_python(camera_params schema/camera_driver.yaml\n"
        "  MODULE camera_params PACKAGE demo_pkg.config OUTPUT_VARIABLE generated)\n"
        'message(STATUS "generated: ${generated}")\n'
    )
    return tmp_path


def configure(project: Path, *options: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [
            "cmake",
            "-S",
            str(project / "src"),
            "-B",
            str(project / "build"),
            f"-DCMAKE_INSTALL_PREFIX={project / 'prefix'}",
            *options,
        ],
        env=tool_env(),
        capture_output=True,
        text=True,
        check=False,
    )


def build_and_install(project: Path) -> str:
    built = run(["cmake", "--build", project / "build"], project).stdout
    run(["cmake", "--install", project / "build"], project)
    return built


def test_generates_installs_and_regenerates_on_schema_change(project: Path) -> None:
    configured = configure(project, f"-Dgenparams_DIR={cmake_dir()}")
    assert configured.returncode == 0, configured.stderr
    build_tree_file = project / "build/genparams/camera_params/demo_pkg/config/camera_params.py"
    assert f"generated: {build_tree_file}" in configured.stdout

    first = build_and_install(project)
    assert "genparams: generating demo_pkg.config.camera_params" in first
    schema = project / "src" / "schema" / "camera_driver.yaml"
    installed = project / "prefix" / INSTALLED
    assert installed.read_text() == genparams.generate(schema)

    # Nothing changed: nothing is regenerated.
    assert "genparams: generating" not in build_and_install(project)

    # CMake's install skips a file whose time matches to the second; age the installed copy
    # as if this build happened a while ago, rather than sleeping.
    stamp = installed.stat().st_mtime - 60
    os.utime(installed, (stamp, stamp))
    schema.write_text(schema.read_text().replace("default: 30.0", "default: 25.0"))
    again = build_and_install(project)
    assert "genparams: generating demo_pkg.config.camera_params" in again
    assert installed.read_text() == genparams.generate(schema)
    assert '("camera.fps", 25.0, ' in installed.read_text()


def test_bad_schema_fails_the_build_and_keeps_the_previous_module(project: Path) -> None:
    assert configure(project, f"-Dgenparams_DIR={cmake_dir()}").returncode == 0
    build_and_install(project)
    built = project / "build/genparams/camera_params/demo_pkg/config/camera_params.py"
    before = built.read_bytes()
    schema = project / "src" / "schema" / "camera_driver.yaml"
    schema.write_text(schema.read_text().replace("default: 640", "defualt: 640"))
    failed = subprocess.run(
        ["cmake", "--build", str(project / "build")],
        env=tool_env(),
        capture_output=True,
        text=True,
        check=False,
    )
    assert failed.returncode != 0
    assert f"{schema}:17:" in failed.stderr
    assert "parameters.camera.width.defualt: unknown key 'defualt'" in failed.stderr
    assert built.read_bytes() == before


def test_too_new_version_request_is_refused(project: Path) -> None:
    cmake_lists = project / "src" / "CMakeLists.txt"
    cmake_lists.write_text(
        cmake_lists.read_text().replace("find_package(genparams 0.1", "find_package(genparams 9.0")
    )
    configured = configure(project, f"-Dgenparams_DIR={cmake_dir()}")
    assert configured.returncode != 0
    assert "genparams" in configured.stderr and genparams.__version__ in configured.stderr


def test_cmake_dir_is_printed_by_the_command_and_the_module() -> None:
    by_command = run([sys.executable, "-m", "genparams", "cmake-dir"], EXAMPLES).stdout
    by_module = run([sys.executable, "-m", "genparams.cmake"], EXAMPLES).stdout
    assert by_command == by_module == f"{cmake_dir()}\n"
    assert (cmake_dir() / "genparamsConfig.cmake").is_file()
    assert (cmake_dir() / "genparamsConfigVersion.cmake").is_file()
