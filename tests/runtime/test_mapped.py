"""Mapped groups (for_each) on real nodes: declared per key, grown and shrunk through services."""

from __future__ import annotations

import gc
import sys
import threading
import types
import uuid
from pathlib import Path
from typing import Any, cast

import pytest
from rcl_interfaces.msg import SetParametersResult
from rclpy.exceptions import ParameterNotDeclaredException
from rclpy.node import Node
from rclpy.parameter import Parameter

import genparams
from genparams.runtime import Changes, GroupMap, ParameterDeclarationError
from genparams.runtime.node.consistency import parameter_set_lock
from tests.support import ROOT, RosHarness, ServiceClient, load_generated

ARM = """\
genparams: 1
name: arm
parameters:
  rate: {type: double, default: 10.0}
  joints: {type: string_array, default: [shoulder, elbow]}
  fingers: {type: string_array, default: [thumb]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0, validators: [{ge: 0.0}], description: Proportional.}
    i: {type: double, default: 0.0}
    offset: {type: int, default: 0, read_only: true}
    limits:
      max: {type: double, default: 2.0, range: {min: 0.0, max: 5.0}}
    tips:
      for_each: fingers
      force: {type: double, default: 0.5}
"""


@pytest.fixture
def arm(tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / "arm.yaml"
    schema.write_text(ARM)
    return load_generated(schema, tmp_path)


def params_file(tmp_path: Path, body: str) -> list[str]:
    """ROS args loading ``body`` (the ros__parameters of every node) from a params file."""
    path = tmp_path / "params.yaml"
    indented = "".join(f"    {line}\n" for line in body.splitlines())
    path.write_text(f"/**:\n  ros__parameters:\n{indented}")
    return ["--params-file", str(path)]


def listed(client: ServiceClient, prefix: str) -> list[str]:
    """Parameter names under ``prefix`` as `ros2 param list` sees them."""
    response = client.harness.wait(client.client.list_parameters([prefix], 0))
    return sorted(response.result.names)


def _reason(result: SetParametersResult) -> str:
    assert not result.successful
    return str(result.reason)


def test_one_group_per_key_read_through_a_mapping(ros: RosHarness, arm: types.ModuleType) -> None:
    node = ros.node()
    cfg = arm.ArmParams.declare(node)
    client = ros.client(node)
    assert listed(client, "gains") == [
        f"gains.{joint}.{leaf}"
        for joint in ("elbow", "shoulder")
        for leaf in ("i", "limits.max", "offset", "p", "tips.thumb.force")
    ]
    assert isinstance(cfg.gains, GroupMap) and list(cfg.gains) == ["shoulder", "elbow"]
    assert cfg.gains["elbow"].p == 1.0 and cfg.gains["elbow"].tips["thumb"].force == 0.5
    assert cfg.gains["shoulder"].limits.max == 2.0
    p, max_ = client.describe("gains.shoulder.p", "gains.elbow.limits.max")
    assert (p.description, p.additional_constraints) == ("Proportional.", "must be >= 0.0")
    assert max_.floating_point_range[0].to_value == 5.0
    with pytest.raises(TypeError):
        cast(Any, cfg.gains)["wrist"] = cfg.gains["elbow"]  # what its type already forbids
    with pytest.raises(AttributeError, match="read-only"):
        cfg.gains["elbow"].p = 2.0
    assert cfg.to_dict()["gains"]["elbow"]["tips"] == {"thumb": {"force": 0.5}}
    (result,) = client.set(Parameter("gains.elbow.p", value=-1.0))
    assert _reason(result) == "gains.elbow.p: must be >= 0.0 (ge), got -1.0"
    assert "read-only" in _reason(client.set(Parameter("gains.elbow.offset", value=3))[0])


def test_map_grows_and_shrinks_through_services(
    ros: RosHarness, arm: types.ModuleType, tmp_path: Path
) -> None:
    node = ros.node(args=params_file(tmp_path, "gains: {wrist: {p: 3.0, limits: {max: 4.0}}}"))
    cfg = arm.ArmParams.declare(node)
    client = ros.client(node)
    before = cfg.snapshot()
    seen: list[Changes[Any]] = []
    cfg.on_change(seen.append)

    (result,) = client.set(Parameter("joints", value=["shoulder", "wrist"]))
    assert result.successful
    assert listed(client, "gains.wrist") == [
        "gains.wrist.i",
        "gains.wrist.limits.max",
        "gains.wrist.offset",
        "gains.wrist.p",
        "gains.wrist.tips.thumb.force",
    ]
    assert listed(client, "gains.elbow") == []
    assert client.get("gains.wrist.p", "gains.wrist.limits.max") == [3.0, 4.0]
    assert list(cfg.gains) == ["shoulder", "wrist"] and cfg.joints == ("shoulder", "wrist")
    assert cfg.gains["wrist"].p == 3.0 and cfg.gains["wrist"].limits.max == 4.0
    # New entries carry their descriptors: ranges and read-only hold.
    (max_,) = client.describe("gains.wrist.limits.max")
    assert max_.floating_point_range[0].to_value == 5.0
    assert _reason(client.set(Parameter("gains.wrist.limits.max", value=9.0))[0]) == (
        "gains.wrist.limits.max: must be within [0.0, 5.0] (range), got 9.0"
    )
    assert "read-only" in _reason(client.set(Parameter("gains.wrist.offset", value=1))[0])
    # One consistent change: the key list and the entries move together.
    (changes,) = seen
    assert changes.before is before and list(before.gains) == ["shoulder", "elbow"]
    assert list(changes.after.gains) == list(changes.after.joints) == ["shoulder", "wrist"]
    moved = {(c.name, c.old, c.new) for c in changes}
    assert ("gains.elbow.p", 1.0, None) in moved and ("gains.wrist.p", None, 3.0) in moved
    assert ("joints", ("shoulder", "elbow"), ("shoulder", "wrist")) in moved

    (result,) = client.set(Parameter("gains.wrist.p", value=0.5))
    assert result.successful and cfg.gains["wrist"].p == 0.5

    (result,) = client.set(Parameter("joints", Parameter.Type.STRING_ARRAY, []))
    assert result.successful and len(cfg.gains) == 0 and listed(client, "gains") == []
    assert cfg.snapshot().to_dict()["gains"] == {}


def test_bad_override_for_a_new_key_rejects_the_set(
    ros: RosHarness, arm: types.ModuleType, tmp_path: Path
) -> None:
    node = ros.node(args=params_file(tmp_path, "gains: {wrist: {p: -1.0, i: 2}}"))
    cfg = arm.ArmParams.declare(node)
    client = ros.client(node)
    (result,) = client.set(Parameter("joints", value=["shoulder", "elbow", "wrist"]))
    assert _reason(result) == (
        "joints: cannot declare the new entries: "
        "gains.wrist.i: override has the wrong type: expected double, got integer 2 "
        "(ROS does not convert: write 2.0); "
        "gains.wrist.p: override rejected: must be >= 0.0 (ge), got -1.0"
    )
    assert cfg.joints == ("shoulder", "elbow") and client.get("joints") == [["shoulder", "elbow"]]
    assert listed(client, "gains.wrist") == [] and list(cfg.gains) == ["shoulder", "elbow"]


def test_new_key_overrides_are_checked_at_declare_too(
    ros: RosHarness, arm: types.ModuleType, tmp_path: Path
) -> None:
    args = params_file(tmp_path, "joints: [wrist]\ngains: {wrist: {p: -1.0}}")
    node = ros.node(args=args)
    with pytest.raises(ParameterDeclarationError) as caught:
        arm.ArmParams.declare(node)
    assert tuple(map(str, caught.value.problems)) == (
        "gains.wrist.p: override rejected: must be >= 0.0 (ge), got -1.0",
    )
    assert not node.has_parameter("joints")


def test_keys_named_like_fields_methods_and_keywords(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    node = ros.node()
    cfg = arm.ArmParams.declare(node)
    keys = ["rate", "snapshot", "p", "class", "gains"]
    assert ros.client(node).set(Parameter("joints", value=keys))[0].successful
    assert list(cfg.gains) == keys
    assert cfg.rate == 10.0 and cfg.snapshot().gains["snapshot"].p == 1.0
    assert cfg.gains["class"].i == 0.0 and cfg.gains["gains"].p == 1.0
    node.set_parameters([Parameter("gains.rate.p", value=4.0)])
    assert cfg.gains["rate"].p == 4.0 and cfg.rate == 10.0


def test_keys_with_dashes_and_leading_digits_work_through_services(
    ros: RosHarness, arm: types.ModuleType, tmp_path: Path
) -> None:
    """`left-arm` and `1st` are ROS name segments the services and params files carry."""
    node = ros.node(args=params_file(tmp_path, "gains:\n  left-arm: {p: 2.5}\n  1st: {i: 0.25}"))
    cfg = arm.ArmParams.declare(node)
    client = ros.client(node)
    (result,) = client.set(Parameter("joints", value=["shoulder", "left-arm", "1st"]))
    assert result.successful, result.reason
    assert list(cfg.gains) == ["shoulder", "left-arm", "1st"]
    assert cfg.gains["left-arm"].p == 2.5 and cfg.gains["1st"].i == 0.25  # params-file overrides
    assert client.get("gains.left-arm.p", "gains.1st.i") == [2.5, 0.25]
    assert "gains.left-arm.limits.max" in listed(client, "gains")

    (result,) = client.set(Parameter("gains.left-arm.p", value=3.0))
    assert result.successful, result.reason
    assert cfg.gains["left-arm"].p == 3.0 and node.get_parameter("gains.left-arm.p").value == 3.0
    (result,) = client.set(Parameter("gains.1st.limits.max", value=9.0))
    assert "gains.1st.limits.max" in _reason(result) and cfg.gains["1st"].limits.max == 2.0

    (result,) = client.set(Parameter("joints", value=["1st"]))
    assert result.successful, result.reason
    assert list(cfg.gains) == ["1st"]
    assert not node.has_parameter("gains.left-arm.p")
    assert "gains.left-arm.p" not in listed(client, "gains")


@pytest.mark.parametrize("key", ["left.arm", "a b", "", "*", "tab\tkey"])
def test_key_that_cannot_name_an_entry_is_rejected(
    ros: RosHarness, arm: types.ModuleType, key: str
) -> None:
    node = ros.node()
    cfg = arm.ArmParams.declare(node)
    client = ros.client(node)
    (result,) = client.set(Parameter("joints", value=["shoulder", key]))
    assert _reason(result) == (
        f"joints: item 1 {key!r} cannot name an entry of gains: "
        "use any text but '.', '*', spaces and control characters (for_each)"
    )
    assert cfg.joints == ("shoulder", "elbow") and list(cfg.gains) == ["shoulder", "elbow"]
    assert node.get_parameter("joints").value == ["shoulder", "elbow"]


def test_repeated_key_is_rejected(ros: RosHarness, arm: types.ModuleType) -> None:
    node = ros.node()
    cfg = arm.ArmParams.declare(node)
    client = ros.client(node)
    (result,) = client.set(Parameter("joints", value=["a", "a"]))
    assert (
        _reason(result)
        == "joints: item 1 'a' repeats: each item names one entry of gains (for_each)"
    )
    assert cfg.joints == ("shoulder", "elbow")
    (described,) = client.describe("joints")
    assert (
        "each item names an entry of gains: any text but '.', '*', spaces and control "
        "characters; no repeats"
    ) in (described.additional_constraints)

    bad = ros.node(args=["-p", "fingers:=[thumb, '']"])
    with pytest.raises(ParameterDeclarationError, match=r"fingers: override rejected: item 1 ''"):
        arm.ArmParams.declare(bad)


def test_under_a_prefix(ros: RosHarness, arm: types.ModuleType, tmp_path: Path) -> None:
    node = ros.node(args=params_file(tmp_path, "left: {gains: {wrist: {i: 0.5}}}"))
    cfg = arm.ArmParams.declare(node, prefix="left")
    client = ros.client(node)
    assert client.get("left.gains.elbow.p") == [1.0]
    (result,) = client.set(Parameter("left.joints", value=["wrist"]))
    assert result.successful
    assert listed(client, "left.gains") == [
        "left.gains.wrist.i",
        "left.gains.wrist.limits.max",
        "left.gains.wrist.offset",
        "left.gains.wrist.p",
        "left.gains.wrist.tips.thumb.force",
    ]
    assert cfg.gains["wrist"].i == 0.5 and listed(client, "gains") == []


def test_nested_map_follows_both_key_lists(ros: RosHarness, arm: types.ModuleType) -> None:
    node = ros.node(args=["-p", "gains.elbow.tips.index.force:=0.75"])
    cfg = arm.ArmParams.declare(node)
    client = ros.client(node)
    assert client.set(Parameter("fingers", value=["thumb", "index"]))[0].successful
    assert [list(cfg.gains[j].tips) for j in cfg.gains] == [["thumb", "index"]] * 2
    assert cfg.gains["elbow"].tips["index"].force == 0.75
    assert cfg.gains["shoulder"].tips["index"].force == 0.5
    result = client.set_atomically(
        Parameter("joints", value=["elbow", "wrist"]), Parameter("fingers", value=["index"])
    )
    assert result.successful
    assert listed(client, "gains.wrist.tips") == ["gains.wrist.tips.index.force"]
    assert listed(client, "gains.elbow.tips") == ["gains.elbow.tips.index.force"]
    assert {j: list(cfg.gains[j].tips) for j in cfg.gains} == {
        "elbow": ["index"],
        "wrist": ["index"],
    }
    assert cfg.gains["elbow"].tips["index"].force == 0.75


def test_atomic_change_of_keys_and_values_is_one_commit(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    node = ros.node()
    cfg = arm.ArmParams.declare(node)
    seen: list[Changes[object]] = []
    cfg.on_change(seen.append)
    result = ros.client(node).set_atomically(
        Parameter("joints", value=["shoulder", "wrist"]),
        Parameter("gains.shoulder.p", value=2.5),
        Parameter("rate", value=20.0),
    )
    assert result.successful
    (changes,) = seen
    assert {"joints", "gains.shoulder.p", "rate", "gains.wrist.p", "gains.elbow.p"} <= changes.names
    assert (cfg.gains["shoulder"].p, cfg.rate, list(cfg.gains)) == (
        2.5,
        20.0,
        ["shoulder", "wrist"],
    )


def test_automatically_declared_entries_get_their_descriptors(
    ros: RosHarness, arm: types.ModuleType, tmp_path: Path
) -> None:
    node = ros.node(
        args=params_file(tmp_path, "gains: {wrist: {p: 3.0}, elbow: {p: 2.0}}"),
        automatically_declare_parameters_from_overrides=True,
    )
    cfg = arm.ArmParams.declare(node)
    assert cfg.gains["elbow"].p == 2.0
    client = ros.client(node)
    assert client.set(Parameter("joints", value=["wrist"]))[0].successful
    assert cfg.gains["wrist"].p == 3.0
    (p,) = client.describe("gains.wrist.p")
    assert p.additional_constraints == "must be >= 0.0" and not p.dynamic_typing
    assert "must be >= 0.0" in _reason(client.set(Parameter("gains.wrist.p", value=-2.0))[0])


def test_undeclaring_an_entry_directly_is_refused(ros: RosHarness, arm: types.ModuleType) -> None:
    node = ros.node()
    cfg = arm.ArmParams.declare(node)
    (result,) = ros.client(node).set(Parameter("gains.elbow.p"))
    assert not result.successful and node.has_parameter("gains.elbow.p")
    assert cfg.gains["elbow"].p == 1.0


def test_defaults_expand_maps_without_ros(arm: types.ModuleType) -> None:
    snap = arm.ArmParams.defaults({"joints": ["x"], "gains.x.p": 2.0})
    assert list(snap.gains) == ["x"] and snap.gains["x"].p == 2.0
    assert arm.ArmParams.defaults().gains["elbow"].tips["thumb"].force == 0.5
    with pytest.raises(ParameterDeclarationError, match=r"gains\.y\.p: no such parameter"):
        arm.ArmParams.defaults({"gains.y.p": 2.0})


def test_mapped_groups_are_typed_for_mypy(tmp_path: Path) -> None:
    """cfg.gains is a Mapping[str, GainsGroup]: entry fields keep their types under --strict."""
    from mypy import api

    schema = tmp_path / "arm.yaml"
    schema.write_text(ARM)
    # Names unique across runs: mypy's shared cache would otherwise replay an earlier run.
    run = uuid.uuid4().hex[:12]
    generated, user = f"arm_params_{run}", f"use_arm_{run}"
    (tmp_path / f"{generated}.py").write_text(genparams.generate(schema))
    (tmp_path / f"{user}.py").write_text(
        "from collections.abc import Mapping\n\n"
        f"from {generated} import ArmParams, GainsGroup\n\n\n"
        "def total(cfg: ArmParams) -> float:\n"
        "    gains: Mapping[str, GainsGroup] = cfg.gains\n"
        "    return sum(g.p for g in gains.values()) + cfg.gains['a'].tips['b'].force\n\n\n"
        "def wrong(cfg: ArmParams) -> str:\n"
        "    return cfg.gains['a'].limits.max\n"
    )
    files = [str(tmp_path / f"{generated}.py"), str(tmp_path / f"{user}.py")]
    cache = ["--cache-dir", str(ROOT / ".mypy_cache")]
    # mypy tunes the garbage collector and recursion limit of the process it runs in.
    threshold, limit = gc.get_threshold(), sys.getrecursionlimit()
    try:
        out, _, status = api.run(["--strict", *cache, "--no-error-summary", *files])
    finally:
        gc.set_threshold(*threshold)
        sys.setrecursionlimit(limit)
    assert status == 1 and out.splitlines() == [
        f"{files[1]}:12: error: Incompatible return value type "
        '(got "float", expected "str")  [return-value]'
    ]


def test_required_leaf_of_a_new_entry_must_come_from_an_override(
    ros: RosHarness, tmp_path: Path
) -> None:
    schema = tmp_path / "tools.yaml"
    schema.write_text(
        "genparams: 1\nname: tools\nparameters:\n"
        "  names: {type: string_array, default: []}\n"
        "  tool:\n    for_each: names\n    serial: {type: string}\n"
    )
    module = load_generated(schema, tmp_path)
    node = ros.node(args=["-p", "tool.drill.serial:=D1"])
    cfg = module.ToolsParams.declare(node)
    assert len(cfg.tool) == 0
    client = ros.client(node)
    (result,) = client.set(Parameter("names", value=["drill", "saw"]))
    assert _reason(result) == (
        "names: cannot declare the new entries: tool.saw.serial: required parameter is not set "
        "(pass -p tool.saw.serial:=<string> or set it in a params file)"
    )
    assert client.set(Parameter("names", value=["drill"]))[0].successful
    assert cfg.tool["drill"].serial == "D1"


def _entries_agree(node: Node, cfg: Any) -> None:
    """Every entry the view holds is declared on the node, and no other entry is."""
    on_node = sorted(node.list_parameters(["gains"], 0).names)
    in_view = sorted(
        f"gains.{joint}.{leaf}"
        for joint in cfg.gains
        for leaf in ("i", "limits.max", "offset", "p", "tips.thumb.force")
    )
    assert on_node == in_view


def test_undeclared_entry_is_refused_where_undeclared_parameters_are_allowed(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    node = ros.node(allow_undeclared_parameters=True)
    cfg = arm.ArmParams.declare(node)
    client = ros.client(node)
    (result,) = client.set(Parameter("gains.wrist.p", value=2.0))
    assert _reason(result) == "gains.wrist.p: no such entry: its key is not in the key list"
    assert not node.has_parameter("gains.wrist.p")
    # The key can still be added: no stray parameter holds its entry's name.
    assert client.set(Parameter("joints", value=["shoulder", "wrist"]))[0].successful
    assert cfg.gains["wrist"].p == 1.0 and client.get("gains.wrist.p") == [1.0]
    # Other undeclared names are still the node's business.
    assert client.set(Parameter("free_form", value=1))[0].successful
    _entries_agree(node, cfg)


def test_set_of_an_entry_racing_its_removal_leaves_no_stray(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    """rclpy checks that a parameter is declared before a set takes the node's set lock."""
    node = ros.node()
    cfg = arm.ArmParams.declare(node)
    checked = threading.Event()

    def signal(parameters: list[Parameter]) -> list[Parameter]:
        if threading.current_thread() is not threading.main_thread():
            checked.set()
        return parameters

    node.add_pre_set_parameters_callback(signal)
    outcome: list[object] = []

    def set_elbow() -> None:
        try:
            outcome.append(node.set_parameters([Parameter("gains.elbow.p", value=2.0)])[0])
        except ParameterNotDeclaredException as exc:
            outcome.append(exc)

    with parameter_set_lock(node):  # the set below waits here, its declared-check done or near
        racer = threading.Thread(target=set_elbow)
        racer.start()
        assert checked.wait(10.0)
        assert node.set_parameters([Parameter("joints", value=["shoulder"])])[0].successful
    racer.join(10.0)
    (result,) = outcome
    if isinstance(result, SetParametersResult):  # it passed the check before the removal
        assert _reason(result) == "gains.elbow.p: no such entry: its key is not in the key list"
    assert not node.has_parameter("gains.elbow.p") and list(cfg.gains) == ["shoulder"]
    assert node.set_parameters([Parameter("joints", value=["shoulder", "elbow"])])[0].successful
    assert cfg.gains["elbow"].p == 1.0
    _entries_agree(node, cfg)


def test_a_callback_refusing_the_entries_refuses_the_change_of_keys(
    ros: RosHarness, arm: types.ModuleType
) -> None:
    """Another on-set callback sees the entries' declarations and undeclarations in the
    on-set round, so its veto refuses the key change instead of splitting keys and entries."""
    node = ros.node()
    cfg = arm.ArmParams.declare(node)

    def guard(parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.type_ == Parameter.Type.NOT_SET:
                return SetParametersResult(successful=False, reason="nothing is undeclared here")
            if parameter.name.startswith("gains.wrist."):
                return SetParametersResult(successful=False, reason="no wrist on this arm")
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(guard)
    client = ros.client(node)
    (result,) = client.set(Parameter("joints", value=["shoulder"]))
    assert _reason(result) == "joints: the new entries were refused: nothing is undeclared here"
    (result,) = client.set(Parameter("joints", value=["shoulder", "elbow", "wrist"]))
    assert _reason(result) == "joints: the new entries were refused: no wrist on this arm"
    assert cfg.joints == ("shoulder", "elbow") and list(cfg.gains) == ["shoulder", "elbow"]
    assert client.get("joints") == [["shoulder", "elbow"]]
    _entries_agree(node, cfg)
    # A change the callback accepts goes through, entries and all.
    assert client.set(Parameter("joints", value=["shoulder", "elbow", "hand"]))[0].successful
    assert list(cfg.gains) == ["shoulder", "elbow", "hand"]
    _entries_agree(node, cfg)
