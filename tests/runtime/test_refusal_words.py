"""Every refusal of a value a class owns reads in genparams' words, however the set arrives.

rclpy checks each value against its descriptor first (read-only, type, range,
step) and decides; genparams words the refusal as its own checks do, naming the
parameter, the rule and the value. A set of a mapped entry whose key is not in
its key list names the entry. The same text comes back from
``node.set_parameters``, ``set_parameters_atomically`` and the parameter
services (what ``ros2 param set`` prints). Values of other code keep rclpy's words.
"""

from __future__ import annotations

import math
import types
from collections.abc import Callable

import pytest
from hypothesis import given
from hypothesis import strategies as st
from rcl_interfaces.msg import SetParametersResult
from rclpy.exceptions import ParameterNotDeclaredException
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime.core.validators import RosRange
from genparams.runtime.node import rclpy_internals as internals
from tests.runtime.schemas import generate
from tests.support import RosHarness

CAMERA = """\
genparams: 1
name: camera
parameters:
  robot_name: {type: string, default: rover, read_only: true}
  image:
    fps: {type: double, default: 30.0, range: {min: 1.0, max: 120.0, step: 0.5}}
    width: {type: int, default: 640, range: {min: 64, max: 4096, step: 2}}
    encoding: {type: string, default: rgb8, choices: [rgb8, mono8]}
  max_speed: {type: double, default: 1.0, range: {min: 0.0, max: 3.0}, aliases: [speed_limit]}
  cameras: {type: string_array, default: [rear]}
  camera:
    for_each: cameras
    gain_db: {type: double, default: 0.0, range: {min: -10.0, max: 10.0}}
"""

FPS_RANGE = "image.fps: must be within [1.0, 120.0] (range), got 200.0"
FPS_STEP = "image.fps: must be 1.0 plus a whole number of steps of 0.5 (range), got 30.3"
FPS_TYPE = "image.fps: expected double, got integer 200 (ROS does not convert: write 200.0)"
WIDTH_STEP = "image.width: must be 64 plus a whole number of steps of 2 (range), got 641"
READ_ONLY = "robot_name: read-only: set it when the node starts (-p, a params file or launch)"
NO_ENTRY = "camera.front.gain_db: no such entry: its key is not in the key list"

REFUSED = [
    (Parameter("image.fps", value=200.0), FPS_RANGE),
    (Parameter("image.fps", value=30.3), FPS_STEP),
    (Parameter("image.fps", value=200), FPS_TYPE),
    (Parameter("image.width", value=641), WIDTH_STEP),
    (Parameter("image.width", value=1.5), "image.width: expected integer, got double 1.5"),
    (Parameter("robot_name", value="other"), READ_ONLY),
    (Parameter("image.fps"), "image.fps: cannot be undeclared"),
    (
        Parameter("speed_limit", value=4.0),
        "speed_limit: must be within [0.0, 3.0] (range), got 4.0",
    ),
    (
        Parameter("image.encoding", value="yuv422"),
        "image.encoding: must be one of ['rgb8', 'mono8'] (one_of), got 'yuv422'",
    ),
    (
        Parameter("camera.rear.gain_db", value=11.0),
        "camera.rear.gain_db: must be within [-10.0, 10.0] (range), got 11.0",
    ),
]

Setter = Callable[[RosHarness, Node, Parameter], str]


def reason(result: SetParametersResult) -> str:
    assert not result.successful
    return str(result.reason)


def by_set_parameters(ros: RosHarness, node: Node, parameter: Parameter) -> str:
    (result,) = node.set_parameters([parameter])
    return reason(result)


def by_set_parameters_atomically(ros: RosHarness, node: Node, parameter: Parameter) -> str:
    return reason(node.set_parameters_atomically([parameter]))


def by_set_service(ros: RosHarness, node: Node, parameter: Parameter) -> str:
    (result,) = ros.client(node).set(parameter)
    return reason(result)


def by_atomic_service(ros: RosHarness, node: Node, parameter: Parameter) -> str:
    return reason(ros.client(node).set_atomically(parameter))


SETTERS = [by_set_parameters, by_set_parameters_atomically, by_set_service, by_atomic_service]


@pytest.fixture(scope="module")
def camera(tmp_path_factory: pytest.TempPathFactory) -> types.ModuleType:
    return generate(tmp_path_factory.mktemp("camera"), CAMERA, "camera")


@pytest.mark.parametrize("setter", SETTERS, ids=lambda s: s.__name__)
def test_every_refusal_names_parameter_rule_and_value(
    setter: Setter, ros: RosHarness, camera: types.ModuleType
) -> None:
    node = ros.node()
    cfg = camera.CameraParams.declare(node)
    before = cfg.snapshot()
    for parameter, words in REFUSED:
        assert setter(ros, node, parameter) == words
    assert cfg.snapshot() is before
    assert node.get_parameter("image.fps").value == 30.0


