"""Real colcon builds of the ROS example packages; their nodes run from the install space.

ament_python (examples/ros/lidar_filter, flat; examples/ros/gripper_driver, src/ layout)
through genparams.setuptools, and ament_cmake (examples/ros/battery_monitor) through
find_package(genparams), in every install layout colcon offers.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

import genparams
from genparams.cmake import cmake_dir
from tests.build_support import (
    copy_example,
    node_process,
    run,
    space_free_tools,
    tool_env,
    tree_snapshot,
    wait_for_node,
)
from tests.support import RosHarness, unique_name

pytestmark = pytest.mark.slow

LAYOUTS = {
    "isolated": [],
    "symlink": ["--symlink-install"],
    "merge": ["--merge-install"],
    "symlink-merge": ["--symlink-install", "--merge-install"],
}
# package -> (generated module, its path in the package's sources, its schema)
PYTHON_MODULES = {
    "lidar_filter": (
        "lidar_filter.lidar_filter_params",
        "lidar_filter/lidar_filter_params.py",
        "config/lidar_filter.yaml",
    ),
    "gripper_driver": (
        "gripper_driver.gripper_params",
        "src/gripper_driver/gripper_params.py",
        "config/gripper.yaml",
    ),
}


def workspace_with(tmp_path: Path, *packages: str) -> Path:
    workspace = tmp_path / "ws"
    (workspace / "src").mkdir(parents=True)
    for package in packages:
        copy_example(f"ros/{package}", workspace / "src")
    return workspace


def colcon_build(workspace: Path, *options: str) -> str:
    env = tool_env(COLCON_HOME=str(workspace / ".colcon"))
    # The interpreter colcon writes into install/setup.sh, by a path without spaces.
    env["PATH"] = f"{space_free_tools(workspace.parent)}{os.pathsep}{env['PATH']}"
    completed = run(
        ["colcon", "build", "--base-paths", "src", "--event-handlers", "console_direct+", *options],
        workspace,
        env,
    )
    return completed.stdout


def installed_python(workspace: Path, code: str) -> str:
    """Run Python code in the environment of the workspace's install/setup.sh."""
    return run(
        ["sh", "-c", '. ./install/setup.sh && exec python -c "$0"', code], workspace
    ).stdout.strip()


def script(workspace: Path, package: str, name: str, merged: bool) -> str:
    base = "install" if merged else f"install/{package}"
    return f"{base}/lib/{package}/{name}"


@pytest.mark.parametrize("options", LAYOUTS.values(), ids=LAYOUTS.keys())
def test_ament_python_generates_at_build_time(
    tmp_path: Path, ros: RosHarness, options: list[str]
) -> None:
    workspace = workspace_with(tmp_path, *PYTHON_MODULES)
    sources = tree_snapshot(workspace / "src")
    output = colcon_build(workspace, *options)
    editable = "--symlink-install" in options
    merged = "--merge-install" in options

    for package, (module, source_path, schema) in PYTHON_MODULES.items():
        in_source = workspace / "src" / package / source_path
        imported = Path(installed_python(workspace, f"import {module} as m; print(m.__file__)"))
        if editable:
            # Python imports the package from the sources, so the module is generated there.
            assert imported.resolve() == in_source
            assert f"-> {in_source} (in place: editable build)" in output
        else:
            assert imported.is_relative_to(workspace / "install")
            assert not in_source.exists()
        assert imported.read_text() == genparams.generate(workspace / "src" / package / schema)
    # Only an editable build writes into the sources, and only the generated modules.
    in_place = {f"{package}/{path}" for package, (_, path, _) in PYTHON_MODULES.items()}
    changed = set(tree_snapshot(workspace / "src")) - set(sources)
    assert changed == (in_place if editable else set())

    lidar = unique_name("lidar")
    with node_process(
        workspace,
        script(workspace, "lidar_filter", "filter_node", merged),
        "-r",
        f"__node:={lidar}",
        "-p",
        "limits.max:=12.5",
    ) as process:
        client = wait_for_node(ros, process, f"/{lidar}")
        assert client.get("limits.max", "median_window") == [12.5, 5]
        (rejected,) = client.set(Parameter("limits.max", value=150.0))
        assert not rejected.successful
        assert "limits.max" in rejected.reason and "must be within" in rejected.reason

    gripper = unique_name("gripper")
    with node_process(
        workspace,
        script(workspace, "gripper_driver", "gripper_node", merged),
        "-r",
        f"__node:={gripper}",
        "-p",
        "grip.force:=35.0",
    ) as process:
        client = wait_for_node(ros, process, f"/{gripper}")
        assert client.get("grip.force", "fingers") == [35.0, ["left", "right"]]
        (rejected,) = client.set(Parameter("fingers", value=["left", "left"]))
        assert not rejected.successful
        assert "fingers" in rejected.reason

    # An edited schema reaches the install space with the next build.
    edited = workspace / "src" / "lidar_filter" / "config" / "lidar_filter.yaml"
    edited.write_text(edited.read_text().replace("default: 0.1", "default: 0.25"))
    colcon_build(workspace, *options)
    rebuilt = installed_python(
        workspace,
        "from lidar_filter.lidar_filter_params import LidarFilterParams as P;"
        "print(P.defaults().limits.min)",
    )
    assert rebuilt == "0.25"


@pytest.mark.parametrize("options", [[], ["--symlink-install", "--merge-install"]])
def test_ament_cmake_generates_at_build_time(
    tmp_path: Path, ros: RosHarness, options: list[str]
) -> None:
    workspace = workspace_with(tmp_path, "battery_monitor")
    sources = tree_snapshot(workspace / "src")
    cmake_args = ["--cmake-args", f"-Dgenparams_DIR={cmake_dir()}"]
    output = colcon_build(workspace, *options, *cmake_args)
    assert "genparams: generating battery_monitor.battery_monitor_params" in output
    merged = "--merge-install" in options
    imported = Path(
        installed_python(
            workspace, "import battery_monitor.battery_monitor_params as m; print(m.__file__)"
        )
    )
    assert imported.is_relative_to(workspace / "install")
    schema = workspace / "src" / "battery_monitor" / "config" / "battery_monitor.yaml"
    assert imported.read_text() == genparams.generate(schema)
    assert tree_snapshot(workspace / "src") == sources

    monitor = unique_name("battery")
    with node_process(
        workspace,
        script(workspace, "battery_monitor", "battery_monitor_node", merged),
        "-r",
        f"__node:={monitor}",
        "-p",
        "cells:=6",
    ) as process:
        client = wait_for_node(ros, process, f"/{monitor}")
        assert client.get("cells", "thresholds.warn") == [6, 3.5]
        (rejected,) = client.set(Parameter("thresholds.warn", value=5.0))
        assert not rejected.successful

    schema.write_text(schema.read_text().replace("default: 3.5", "default: 3.6"))
    colcon_build(workspace, *options, *cmake_args)
    rebuilt = installed_python(
        workspace,
        "from battery_monitor.battery_monitor_params import BatteryMonitorParams as P;"
        "print(P.defaults().thresholds.warn)",
    )
    assert rebuilt == "3.6"
