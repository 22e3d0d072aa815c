"""The schema features GPL files need, on real nodes through the parameter services."""

from __future__ import annotations

import json
import math
import subprocess
import sys
import types
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

import genparams
from genparams.outputs.json_schema import params_file_schema
from genparams.runtime.core.errors import ParameterDeclarationError
from tests.support import RosHarness, load_generated

SCHEMA = Path(__file__).parent / "cases" / "features.yaml"
PARAMS = """\
/**:
  ros__parameters:
    interfaces: [wheel_left/position, x-1]
    wheel_left/position: {scale: 2.5}
    constraints:
      goal_time: 2.0
      shoulder: {goal: 0.3}
    weights:
      elbow:
        x-1: {w: 4.0}
    filter_chain:
      filter1: {name: mean, type: filters/MeanFilterDouble, params: {number_of_observations: 2}}
    defaults: {strictness: 2}
    snapshot: true
    int: 7
"""


@pytest.fixture(scope="module")
def features(tmp_path_factory: pytest.TempPathFactory) -> types.ModuleType:
    return load_generated(SCHEMA, tmp_path_factory.mktemp("features"))


@pytest.fixture
def params_file(tmp_path: Path) -> Path:
    path = tmp_path / "params.yaml"
    path.write_text(PARAMS, encoding="utf-8")
    return path


def test_in_place_entries_read_by_key_beside_plain_names(
    ros: RosHarness, features: types.ModuleType, params_file: Path
) -> None:
    node = ros.node(args=["--params-file", str(params_file)])
    cfg = features.FeaturesParams.declare(node)
    assert list(cfg) == ["wheel_left/position", "x-1"]
    assert (cfg["wheel_left/position"].scale, cfg["x-1"].scale) == (2.5, 1.0)
    assert cfg.constraints.goal_time == 2.0
    assert (cfg.constraints["shoulder"].goal, cfg.constraints["elbow"].goal) == (0.3, 0.1)
    assert cfg.weights["elbow"]["x-1"].w == 4.0 and len(cfg.weights["shoulder"]) == 2
    client = ros.client(node)
    assert client.get("wheel_left/position.scale", "weights.elbow.x-1.w") == [2.5, 4.0]
    (result,) = client.set(Parameter("constraints.elbow.goal", value=0.7))
    assert result.successful and cfg.constraints["elbow"].goal == 0.7
    (result,) = client.set(Parameter("constraints.elbow.goal", value=-1.0))
    assert result.reason == "constraints.elbow.goal: must be >= 0.0 (ge), got -1.0"
    assert cfg.to_dict()["constraints"] == {
        "goal_time": 2.0,
        "shoulder": {"goal": 0.3},
        "elbow": {"goal": 0.7},
    }


def test_entry_key_cannot_repeat_a_name_beside_it(
    ros: RosHarness, features: types.ModuleType
) -> None:
    node = ros.node()
    cfg = features.FeaturesParams.declare(node)
    client = ros.client(node)
    (result,) = client.set(Parameter("joints", value=["shoulder", "goal_time"]))
    assert result.reason == (
        "joints: item 'goal_time' is already a name in constraints: an entry cannot share it "
        "(for_each)"
    )
    (result,) = client.set(Parameter("joints", value=["wrist"]))
    assert result.successful and list(cfg.constraints) == ["wrist"]
    assert node.has_parameter("weights.wrist.x-1.w") is False  # interfaces are the defaults
    assert node.has_parameter("weights.wrist.wheel_left/position.w")


def test_open_namespace_is_left_to_other_code(
    ros: RosHarness, features: types.ModuleType, params_file: Path
) -> None:
    node = ros.node(args=["--params-file", str(params_file)])
    cfg = features.FeaturesParams.declare(node)
    assert not node.has_parameter("filter_chain.filter1.name")
    assert "filter_chain" not in cfg.to_dict()
    # The plugin that owns it declares its parameters from the same overrides.
    assert node.declare_parameter("filter_chain.filter1.name", "").value == "mean"
    schema = genparams.load_schema(SCHEMA)
    assert [n.ros_name for n in schema.open_namespaces] == ["filter_chain"]


