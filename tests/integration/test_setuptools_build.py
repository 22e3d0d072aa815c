"""genparams.setuptools outside colcon: pip builds a wheel, an editable install, clear errors."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

import genparams
from tests.build_support import copy_example, run, tool_env, tree_snapshot

PIP_OFFLINE = ["--no-build-isolation", "--no-deps", "--no-index", "--quiet"]


def test_wheel_holds_generated_module_and_sources_stay_untouched(tmp_path: Path) -> None:
    package = copy_example("ros/gripper_driver", tmp_path)  # a src/ layout
    sources = tree_snapshot(package / "src")
    run([sys.executable, "-m", "pip", "wheel", *PIP_OFFLINE, "-w", tmp_path / "dist", "."], package)
    (wheel,) = (tmp_path / "dist").glob("gripper_driver-*.whl")
    with zipfile.ZipFile(wheel) as archive:
        generated = archive.read("gripper_driver/gripper_params.py").decode()
        record = archive.read("gripper_driver-0.1.0.dist-info/RECORD").decode()
    assert generated == genparams.generate(package / "config" / "gripper.yaml")
    assert "gripper_driver/gripper_params.py," in record
    # Built in the build folder only: src/ has no generated file (just setuptools' egg-info).
    after = {k: v for k, v in tree_snapshot(package / "src").items() if ".egg-info" not in k}
    assert after == sources


def test_editable_install_generates_in_place(tmp_path: Path) -> None:
    package = copy_example("ros/lidar_filter", tmp_path)
    prefix = tmp_path / "prefix"
    run(
        [sys.executable, "-m", "pip", "install", *PIP_OFFLINE, "--prefix", prefix, "-e", "."],
        package,
    )
    in_place = package / "lidar_filter" / "lidar_filter_params.py"
    assert in_place.read_text() == genparams.generate(package / "config" / "lidar_filter.yaml")
    (site,) = prefix.glob("lib/python*/site-packages")
    shown = run(
        [
            sys.executable,
            "-c",
            "import site, sys; site.addsitedir(sys.argv[1]);"
            "import lidar_filter.lidar_filter_params as m;"
            "print(m.__file__); print(m.LidarFilterParams.defaults().limits.max)",
            site,
        ],
        tmp_path,
    ).stdout.split()
    assert shown == [str(in_place), "30.0"]


def write_package(folder: Path, schema_text: str, output: str) -> Path:
    (folder / "pkg").mkdir(parents=True)
    (folder / "pkg" / "__init__.py").write_text("")
    (folder / "params.yaml").write_text(schema_text)
    (folder / "pyproject.toml").write_text(
        f'[[tool.genparams.modules]]\nschema = "params.yaml"\noutput = "{output}"\n'
    )
    (folder / "setup.py").write_text(
        "from setuptools import setup\n"
        "from genparams.setuptools import build_py, develop\n"
        'setup(name="pkg", version="1.0", packages=["pkg"],\n'
        '      cmdclass={"build_py": build_py, "develop": develop})\n'
    )
    return folder


GOOD_SCHEMA = "genparams: 1\nname: demo\nparameters:\n  rate: {type: double, default: 1.0}\n"


def setup_py_build(package: Path) -> tuple[int, str]:
    completed = subprocess.run(
        [sys.executable, "setup.py", "build", "--build-base", "out"],
        cwd=package,
        env=tool_env(),
        capture_output=True,
        text=True,
        check=False,
    )
    return completed.returncode, completed.stdout + completed.stderr


def test_setup_py_build_writes_module_into_build_lib(tmp_path: Path) -> None:
    package = write_package(tmp_path / "p", GOOD_SCHEMA, "pkg/demo_params.py")
    code, output = setup_py_build(package)
    assert code == 0, output
    built = package / "out" / "lib" / "pkg" / "demo_params.py"
    assert built.read_text() == genparams.generate(package / "params.yaml")
    assert "genparams: params.yaml -> out/lib/pkg/demo_params.py" in output
    assert not (package / "pkg" / "demo_params.py").exists()


def test_output_outside_every_package_is_a_clear_error(tmp_path: Path) -> None:
    package = write_package(tmp_path / "p", GOOD_SCHEMA, "elsewhere/demo_params.py")
    code, output = setup_py_build(package)
    assert code != 0
    assert (
        "error: genparams: output 'elsewhere/demo_params.py' of 'params.yaml' is not inside "
        "a package this setup() builds (packages: ['pkg'])"
    ) in output


@pytest.mark.parametrize(
    ("schema_text", "expected"),
    [
        (
            "genparams: 1\nname: demo\nparameters:\n  rate: {type: double, defualt: 1.0}\n",
            "params.yaml:4:24: parameters.rate.defualt: unknown key 'defualt'",
        ),
        (
            "genparams: 1\nname: demo\nparameters:\n  rate: {type: double, default: fast}\n",
            "params.yaml:4:33: parameters.rate.default:",
        ),
    ],
)
def test_bad_schema_fails_the_build_naming_the_place(
    tmp_path: Path, schema_text: str, expected: str
) -> None:
    package = write_package(tmp_path / "p", schema_text, "pkg/demo_params.py")
    code, output = setup_py_build(package)
    assert code != 0
    assert "genparams: invalid schema" in output
    assert expected in output
    assert not (package / "out" / "lib" / "pkg" / "demo_params.py").exists()


def test_missing_genparams_table_is_a_clear_error(tmp_path: Path) -> None:
    package = write_package(tmp_path / "p", GOOD_SCHEMA, "pkg/demo_params.py")
    (package / "pyproject.toml").write_text("")
    code, output = setup_py_build(package)
    assert code != 0
    assert f"genparams: {package / 'pyproject.toml'}: no [tool.genparams] table" in output


def test_pyproject_only_package_generates_while_pip_builds_the_wheel(tmp_path: Path) -> None:
    package = tmp_path / "plain"
    (package / "src" / "plain").mkdir(parents=True)
    (package / "src" / "plain" / "__init__.py").write_text("")
    (package / "params.yaml").write_text(GOOD_SCHEMA)
    (package / "pyproject.toml").write_text(
        '[build-system]\nrequires = ["setuptools>=61", "genparams"]\n'
        'build-backend = "setuptools.build_meta"\n\n'
        '[project]\nname = "plain"\nversion = "1.0"\n\n'
        '[tool.setuptools.cmdclass]\nbuild_py = "genparams.setuptools.build_py"\n\n'
        '[[tool.genparams.modules]]\nschema = "params.yaml"\noutput = "src/plain/demo_params.py"\n'
    )
    run([sys.executable, "-m", "pip", "wheel", *PIP_OFFLINE, "-w", tmp_path / "dist", "."], package)
    (wheel,) = (tmp_path / "dist").glob("plain-*.whl")
    with zipfile.ZipFile(wheel) as archive:
        generated = archive.read("plain/demo_params.py").decode()
    assert generated == genparams.generate(package / "params.yaml")
    assert not (package / "src" / "plain" / "demo_params.py").exists()
