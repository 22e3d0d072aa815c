"""genparams as users install it: the wheel's contents, a fresh venv, a lean runtime."""

from __future__ import annotations

import subprocess
import sys
import time
import zipfile
from pathlib import Path

import pytest

import genparams
from tests.build_support import EXAMPLES, build_wheel, copy_repository, run

SCHEMA = EXAMPLES / "camera_node" / "camera_driver.yaml"
# rclpy itself imports yaml, so first load rclpy's modules, then see what the generated module
# and genparams' runtime add: none of the generator's stages nor its dependencies.
RUNTIME_PROBE = """
import sys
import rclpy.node, rclpy.parameter
before = set(sys.modules)
sys.path.insert(0, sys.argv[1])
from camera_driver_params import CameraDriverParams
import genparams.runtime.binding
if CameraDriverParams.defaults({"serial": "ABCD1234"}).camera.fps != 30.0:
    sys.exit("the generated module does not work")
generator = ("jinja2", "jsonschema", "yaml", "genparams.outputs.render", "genparams.schema.loader",
             "genparams.schema.schema_check", "genparams.schema.builder", "genparams.api")
added = set(sys.modules) - before
print(sorted(m for m in added if m.split(".")[0] in generator or m in generator))
print(sorted(m for m in ("jinja2", "jsonschema") if m in sys.modules))
"""


def runtime_imports(python: Path | str, tmp_path: Path) -> str:
    (tmp_path / "camera_driver_params.py").write_text(genparams.generate(SCHEMA))
    return run([python, "-c", RUNTIME_PROBE, tmp_path], tmp_path).stdout


def test_generated_module_imports_no_generator_dependency(tmp_path: Path) -> None:
    assert runtime_imports(sys.executable, tmp_path) == "[]\n[]\n"


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    source = copy_repository(tmp_path_factory.mktemp("genparams-src"))
    return build_wheel(source, tmp_path_factory.mktemp("dist"))


@pytest.mark.slow
def test_wheel_ships_schemas_templates_and_cmake_package(wheel: Path) -> None:
    with zipfile.ZipFile(wheel) as archive:
        names = set(archive.namelist())
    assert {
        "genparams/schemas/genparams.schema.json",
        "genparams/templates/module.py.j2",
        "genparams/cmake/genparamsConfig.cmake",
        "genparams/cmake/genparamsConfigVersion.cmake",
        "genparams/setuptools.py",
        "genparams/py.typed",
    } <= names
    assert not any(name.startswith(("tests/", "examples/")) for name in names)


@pytest.fixture(scope="module")
def venv(wheel: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A fresh venv with the wheel installed, dependencies (rclpy and all) included."""
    folder = tmp_path_factory.mktemp("fresh") / "venv"
    started = time.monotonic()
    run([sys.executable, "-m", "venv", folder], folder.parent)
    run([folder / "bin" / "python", "-m", "pip", "install", "--quiet", wheel], folder.parent)
    print(f"fresh venv with the wheel and its dependencies: {time.monotonic() - started:.1f} s")
    return folder


@pytest.mark.slow
def test_fresh_venv_from_the_wheel_generates_and_runs(venv: Path, tmp_path: Path) -> None:
    site = run(
        [venv / "bin" / "python", "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
        tmp_path,
    ).stdout.strip()

    version = run([venv / "bin" / "genparams", "--version"], tmp_path).stdout
    assert version == f"genparams {genparams.__version__}\n"
    # Outside the checkout, from the installed copy of schemas/ and templates/.
    generated = run([venv / "bin" / "genparams", "generate", SCHEMA], tmp_path).stdout
    assert generated == genparams.generate(SCHEMA)
    located = run(
        [
            venv / "bin" / "python",
            "-c",
            "import genparams, genparams.schema.resources as r;"
            "print(genparams.__file__); print(r.resource_dir('templates'));"
            "print(r.resource_dir('schemas'))",
        ],
        tmp_path,
    ).stdout.split()
    assert all(path.startswith(site) for path in located), located
    cmake = run([venv / "bin" / "python", "-m", "genparams.cmake"], tmp_path).stdout.strip()
    assert cmake == f"{site}/genparams/cmake"
    assert runtime_imports(venv / "bin" / "python", tmp_path) == "[]\n[]\n"


@pytest.mark.slow
def test_installed_cmake_package_finds_its_own_command(venv: Path, tmp_path: Path) -> None:
    """find_package(genparams) finds the genparams command of its own venv, PATH or not."""
    cmake = run([venv / "bin" / "python", "-m", "genparams.cmake"], tmp_path).stdout.strip()
    source = tmp_path / "src"
    source.mkdir()
    (source / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.17)\nproject(probe NONE)\n"
        "find_package(genparams REQUIRED)\n"
        'message(STATUS "command: ${GENPARAMS_EXECUTABLE}")\n'
    )
    configured = subprocess.run(
        ["cmake", "-S", str(source), "-B", str(tmp_path / "build"), f"-Dgenparams_DIR={cmake}"],
        env={"PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        check=False,
    )
    assert configured.returncode == 0, configured.stderr
    assert f"command: {venv}/bin/genparams" in configured.stdout
