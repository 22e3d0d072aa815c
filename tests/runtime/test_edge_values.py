"""Every kind of bound and step, at the edge and either side of it, on a real node.

Two paths reach genparams' own checks: a set through the parameter services
(for arrays rclpy checks no range at all, so genparams' check is all there is)
and an override given when the node starts (checked by genparams before rclpy
sees it, scalars included). Both must give the verdict of the table in
tests/edge_values.py, and a refused value must leave node and ``cfg`` as they were.
"""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import pytest
from rclpy.parameter import Parameter

from genparams.runtime import ParameterDeclarationError
from tests.edge_values import ARRAY_EDGES, EDGES, SCALAR_EDGES, Edge, write_schema, yaml_value
from tests.support import RosHarness, load_generated

_MODULE: list[types.ModuleType] = []


@pytest.fixture
def edges_class(tmp_path_factory: pytest.TempPathFactory) -> type:
    if not _MODULE:
        folder = tmp_path_factory.mktemp("edges")
        _MODULE.append(load_generated(write_schema(folder), folder))
    return _MODULE[0].EdgesParams  # type: ignore[no-any-return]


def _as_list(value: Any) -> Any:
    return value if isinstance(value, (bool, int, float, str)) else list(value)


@pytest.mark.parametrize("edge", ARRAY_EDGES, ids=lambda e: e.id)
def test_array_items_through_the_service(edge: Edge, ros: RosHarness, edges_class: type) -> None:
    node = ros.node()
    cfg = edges_class.declare(node)  # type: ignore[attr-defined]
    before = _as_list(getattr(cfg, edge.name))
    (result,) = ros.client(node).set(Parameter(edge.name, value=edge.value))
    assert result.successful == edge.accepted, result.reason
    expected = edge.value if edge.accepted else before
    assert _as_list(getattr(cfg, edge.name)) == expected
    assert _as_list(node.get_parameter(edge.name).value) == expected
    if not edge.accepted:
        assert result.reason.startswith(f"{edge.name}: {edge.problem}"), result.reason


@pytest.mark.parametrize("edge", SCALAR_EDGES, ids=lambda e: e.id)
def test_scalars_through_the_service(edge: Edge, ros: RosHarness, edges_class: type) -> None:
    """rclpy checks scalar ranges itself and decides; a refusal reads in genparams' words."""
    node = ros.node()
    cfg = edges_class.declare(node)  # type: ignore[attr-defined]
    before = getattr(cfg, edge.name)
    (result,) = ros.client(node).set(Parameter(edge.name, value=edge.value))
    assert result.successful == edge.accepted, result.reason
    assert getattr(cfg, edge.name) == (edge.value if edge.accepted else before)
    if not edge.accepted:
        assert result.reason.startswith(f"{edge.name}: "), result.reason
        assert edge.problem in result.reason and "Parameter" not in result.reason, result.reason


@pytest.mark.parametrize("edge", EDGES, ids=lambda e: e.id)
def test_overrides_at_start(edge: Edge, ros: RosHarness, edges_class: type) -> None:
    node = ros.node(args=["-p", f"{edge.name}:={yaml_value(edge.value)}"])
    if edge.accepted:
        cfg = edges_class.declare(node)  # type: ignore[attr-defined]
        assert _as_list(getattr(cfg, edge.name)) == edge.value
        return
    with pytest.raises(ParameterDeclarationError) as caught:
        edges_class.declare(node)  # type: ignore[attr-defined]
    (problem,) = caught.value.problems
    assert problem.key == edge.name, problem
    assert problem.message.startswith("override rejected: "), problem
    assert edge.problem in problem.message, problem


def test_the_table_covers_every_parameter_both_ways(tmp_path: Path) -> None:
    names = {line.split(":")[0].strip() for line in write_schema(tmp_path).read_text().splitlines()}
    covered = {e.name for e in EDGES if e.accepted} & {e.name for e in EDGES if not e.accepted}
    assert covered == names - {"genparams", "name", "parameters"}
