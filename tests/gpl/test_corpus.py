"""Every real GPL schema of the corpus: imported, generated, declared on real nodes with its
real params files, every value the file sets read back through the node and through cfg."""

from __future__ import annotations

import sys
import types
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
import yaml

import genparams
from genparams.gpl.convert import GplImported, import_gpl
from genparams.gpl.emit import schema_text, stub_text
from genparams.paramsfile.check_params import check_params
from genparams.paramsfile.params_reader import read_params_file
from genparams.runtime.core.errors import ParameterDeclarationError
from genparams.runtime.core.naming import NODE_PARAMETERS
from genparams.schema.loader import load_yaml
from tests import corpus
from tests.gpl.corpus_cases import (
    CORPUS,
    Section,
    gpl_declared,
    same,
    schemas,
    sections,
    values_for,
)
from tests.support import RosHarness, import_file, unique_name

corpus.folder("gpl")  # skips this module where the corpus is absent

# Files GPL itself refuses to load without overrides (its tests expect the failure).
MISSING_REQUIRED = "missing_required.yaml"

# Parameters the node's own code declares before GPL's listener, and their value there.
ADOPTED = {"controller_manager_parameters.yaml": {"overruns.print_warnings": True}}

# Sections whose values break the schema's own validators: GPL refuses them the same way.
REJECTED = {
    "test_gripper_action_position_controller_empty_joint": "joint: override rejected: must not "
    "be empty (not_empty)",
    # GPL's descriptor range for gt<>: [0.0] starts one epsilon above 0.0, so ROS refuses it.
    "tricycle_controller": "wheel_radius: override rejected: 0.0 is out of range",
}


@dataclass
class Loaded:
    imported: GplImported
    module: types.ModuleType
    schema_file: Path  # the imported genparams schema

    @property
    def params_cls(self) -> Any:
        return getattr(self.module, next(n for n in self.module.__all__ if n.endswith("Params")))


_LOADED: dict[Path, Loaded] = {}


def load(schema: Path, tmp_path_factory: pytest.TempPathFactory) -> Loaded:
    """Import, write, generate and import one schema (once per test session)."""
    if schema not in _LOADED:
        folder = tmp_path_factory.mktemp("gpl")
        document = load_yaml(schema.read_text(encoding="utf-8"), str(schema))
        checks = unique_name("checks")
        imported = import_gpl(document, checks, ADOPTED.get(schema.name, {}))
        text = schema_text(imported, schema.name)
        (folder / f"{imported.name}.yaml").write_text(text, encoding="utf-8")
        if imported.customs:
            (folder / f"{checks}.py").write_text(stub_text(imported, checks), encoding="utf-8")
            sys.path.insert(0, str(folder))
        module_name = unique_name(f"gen_{imported.name}")
        module_path = folder / f"{module_name}.py"
        module_path.write_text(genparams.generate(folder / f"{imported.name}.yaml"), "utf-8")
        module = import_file(module_path, module_name)
        _LOADED[schema] = Loaded(imported, module, folder / f"{imported.name}.yaml")
    return _LOADED[schema]


def _id(path: Path) -> str:
    return str(path.relative_to(CORPUS))


@pytest.mark.parametrize("schema", schemas(), ids=_id)
def test_every_parameter_is_imported(
    schema: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    loaded = load(schema, tmp_path_factory)
    assert loaded.imported.imported == loaded.imported.parameters > 0
    assert [str(w) for w in loaded.imported.warnings] == []


def _read(tree: dict[str, Any], name: str) -> Any:
    node: Any = tree
    for part in name.split("."):
        node = node[part]
    return node


@pytest.mark.parametrize("section", sections(), ids=lambda s: s.id)
def test_params_file_section_loads_with_equal_values(
    ros: RosHarness, section: Section, tmp_path_factory: pytest.TempPathFactory
) -> None:
    loaded = load(section.schema, tmp_path_factory)
    node = ros.node(section.node, args=["--params-file", str(section.params_file)])
    for name, value in ADOPTED.get(section.schema.name, {}).items():
        node.declare_parameter(name, value)  # as the node's own code does, first
    if section.params_file.name == MISSING_REQUIRED:
        with pytest.raises(ParameterDeclarationError, match="required parameter is not set"):
            loaded.params_cls.declare(node)
        return
    if section.node in REJECTED:
        with pytest.raises(ParameterDeclarationError) as refused:
            loaded.params_cls.declare(node)
        assert REJECTED[section.node] in str(refused.value)
        return
    cfg = loaded.params_cls.declare(node)
    tree = cfg.to_dict()
    # The same names GPL declares for these keys, with GPL's description and read_only.
    declared = gpl_declared(section.schema, lambda name: _value(node, name))
    added = set(loaded.imported.data["parameters"]) - set(_top_names(section.schema))
    ours = {n for n in node._parameters if n not in NODE_PARAMETERS} - added
    assert ours == set(declared)
    for name, leaf in declared.items():
        descriptor = node.describe_parameter(name)
        assert descriptor.description == leaf.get("description", ""), name
        assert descriptor.read_only == bool(leaf.get("read_only", False)), name
        bounds = (leaf.get("validation") or {}).get("bounds<>")
        if bounds is not None and not leaf["type"].endswith("array"):
            (ros_range,) = list(descriptor.floating_point_range) + list(descriptor.integer_range)
            assert (ros_range.from_value, ros_range.to_value) == tuple(bounds), name
    checked = 0
    for name, value in values_for(section).items():
        if not node.has_parameter(name) or name in ("use_sim_time",):
            continue  # not a parameter of this schema (another controller's, a plugin type)
        assert same(node.get_parameter(name).value, value), name
        assert same(_read(tree, name), value), name
        checked += 1
    assert checked or not values_for(section)


@pytest.mark.parametrize("section", sections(), ids=lambda s: s.id)
def test_params_file_section_passes_check_params(
    section: Section, tmp_path_factory: pytest.TempPathFactory
) -> None:
    """What loads on a node also passes the offline checks (and what is refused fails them)."""
    loaded = load(section.schema, tmp_path_factory)
    schema = genparams.load_schema(loaded.schema_file)
    document = read_params_file(section.params_file.read_text("utf-8"), str(section.params_file))
    report = check_params(schema, document, [f"/{section.node}"])
    if section.node in REJECTED:
        assert any(REJECTED[section.node].split(": ")[-1] in p.message for p in report.problems)
        return
    # Real files also configure other nodes, and keep keys their controllers no longer
    # read: check-params names those (ROS ignores them); every value it checks must pass.
    ignored = ("unknown parameter", "matches no node given by --node")
    problems = [str(p) for p in report.problems if not any(i in p.message for i in ignored)]
    if section.params_file.name == MISSING_REQUIRED:
        assert problems and all("required" in p for p in problems)
        return
    assert problems == []


def _value(node: Any, name: str) -> Any:
    return node.get_parameter(name).value if node.has_parameter(name) else None


def _top_names(gpl_file: Path) -> list[str]:
    ((_, tree),) = yaml.safe_load(gpl_file.read_text(encoding="utf-8")).items()
    return [key for key in tree if not key.startswith("__map_")]
