"""Mapped parameters and renames on a real node, in one process.

Run from the repository root (make keeps DDS discovery on this machine and picks a
ROS_DOMAIN_ID): make demo-arm
"""

from __future__ import annotations

import importlib.util
import sys
import tempfile
from pathlib import Path
from types import ModuleType
from typing import Any

import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter

import genparams

HERE = Path(__file__).resolve().parent


def generated_module(directory: Path) -> ModuleType:
    path = directory / "arm_params.py"
    path.write_text(genparams.generate(HERE / "arm.yaml"), encoding="utf-8")
    spec = importlib.util.spec_from_file_location("arm_params", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["arm_params"] = module
    spec.loader.exec_module(module)
    return module


def show(cfg: Any, node: Node) -> None:  # the module is generated at run time: no static types
    gains = {key: (entry.p, entry.i) for key, entry in cfg.gains.items()}
    names = sorted(n for n in node.get_parameters_by_prefix("gains"))
    print(f"  cfg.gains = {gains}")
    print(f"  node parameters under gains: {names}")


def main() -> int:
    rclpy.init()
    with tempfile.TemporaryDirectory() as directory:
        arm = generated_module(Path(directory))
        node = Node("arm", cli_args=["--ros-args", "--params-file", str(HERE / "params.yaml")])
        cfg = arm.ArmParams.declare(node)
        print(f"max_speed = {cfg.max_speed} (given as speed_limit in params.yaml)")
        show(cfg, node)

        print("set joints := [shoulder, wrist, left-arm]")
        node.set_parameters([Parameter("joints", value=["shoulder", "wrist", "left-arm"])])
        show(cfg, node)

        (result,) = node.set_parameters([Parameter("joints", value=["left.arm"])])
        print(f"set joints := [left.arm] -> rejected: {result.reason}")

        node.set_parameters([Parameter("speed_limit", value=0.5)])
        speeds = [node.get_parameter(n).value for n in ("max_speed", "speed_limit")]
        print(f"set speed_limit := 0.5 -> max_speed, speed_limit = {speeds}; cfg: {cfg.max_speed}")
        node.destroy_node()
    rclpy.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
