"""import-rclpy against real rclpy: each test node's own declaration code runs on a real
node; the class generated from the imported schema, declared on a fresh node, must give
the same parameters, descriptor by descriptor; the patched node must declare what the
hand-written one did, and the patch must apply with `patch`."""

from __future__ import annotations

import shutil
import subprocess
import sys
import types
from pathlib import Path

import pytest
from rclpy.node import Node

import genparams
from genparams.importing import APPROXIMATE, EXACT, LEFT_OUT
from genparams.outputs.schema_yaml import schema_yaml
from genparams.rclpy_import.found import Found
from genparams.rclpy_import.node_file import ImportedNode, import_node
from genparams.rclpy_import.patch import patched_source
from genparams.runtime.core.naming import class_name, module_name
from tests.rclpy_import.cases import CASES, CLASSES, GOLDEN, NODES, Case
from tests.rclpy_import.declared import declared, schema_key, without_item_rule
from tests.support import RosHarness, import_file, load_generated


def imported(case: Case) -> ImportedNode:
    text = (NODES / case.file).read_text("utf-8")
    return import_node(text, str(NODES / case.file), case.cls)


def hand_written(ros: RosHarness, case: Case, module: types.ModuleType) -> Node:
    """A node running the case's own declaration code, with the case's params file."""
    if case.declare is not None:
        node = ros.node(args=case.ros_args)
        getattr(module, case.declare)(node)
        return node
    cli_args = ["--ros-args", *case.ros_args] if case.params else None
    return ros.add_node(getattr(module, CLASSES[case.name])(context=ros.context, cli_args=cli_args))


def generated(node: ImportedNode, tmp_path: Path) -> types.ModuleType:
    schema = tmp_path / f"{node.imported.name}.yaml"
    schema.write_text(schema_yaml(dict(node.imported.data)), encoding="utf-8")
    return load_generated(schema, tmp_path)


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_generated_class_declares_what_the_node_declared(
    case: Case, ros: RosHarness, tmp_path: Path
) -> None:
    result = imported(case)
    hand = declared(hand_written(ros, case, import_file(NODES / case.file)))
    params = getattr(generated(result, tmp_path), class_name(result.imported.name))
    fresh = ros.node(args=case.ros_args)
    params.declare(fresh)
    ours = declared(fresh)
    assert set(ours) <= set(hand)
    assert sorted(set(hand) - set(ours)) == NOT_IMPORTED.get(case.name, [])
    from_item = {n for n in ours if _found(result, n).value.problem is not None}
    assert sorted(from_item) == FROM_ITEM.get(case.name, [])
    for name in ours:
        outcome = _outcome(result, name)
        (hand_descriptor, hand_value), (our_descriptor, our_value) = hand[name], ours[name]
        assert our_value == hand_value, name
        assert our_descriptor[:2] == hand_descriptor[:2], name  # name and type
        if outcome == EXACT or name in from_item:  # a default from the item: the file gives it
            assert without_item_rule(our_descriptor) == hand_descriptor, name
        else:  # the warning named what could not be kept
            assert outcome == APPROXIMATE and our_descriptor != hand_descriptor, name


# What each hand-written node declares that the import left out, with a warning.
NOT_IMPORTED = {"legacy_bridge": ["home"]}
# The entries whose default the node computes from the key: imported with none, given by
# the params file.
FROM_ITEM = {"sensor_hub": ["sensors.front.frame_id", "sensors.rear.frame_id"]}


def _outcome(result: ImportedNode, name: str) -> str:
    found = _found(result, name)
    return next(o.fate for o in result.imported.declared if o.found is found)


def _found(result: ImportedNode, name: str) -> Found:
    """The declaration of ``name``: by its own name, as an item of a per-item parameter
    (``offsets`` holds ``offsets.shoulder``, ``*`` the top level's), or as a parameter of
    a mapped group's entry (``gains.*.p`` holds ``gains.shoulder.p``)."""
    keys = {o.key: o.found for o in result.imported.declared if o.key and o.found}
    key = schema_key(keys, name)
    if key is None:
        raise KeyError(name)
    return keys[key]


def test_every_case_is_counted() -> None:
    counts = {c.name: [o.fate for o in imported(c).imported.declared] for c in CASES}
    tallies = {n: (o.count(EXACT), o.count(APPROXIMATE), o.count(LEFT_OUT)) for n, o in
               counts.items()}  # fmt: skip
    assert tallies == {
        "arm_controller": (14, 0, 0),
        "camera_driver": (12, 0, 0),
        "fleet_monitor": (1, 2, 0),
        "key_teleop": (9, 0, 0),
        "lease_client": (13, 0, 0),
        "legacy_bridge": (8, 2, 2),
        "pan_tilt": (5, 0, 0),
        "planner": (13, 0, 0),
        "sensor_hub": (5, 1, 0),
        "serial_driver": (2, 0, 0),
        "two_nodes_service": (1, 0, 0),
        "waypoint_player": (5, 0, 0),
    }


@pytest.mark.parametrize("case", [c for c in CASES if c.declare is None], ids=lambda c: c.name)
def test_patched_node_declares_what_the_hand_written_one_did(
    case: Case, ros: RosHarness, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    result = imported(case)
    hand = declared(hand_written(ros, case, import_file(NODES / case.file)))
    module = module_name(result.imported.name)
    text = genparams.generate(
        f"{result.imported.name}.yaml", schema_yaml(dict(result.imported.data))
    )
    (tmp_path / f"{module}.py").write_text(text, encoding="utf-8")
    patched = tmp_path / case.file
    patched.write_text(patched_source(result, str(NODES / case.file)), encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.delitem(sys.modules, module, raising=False)
    node = hand_written(ros, case, import_file(patched))
    ours = declared(node)
    assert sorted(ours) == sorted(hand)
    for name in hand:
        if _outcome(result, name) != APPROXIMATE:
            our_descriptor, our_value = ours[name]
            assert (without_item_rule(our_descriptor), our_value) == hand[name], name
    ruff = [sys.executable, "-m", "ruff", "check", "--isolated", "--line-length", "100"]
    lint = subprocess.run(
        [*ruff, "--select", "F,E9,E501", str(patched)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert lint.returncode == 0, lint.stdout


@pytest.mark.skipif(shutil.which("patch") is None, reason="needs the patch tool")
@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_the_diff_applies_with_patch(case: Case, tmp_path: Path) -> None:
    shutil.copy(NODES / case.file, tmp_path / case.file)
    diff = (GOLDEN / f"{case.name}.diff").read_text("utf-8")
    if not diff:  # declarations outside a class are left as they are
        return
    applied = subprocess.run(
        ["patch", "-p0", "--quiet"], input=diff, cwd=tmp_path, text=True, check=False,
        capture_output=True,
    )  # fmt: skip
    assert applied.returncode == 0, applied.stdout + applied.stderr
    expected = patched_source(imported(case), str(NODES / case.file))
    assert (tmp_path / case.file).read_text("utf-8") == expected
