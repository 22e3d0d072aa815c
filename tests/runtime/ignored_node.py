"""A node started as ROS starts one, to show what rclpy ignores: ``python -m
tests.runtime.ignored_node NAMESPACE NAME PREFIX WARN --ros-args ...``. It declares the
camera example's class under PREFIX ("" for the root; WARN "off" passes
``warn_unknown=False``), prints "declared", and exits."""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

import rclpy
from rclpy.node import Node

import genparams
from tests.support import ROOT, import_file

SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"


def main(argv: list[str]) -> int:
    namespace, name, prefix, warn = argv[:4]
    module_path = Path(tempfile.mkdtemp(prefix="genparams-ignored-")) / "camera_driver_params.py"
    module_path.write_text(genparams.generate(SCHEMA), encoding="utf-8")
    params = import_file(module_path).CameraDriverParams
    rclpy.init()  # sys.argv: the global arguments, as `ros2 run` and launch give them
    try:
        node = Node(name, namespace=namespace)
        params.declare(node, prefix, warn_unknown=warn != "off")
        print("declared", flush=True)
        node.destroy_node()
    finally:
        rclpy.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
