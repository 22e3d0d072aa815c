"""configure_only: a lifecycle node refuses sets while active, naming its state."""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import pytest
from rclpy.lifecycle import Node as LifecycleNode
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.parameter import Parameter

from genparams.runtime.core.errors import RemoteSetError
from tests.runtime.schemas import MOTION, generate
from tests.support import RosHarness, unique_name

STRING = Parameter.Type.STRING
TEXT = "changes only while the lifecycle node is unconfigured or inactive"


@pytest.fixture
def motion(tmp_path: Path) -> types.ModuleType:
    return generate(tmp_path, MOTION, "motion")


def make_driver(ros: RosHarness, motion: types.ModuleType) -> Any:
    class Driver(LifecycleNode):
        def __init__(self) -> None:
            super().__init__(unique_name("driver"), context=ros.context)
            self.params = motion.MotionParams.declare(self)

        def on_configure(self, state: State) -> TransitionCallbackReturn:
            # Configuration time: a configure-only parameter may still change here.
            ok = self.set_parameters([Parameter("port", STRING, "/dev/ttyACM0")])[0].successful
            return TransitionCallbackReturn.SUCCESS if ok else TransitionCallbackReturn.FAILURE

    return ros.add_node(Driver())


def test_configure_only_parameters_follow_the_lifecycle_state(
    ros: RosHarness, motion: types.ModuleType
) -> None:
    driver = make_driver(ros, motion)
    client = ros.client(driver)
    (descriptor,) = client.describe("port")
    assert descriptor.additional_constraints == TEXT

    (ok,) = client.set(Parameter("port", STRING, "/dev/ttyS1"))  # unconfigured
    assert ok.successful and driver.params.port == "/dev/ttyS1"
    driver.trigger_configure()
    assert driver.params.port == "/dev/ttyACM0"
    driver.trigger_activate()
    (refused,) = client.set(Parameter("port", STRING, "/dev/ttyS2"))
    assert not refused.successful
    assert refused.reason == f"port: {TEXT}; the node is active (deactivate it first)"
    refused_array = driver.set_parameters(
        [Parameter("joints", Parameter.Type.STRING_ARRAY, ["a", "b"])]
    )[0]
    assert not refused_array.successful and "the node is active" in refused_array.reason
    assert driver.params.port == "/dev/ttyACM0" and driver.params.joints == ("a",)
    assert driver.get_parameter("port").value == "/dev/ttyACM0"
    # Other parameters change whatever the state.
    assert client.set(Parameter("max_speed", Parameter.Type.DOUBLE, 3.0))[0].successful

    remote = motion.MotionParams.remote(ros.client_node, driver.get_fully_qualified_name())
    with pytest.raises(RemoteSetError, match="the node is active") as caught:
        ros.wait(remote.set({"port": "/dev/ttyS3"}))
    assert caught.value.sent

    driver.trigger_deactivate()
    assert client.set(Parameter("port", STRING, "/dev/ttyS4"))[0].successful
    assert driver.params.port == "/dev/ttyS4"


def test_plain_nodes_ignore_configure_only(ros: RosHarness, motion: types.ModuleType) -> None:
    node = ros.node()
    cfg = motion.MotionParams.declare(node)
    assert node.set_parameters([Parameter("port", STRING, "/dev/ttyS9")])[0].successful
    assert cfg.port == "/dev/ttyS9"


def test_docs_and_generated_module_say_configure_only(tmp_path: Path) -> None:
    import subprocess
    import sys

    schema = tmp_path / "motion.yaml"
    schema.write_text(MOTION)
    docs = subprocess.run(
        [sys.executable, "-m", "genparams", "docs", str(schema), "--format", "markdown"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    port_row = next(line for line in docs.splitlines() if "`port`" in line)
    assert TEXT in port_row
    module = generate(tmp_path, MOTION, "motion_again")
    port = next(p for p in module.MotionParams._SPEC.parameters if p.name == "port")
    assert port.configure_only is True