def test_check_params_and_json_schema_accept_the_file(params_file: Path) -> None:
    result = subprocess.run(
        [sys.executable, "-m", "genparams", "check-params", str(SCHEMA), str(params_file)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert (result.returncode, result.stdout + result.stderr) == (0, "")
    jsonschema = pytest.importorskip("jsonschema")
    import yaml

    document = json.loads(json.dumps(params_file_schema(genparams.load_schema(SCHEMA))))
    validator = jsonschema.Draft202012Validator(document)
    data = yaml.safe_load(PARAMS)
    assert [e.message for e in validator.iter_errors(data)] == []
    data["/**"]["ros__parameters"]["constraints"]["goal_time"] = {"goal": 1.0}
    assert validator.iter_errors(data) is not None and list(validator.iter_errors(data))


def test_custom_validator_with_arguments(ros: RosHarness, features: types.ModuleType) -> None:
    node = ros.node()
    cfg = features.FeaturesParams.declare(node)
    assert math.isnan(cfg.max_velocity)
    client = ros.client(node)
    (result,) = client.set(Parameter("max_velocity", value=0.2))
    assert result.reason == (
        "max_velocity: must be NaN or >= 0.5 (tests.gpl.checks:at_least_or_nan(0.5))"
    )
    (result,) = client.set(Parameter("max_velocity", value=0.5))
    assert result.successful and cfg.max_velocity == 0.5
    (described,) = client.describe("max_velocity")
    assert described.additional_constraints == "passes tests.gpl.checks:at_least_or_nan(0.5)"


def test_names_the_generated_api_uses_keep_their_ros_names(
    ros: RosHarness, features: types.ModuleType, params_file: Path
) -> None:
    node = ros.node(args=["--params-file", str(params_file)])
    cfg = features.FeaturesParams.declare(node)
    assert (cfg.defaults_.strictness, cfg.snapshot_, cfg.int_) == (2, True, 7)
    assert node.get_parameter("defaults.strictness").value == 2
    assert cfg.snapshot().defaults_.strictness == 2  # the API itself still works
    assert features.FeaturesParams.defaults().defaults_.strictness == 1
    assert cfg.to_dict()["defaults"] == {"strictness": 2} and cfg.to_dict()["int"] == 7


def test_adopting_a_parameter_other_code_declared_first(
    ros: RosHarness, features: types.ModuleType
) -> None:
    node = ros.node()
    node.declare_parameter("overruns.print_warnings", False)  # e.g. from use_sim_time
    cfg = features.FeaturesParams.declare(node)
    assert cfg.overruns.print_warnings is False  # its value is kept, now typed and checked
    (described,) = ros.client(node).describe("overruns.print_warnings")
    assert described.description == "Warn on overruns."
    (result,) = ros.client(node).set(Parameter("overruns.print_warnings", value=1))
    assert not result.successful and not cfg.overruns.print_warnings


def test_an_adopted_value_is_validated(ros: RosHarness, features: types.ModuleType) -> None:
    node = ros.node()
    node.declare_parameter("overruns.print_warnings", "yes")
    with pytest.raises(ParameterDeclarationError, match=r"overruns\.print_warnings"):
        features.FeaturesParams.declare(node)


def test_without_adopt_other_code_first_is_refused(
    ros: RosHarness, features: types.ModuleType
) -> None:
    node = ros.node()
    node.declare_parameter("constraints.goal_time", 1.0)
    with pytest.raises(ParameterDeclarationError, match="already declared on this node"):
        features.FeaturesParams.declare(node)


def test_remote_reads_and_sets_in_place_entries(
    ros: RosHarness, features: types.ModuleType, params_file: Path
) -> None:
    node = ros.node(args=["--params-file", str(params_file)])
    features.FeaturesParams.declare(node)
    remote = features.FeaturesParams.remote(ros.client_node, node.get_fully_qualified_name())
    assert remote.wait_for_services(timeout_sec=10.0)
    snapshot = ros.wait(remote.get())
    assert snapshot["wheel_left/position"].scale == 2.5
    assert snapshot.constraints["shoulder"].goal == 0.3 and snapshot.defaults_.strictness == 2
    ros.wait(remote.set({"constraints.elbow.goal": 0.9, "x-1.scale": 3.0}))
    after = ros.wait(remote.get())
    assert (after.constraints["elbow"].goal, after["x-1"].scale) == (0.9, 3.0)


def test_top_level_key_list_changes_at_run_time(
    ros: RosHarness, features: types.ModuleType
) -> None:
    node = ros.node()
    cfg = features.FeaturesParams.declare(node)
    seen: list[list[tuple[str, object, object]]] = []
    cfg.on_change(lambda changes: seen.append([(c.name, c.old, c.new) for c in changes]))
    client = ros.client(node)
    (result,) = client.set(Parameter("interfaces", value=["a/b"]))
    assert result.successful and list(cfg) == ["a/b"] and list(cfg.weights["elbow"]) == ["a/b"]
    assert ("wheel_left/position.scale", 1.0, None) in seen[-1]
    assert ("a/b.scale", None, 1.0) in seen[-1]
    (result,) = client.set(Parameter("a/b.scale", value=3.0))
    assert result.successful and cfg["a/b"].scale == cfg.snapshot()["a/b"].scale == 3.0
    (result,) = client.set(Parameter("interfaces", value=["a/b", "joints"]))
    assert result.reason == (
        "interfaces: item 'joints' is already a name in the top level: an entry cannot share "
        "it (for_each)"
    )
