"""genparams as users install it: the wheel's contents, a fresh venv, a lean runtime.

The fresh venv holds the wheel without extras (`pip install genparams`), its dependencies
pinned by requirements/dev.txt: the runtime and code generation, no web stack.
"""

from __future__ import annotations

import subprocess
import sys
import time
import zipfile
from pathlib import Path

import pytest

import genparams
from tests.build_support import EXAMPLES, VENV_BIN, build_wheel, copy_repository, run
from tests.support import ROOT

SCHEMA = EXAMPLES / "camera_node" / "camera_driver.yaml"
# rclpy itself imports yaml, so first load rclpy's modules, then see what the generated module
# and genparams' runtime add while a real node declares the class and a value is read: none
# of the generator's stages nor its dependencies, and nothing of the tuning page's web stack.
RUNTIME_PROBE = """
import sys
import rclpy, rclpy.node, rclpy.parameter
before = set(sys.modules)
sys.path.insert(0, sys.argv[1])
from camera_driver_params import CameraDriverParams
rclpy.init()
serial = rclpy.parameter.Parameter("serial", value="ABCD1234")
node = rclpy.node.Node("lean_runtime_probe", parameter_overrides=[serial])
params = CameraDriverParams.declare(node)
if (params.camera.fps, params.serial) != (30.0, "ABCD1234"):
    sys.exit("the generated module does not work")
node.destroy_node()
rclpy.shutdown()
generator = ("jinja2", "jsonschema", "yaml", "genparams.outputs.render", "genparams.schema.loader",
             "genparams.schema.schema_check", "genparams.schema.builder", "genparams.api")
added = set(sys.modules) - before
print(sorted(m for m in added if m.split(".")[0] in generator or m in generator))
heavy = ("jinja2", "jsonschema", "starlette", "uvicorn")
print(sorted(m for m in sys.modules if m.split(".")[0] in heavy))
"""


def runtime_imports(python: Path | str, tmp_path: Path, module: str | None = None) -> str:
    """The probe's report on ``module`` (the camera example's generated module by default)."""
    (tmp_path / "camera_driver_params.py").write_text(module or genparams.generate(SCHEMA))
    return run([python, "-c", RUNTIME_PROBE, tmp_path], tmp_path).stdout


def test_generated_module_imports_no_generator_dependency(tmp_path: Path) -> None:
    assert runtime_imports(sys.executable, tmp_path) == "[]\n[]\n"


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    source = copy_repository(tmp_path_factory.mktemp("genparams-src"))
    return build_wheel(source, tmp_path_factory.mktemp("dist"), isolated=False)


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
    """A fresh venv with the wheel installed without extras, its dependencies from the lock."""
    folder = tmp_path_factory.mktemp("fresh") / "venv"
    started = time.monotonic()
    run([sys.executable, "-m", "venv", "--without-pip", folder], folder.parent)
    # uv comes with the development environment (requirements/uv.txt); its cache keeps it quick.
    # No index option: the machine's own client configuration decides where packages come from.
    python = folder / "bin" / "python"
    install: list[str | Path] = [VENV_BIN / "uv", "pip", "install", "--quiet", "--python", python]
    run([*install, "--constraint", ROOT / "requirements" / "dev.txt", wheel], folder)
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
    # The module it generated, declared on a real node there, a value read back.
    assert runtime_imports(venv / "bin" / "python", tmp_path, generated) == "[]\n[]\n"
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


@pytest.mark.slow
def test_lean_install_has_no_web_stack_and_tune_says_what_to_install(
    venv: Path, tmp_path: Path
) -> None:
    missing = run(
        [venv / "bin" / "python", "-c", "import importlib.util as u;"
         "print([m for m in ('starlette', 'uvicorn') if u.find_spec(m) is None])"],
        tmp_path,
    ).stdout  # fmt: skip
    assert missing == "['starlette', 'uvicorn']\n"
    tune = subprocess.run(
        [venv / "bin" / "genparams", "tune"], cwd=tmp_path, capture_output=True, text=True
    )
    assert (tune.returncode, tune.stdout) == (2, "")
    assert tune.stderr.count("\n") == 1 and "pip install 'genparams[tune]'" in tune.stderr
    # Every other command (audit too) imports without it: only the page's server needs it.
    modules = run(
        [venv / "bin" / "python", "-c", "import pkgutil, importlib, genparams;"
         "names = [m.name for m in pkgutil.walk_packages(genparams.__path__, 'genparams.')];"
         "web = {'genparams.tune.' + m for m in"
         " ('app', 'server', 'events', 'json_response', 'security', 'connections', 'keep')};"
         "[importlib.import_module(n) for n in names if n not in web and '__main__' not in n];"
         "print(len(names))"],
        tmp_path,
    ).stdout  # fmt: skip
    assert int(modules) > 50


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
