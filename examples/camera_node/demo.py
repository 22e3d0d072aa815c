"""Start the camera node in its own process and tune it through the parameter services.

Run with `make demo`. Prints what a `ros2 param` user would see.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter, parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from rclpy.task import Future

HERE = Path(__file__).resolve().parent
TARGET = "/camera_driver"


def call(node: Node, future: Future) -> object:
    rclpy.spin_until_future_complete(node, future, timeout_sec=10.0)
    if not future.done():
        raise TimeoutError("no answer from the camera node")
    return future.result()


def wait_until_answering(node: Node, client: AsyncParameterClient) -> bool:
    """Services can be discovered before their replies reach us: ask until one arrives."""
    for _ in range(10):
        future = client.get_parameters(["camera.fps"])
        rclpy.spin_until_future_complete(node, future, timeout_sec=3.0)
        if future.done():
            return True
        future.cancel()
    return False


def main() -> int:
    env = dict(os.environ, PYTHONPATH=f"{HERE}{os.pathsep}{os.environ.get('PYTHONPATH', '')}")
    print("$ python -m camera_node.node --ros-args -p serial:=CAM00042 -p camera.fps:=60.0")
    camera = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "camera_node.node",
            "--ros-args",
            "-p",
            "serial:=CAM00042",
            "-p",
            "camera.fps:=60.0",
        ],
        env=env,
    )
    rclpy.init()
    client_node = Node("demo_client")
    try:
        client = AsyncParameterClient(client_node, TARGET)
        if not client.wait_for_services(timeout_sec=15.0) or not wait_until_answering(
            client_node, client
        ):
            print("camera node did not come up", file=sys.stderr)
            return 1
        names = ["camera.fps", "camera.encoding", "serial"]
        values = call(client_node, client.get_parameters(names)).values  # type: ignore[attr-defined]
        for name, value in zip(names, values, strict=True):
            print(f"get {name} -> {parameter_value_to_python(value)!r}")
        for parameter in (
            Parameter("camera.fps", value=15.0),
            Parameter("camera.fps", value=500.0),
            Parameter("camera.encoding", value="yuv422"),
            Parameter("robot_name", value="renamed"),
        ):
            response = call(client_node, client.set_parameters([parameter]))
            (result,) = response.results  # type: ignore[attr-defined]
            verdict = "accepted" if result.successful else f"rejected: {result.reason}"
            print(f"set {parameter.name} = {parameter.value!r} -> {verdict}")
        atomic = [Parameter("camera.width", value=1280), Parameter("camera.height", value=-1)]
        response = call(client_node, client.set_parameters_atomically(atomic))
        result = response.result  # type: ignore[attr-defined]
        verdict = "accepted" if result.successful else f"rejected: {result.reason}"
        print(f"set atomically width=1280, height=-1 -> {verdict}")
        values = call(client_node, client.get_parameters(names)).values  # type: ignore[attr-defined]
        print(
            "final:", {n: parameter_value_to_python(v) for n, v in zip(names, values, strict=True)}
        )

        print("\n$ python -m camera_node.node --ros-args -p camera.fps:=0.1 -p camera.width:=big")
        bad = subprocess.run(
            [
                sys.executable,
                "-m",
                "camera_node.node",
                "--ros-args",
                "-r",
                "__node:=camera_bad",
                "-p",
                "camera.fps:=0.1",
                "-p",
                "camera.width:=big",
            ],
            env=env,
            capture_output=True,
            text=True,
            timeout=60,
        )
        print(bad.stderr.strip())
        print(f"(exit code {bad.returncode})")
        return 0
    finally:
        client_node.destroy_node()
        rclpy.shutdown()
        camera.terminate()
        try:
            camera.wait(timeout=30)
        except subprocess.TimeoutExpired:  # never leave the node running behind the demo
            camera.kill()
            camera.wait()


if __name__ == "__main__":
    sys.exit(main())
