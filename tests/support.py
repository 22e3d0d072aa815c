"""Test support: real rclpy nodes, a parameter-service client, generated modules on disk."""

from __future__ import annotations

import importlib.util
import itertools
import sys
import time
import types
from pathlib import Path
from typing import Any

import rclpy
from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter, parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from rclpy.task import Future

import genparams
from tests.patience import WAIT_S

ROOT = Path(__file__).resolve().parent.parent
CASES = Path(__file__).resolve().parent / "cases"
_names = itertools.count()


def unique_name(stem: str = "node") -> str:
    return f"{stem}_{next(_names)}"


class RosHarness:
    """One rclpy context per test session; nodes per test; an executor to call services."""

    def __init__(self) -> None:
        self.context = Context()
        rclpy.init(context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.client_node = Node(unique_name("param_client"), context=self.context)
        self.executor.add_node(self.client_node)
        self.nodes: list[Node] = []
        self.clients: list[ServiceClient] = []  # of the test nodes, closed with them

    def node(
        self, name: str | None = None, *, args: list[str] | None = None, **kwargs: Any
    ) -> Node:
        """A node served by the executor. ``args`` are ROS args, e.g. ["-p", "fps:=5.0"]."""
        cli_args = ["--ros-args", *args] if args else None
        node = Node(name or unique_name(), context=self.context, cli_args=cli_args, **kwargs)
        self.executor.add_node(node)
        self.nodes.append(node)
        return node

    def add_node(self, node: Node) -> Node:
        self.executor.add_node(node)
        self.nodes.append(node)
        return node

    def client(self, node: Node) -> ServiceClient:
        """``ros2 param``'s view of a test node, closed when the test nodes are destroyed."""
        client = ServiceClient(self, node.get_fully_qualified_name())
        self.clients.append(client)
        return client

    def wait(self, future: Future, timeout: float = WAIT_S) -> Any:
        self.executor.spin_until_future_complete(future, timeout_sec=timeout)
        if not future.done():
            raise TimeoutError("service call did not complete")
        return future.result()

    def destroy_test_nodes(self) -> None:
        # A client left open keeps its six service clients in every later wait of the
        # session's executor: hundreds of property-test examples would slow each spin.
        for client in self.clients:
            client.close()
        self.clients.clear()
        for node in self.nodes:
            self.executor.remove_node(node)
            node.destroy_node()
        self.nodes.clear()

    def close(self) -> None:
        self.destroy_test_nodes()
        self.executor.shutdown()
        self.client_node.destroy_node()
        rclpy.shutdown(context=self.context)


# The services rclpy's AsyncParameterClient opens a client to, by its attribute names.
PARAMETER_SERVICES = (
    "get_parameter",
    "list_parameter",
    "set_parameter",
    "get_parameter_types",
    "describe_parameters",
    "set_parameters_atomically",
)


class ServiceClient:
    """What `ros2 param` sees: calls through the node's parameter services."""

    def __init__(self, harness: RosHarness, target: str, timeout: float = WAIT_S) -> None:
        self.harness = harness
        self.client = AsyncParameterClient(harness.client_node, target)
        # By the clock: spin_once returns early whenever any callback ran, so a count
        # of spins is no timeout on a busy graph.
        deadline = time.monotonic() + timeout
        while not self.client.services_are_ready():
            if time.monotonic() > deadline:
                raise TimeoutError(f"parameter services of {target} did not appear")
            harness.executor.spin_once(timeout_sec=0.1)
        self._first_answer(target)

    def _first_answer(self, target: str, timeout: float = WAIT_S) -> None:
        """Wait until a call is answered. A service can be ready before its reply path
        to this client is matched; a request sent then goes unanswered, so ask again."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            future = self.client.list_parameters([], 1)
            self.harness.executor.spin_until_future_complete(future, timeout_sec=2.0)
            if future.done():
                return
        raise TimeoutError(f"parameter services of {target} never answered")

    def close(self) -> None:
        """Destroy the six service clients (rclpy's parameter client has no close of its own)."""
        for service in PARAMETER_SERVICES:
            self.harness.client_node.destroy_client(getattr(self.client, f"_{service}_client"))

    def get(self, *names: str) -> list[Any]:
        response = self.harness.wait(self.client.get_parameters(list(names)))
        return [parameter_value_to_python(v) for v in response.values]

    def set(self, *parameters: Parameter) -> list[SetParametersResult]:
        response = self.harness.wait(self.client.set_parameters(list(parameters)))
        return list(response.results)

    def set_atomically(self, *parameters: Parameter) -> SetParametersResult:
        response = self.harness.wait(self.client.set_parameters_atomically(list(parameters)))
        return response.result

    def describe(self, *names: str) -> list[ParameterDescriptor]:
        response = self.harness.wait(self.client.describe_parameters(list(names)))
        return list(response.descriptors)


def load_generated(schema: Path, tmp_path: Path) -> types.ModuleType:
    """Generate ``schema`` into ``tmp_path`` and import it under a unique module name."""
    text = genparams.generate(schema)
    module_name = unique_name(f"gen_{schema.stem}")
    path = tmp_path / f"{module_name}.py"
    path.write_text(text, encoding="utf-8")
    return import_file(path, module_name)


def import_file(path: Path, module_name: str | None = None) -> types.ModuleType:
    module_name = module_name or unique_name(path.stem)
    spec = importlib.util.spec_from_file_location(module_name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[module_name] = module
    spec.loader.exec_module(module)
    return module
