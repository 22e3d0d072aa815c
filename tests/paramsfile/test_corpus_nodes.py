"""Every node of the real files, started for real: it refuses exactly when genparams says so.

For each node check-deployment checks in the ros2_control_demos bringup files
and the ros2_controllers test params, a real node is started with the file
(rcl parses it) and declares the generated classes of its schemas. It must
refuse to start exactly when genparams reports a problem that makes it refuse
(unknown keys are ignored by ROS, so they do not), and every value it holds
must be the value genparams explains.
"""

from __future__ import annotations

import math
import types
from pathlib import Path
from typing import Any

import pytest

from genparams.api import load_schema
from genparams.commands.check_deployment import deployed_schemas
from genparams.paramsfile.deployment import configured_nodes
from genparams.paramsfile.explain import explain
from genparams.paramsfile.manifest import read_manifest
from genparams.paramsfile.params_reader import read_params_file
from tests import corpus
from tests.paramsfile.rcl_load import plain, started
from tests.support import load_generated

HERE = Path(__file__).parent
CORPUS = corpus.folder("paramsfile")
CASES = [
    (
        HERE / "deployments" / "demos.manifest.yaml",
        sorted(CORPUS.glob("ros2_control_demos/*/params/*.yaml")),
    ),
    (
        HERE / "deployments" / "controllers.manifest.yaml",
        sorted(CORPUS.glob("ros2_controllers/*/params/*.yaml")),
    ),
]
_MODULES: dict[str, types.ModuleType] = {}


def _class(schema_path: Path, tmp_path: Path) -> type:
    key = str(schema_path)
    if key not in _MODULES:
        _MODULES[key] = load_generated(schema_path, tmp_path)
    return getattr(_MODULES[key], load_schema(schema_path).class_name)  # type: ignore[no-any-return]


def _same(one: Any, other: Any) -> bool:
    if isinstance(one, float) and isinstance(other, float) and math.isnan(one):
        return math.isnan(other)
    return bool(one == other)


@pytest.mark.parametrize(("manifest", "files"), CASES, ids=["demos", "ros2_controllers"])
def test_each_node_starts_as_genparams_says(
    manifest: Path, files: list[Path], tmp_path: Path
) -> None:
    loaded = read_manifest(manifest)
    deployed = deployed_schemas(loaded)
    assert deployed is not None
    nodes = 0
    for path in files:
        document = read_params_file(path.read_text(encoding="utf-8"), str(path))
        for node, item in configured_nodes(deployed, document):
            if "*" in node:
                continue  # a pattern: no real node has this name
            nodes += 1
            known = (*loaded.known, *item.entry.known)
            explanation = explain(item.bounds, [document], node, known)
            classes = [(_class(ref.path, tmp_path), ref.prefix) for ref in item.entry.schemas]
            values = started(node, ["--params-file", str(path)], classes)
            refusing = [
                p for p in explanation.report.problems if "unknown parameter" not in p.message
            ]
            assert (values is None) == bool(refusing), (path.name, node, refusing)
            if values is None:
                continue
            for row in explanation.rows:
                if row.owner == "schema":
                    assert _same(plain(row.value), values[row.name]), (path.name, node, row.name)
    assert nodes > 20
