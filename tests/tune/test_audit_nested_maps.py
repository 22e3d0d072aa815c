"""genparams audit on mapped groups inside mapped groups (and inside an open group): each
entry is judged by its own field's rule, on real nodes serving their parameters.

The node publishes the schema but declares plain, unchecked parameters, as a node in
another language or an older build may: the audit, not the node, has to find the
values its schema forbids."""

from __future__ import annotations

import types
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import pytest
from rclpy.node import Node

from genparams.audit.findings import DRIFT_DEFAULT, VIOLATION
from genparams.audit.walk import AuditResult, audit
from genparams.live.graph import Graph
from genparams.runtime.core.spec import compile_schema
from genparams.runtime.node.schema_topic import publish_schema
from tests.runtime.served_node import served_node
from tests.support import load_generated, unique_name
from tests.tune.support import eventually

SCHEMA = """\
genparams: 1
name: nested_maps
parameters:
  joints: {type: string_array, default: [shoulder, elbow]}
  fingers: {type: string_array, default: [thumb]}
  gains:
    for_each: joints
    p: {type: double, default: 1.0, range: {min: 0.0, max: 10.0}}
    tips:
      for_each: fingers
      force: {type: double, default: 0.5, range: {min: 0.0, max: 2.0}}
  controllers:
    for_each: overrides
    gains:
      for_each: joints
      p: {type: double, default: 1.0, validators: [{ge: 0.0}]}
"""

# What the node declares: one entry's force out of its range, one missing; under the open
# group's key "arm" one gain below its bound and one away from its default.
DECLARED: dict[str, Any] = {
    "joints": ["shoulder", "elbow"],
    "fingers": ["thumb"],
    "gains.shoulder.p": 1.0,
    "gains.elbow.p": 1.0,
    "gains.shoulder.tips.thumb.force": 5.0,
    "controllers.arm.gains.shoulder.p": -1.0,
    "controllers.arm.gains.elbow.p": 2.0,
}


@pytest.fixture(scope="module")
def module(tmp_path_factory: pytest.TempPathFactory) -> types.ModuleType:
    folder = tmp_path_factory.mktemp("nested maps")
    schema = folder / "nested_maps.yaml"
    schema.write_text(SCHEMA, encoding="utf-8")
    return load_generated(schema, folder)


@contextmanager
def loose_node(module: types.ModuleType) -> Iterator[str]:
    """A node describing itself with the schema, its own plain parameters declared."""

    def setup(node: Node) -> None:
        for parameter, value in DECLARED.items():
            node.declare_parameter(parameter, value)
        publish_schema(node, compile_schema(module.NestedMapsParams._SPEC), "")

    with served_node("nested_maps", setup, []) as name:
        yield name


@pytest.fixture(scope="module")
def result(module: types.ModuleType) -> Iterator[tuple[str, AuditResult]]:
    graph = Graph(unique_name("nested_maps_audit"))
    try:
        with loose_node(module) as target:
            # Asked for before discovery, a node's clients can be let go by the graph's sweep.
            eventually(lambda: target in graph.node_names(), timeout=30)
            assert graph.services_ready(target, 30.0)
            yield target, audit(graph, only=[target], settle=0.3, timeout=10.0)
    finally:
        graph.close()


def test_each_entry_of_a_map_inside_a_map_is_judged_by_its_field(
    result: tuple[str, AuditResult],
) -> None:
    target, found = result
    assert target in found.audited
    by_kind: dict[str, dict[str, str]] = {}
    for finding in found.findings:
        by_kind.setdefault(finding.kind, {})[finding.parameter] = finding.text()
    violations = by_kind.get(VIOLATION, {})
    assert sorted(violations) == [
        "controllers.arm.gains.shoulder.p",
        "gains.elbow.tips.thumb.force",
        "gains.shoulder.tips.thumb.force",
    ]
    assert "not on the node" in violations["gains.elbow.tips.thumb.force"]
    assert "5.0" in violations["gains.shoulder.tips.thumb.force"]
    assert "-1.0" in violations["controllers.arm.gains.shoulder.p"]
    assert sorted(by_kind.get(DRIFT_DEFAULT, {})) == [  # a value off its rule is off its default
        "controllers.arm.gains.elbow.p",
        "controllers.arm.gains.shoulder.p",
        "gains.shoulder.tips.thumb.force",
    ]


def test_no_finding_names_a_template(result: tuple[str, AuditResult]) -> None:
    _, found = result
    assert [f.parameter for f in found.findings if "*" in f.parameter] == []
    assert {f.parameter for f in found.findings} <= set(DECLARED) | {"gains.elbow.tips.thumb.force"}


def test_each_place_follows_the_live_keys(module: types.ModuleType) -> None:
    """Where each group stands: a group inside an entry once per key the node holds now
    (a key left out of a list has no entries), an open group keyed by the names
    declared under it."""
    from genparams.runtime.core.entries import map_places
    from genparams.runtime.node.schema_topic import describe_class

    described = describe_class(compile_schema(module.NestedMapsParams._SPEC), "")
    values = {**DECLARED, "joints": ["elbow"]}
    places = {(p.path, p.keys) for p in map_places(described["maps"], values)}
    assert places == {
        ("gains", ("elbow",)),
        ("gains.elbow.tips", ("thumb",)),
        ("controllers", ("arm",)),
        ("controllers.arm.gains", ("elbow",)),
    }


def test_a_message_nesting_deep_over_long_lists_expands_no_product() -> None:
    """Six groups nested over a list of 50 keys would stand 50**6 times: a node holding
    a handful of parameters is read in at most one place per parameter, plus a margin."""
    from genparams.runtime.core.entries import PLACES_BEYOND, map_places

    field = {"name": "x", "type": "double"}
    maps: list[dict[str, Any]] = [{"path": "g", "for_each": "keys", "fields": [field]}]
    for _ in range(5):
        maps.append({"path": maps[-1]["path"] + ".*.g", "for_each": "keys", "fields": [field]})
    values = {"keys": [f"k{i}" for i in range(50)]}
    places = map_places(maps, values)
    assert len(places) <= len(values) + PLACES_BEYOND
    assert places[0].path == "g" and len(places[0].keys) == 50