@pytest.mark.parametrize("setter", SETTERS[2:], ids=lambda s: s.__name__)
def test_a_missing_entry_is_named_by_the_services(
    setter: Setter, ros: RosHarness, camera: types.ModuleType
) -> None:
    node = ros.node()
    camera.CameraParams.declare(node)
    assert setter(ros, node, Parameter("camera.front.gain_db", value=1.0)) == NO_ENTRY
    assert not node.has_parameter("camera.front.gain_db")


def test_a_missing_entry_is_named_by_the_node(ros: RosHarness, camera: types.ModuleType) -> None:
    """rclpy raises for an undeclared name; the exception keeps rclpy's kind."""
    node = ros.node()
    cfg = camera.CameraParams.declare(node)
    entry = Parameter("camera.front.gain_db", value=1.0)
    for set_it in (node.set_parameters, node.set_parameters_atomically):
        with pytest.raises(ParameterNotDeclaredException) as caught:
            set_it([entry])
        assert str(caught.value) == NO_ENTRY
    with pytest.raises(ParameterNotDeclaredException) as caught:
        node.set_parameters_atomically([entry, Parameter("other", value=1)])
    assert str(caught.value) == (
        f"{NO_ENTRY}; Invalid access to undeclared parameter(s): ['other']"  # rclpy's words
    )
    assert node.set_parameters_atomically(
        [Parameter("cameras", value=["rear", "front"]), Parameter("image.fps", value=60.0)]
    ).successful
    assert node.set_parameters([entry])[0].successful and cfg.camera["front"].gain_db == 1.0


def test_other_parameters_keep_rclpys_words(ros: RosHarness, camera: types.ModuleType) -> None:
    plain = ros.node()
    node = ros.node()
    camera.CameraParams.declare(node)
    for target in (plain, node):
        target.declare_parameter("count", 1)
    wrong = [Parameter("count", value="x")]
    assert node.set_parameters(wrong)[0].reason == plain.set_parameters(wrong)[0].reason
    with pytest.raises(ParameterNotDeclaredException) as caught:
        node.set_parameters([Parameter("nothing", value=1)])
    assert str(caught.value) == "Invalid access to undeclared parameter(s): []"
    # rclpy refuses at the first value it refuses: here the other code's
    both = [Parameter("count", value="x"), Parameter("image.fps", value=200.0)]
    assert node.set_parameters_atomically(both).reason == wrong_type(plain, "count")
    # and here the class's: then the class words every value it refuses
    both = [Parameter("image.fps", value=200.0), Parameter("image.width", value=641)]
    assert node.set_parameters_atomically(both).reason == f"{FPS_RANGE}; {WIDTH_STEP}"


def wrong_type(plain: Node, name: str) -> str:
    return str(plain.set_parameters([Parameter(name, value="x")])[0].reason)


def test_a_refusal_by_another_callback_is_passed_on(
    ros: RosHarness, camera: types.ModuleType
) -> None:
    node = ros.node()
    camera.CameraParams.declare(node)
    node.add_on_set_parameters_callback(
        lambda ps: SetParametersResult(successful=False, reason="the driver is busy")
    )
    (result,) = node.set_parameters([Parameter("image.fps", value=60.0)])
    assert (result.successful, result.reason) == (False, "the driver is busy")


FPS = RosRange(1.0, 120.0, 0.5, integer=False)  # the schema's image.fps
HALVES = st.integers(min_value=2, max_value=240).map(lambda half: half / 2)
VALUES = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    HALVES,
    HALVES.map(lambda value: value * (1 + 1e-7)),  # within rclpy's tolerance of a step
    HALVES.map(lambda value: value * (1 + 1e-5)),  # beyond it
)


def test_rclpy_and_genparams_never_disagree(ros: RosHarness, camera: types.ModuleType) -> None:
    """The node's verdict is rclpy's descriptor check; genparams' own check gives the same
    one, and the node's reason is genparams' words for it."""
    node = ros.node()
    camera.CameraParams.declare(node)

    @given(value=VALUES)
    def same_verdict(value: float) -> None:
        parameter = Parameter("image.fps", value=value)
        descriptor = node.describe_parameter("image.fps")
        rclpy_verdict = internals.descriptor_check(node, parameter, descriptor).successful
        (result,) = node.set_parameters([parameter])
        ours = FPS(value)
        assert result.successful == rclpy_verdict == (ours is None), (value, result.reason)
        if ours is not None:
            assert result.reason == f"image.fps: {ours}"
        elif not math.isnan(value):
            assert node.get_parameter("image.fps").value == value

    same_verdict()
