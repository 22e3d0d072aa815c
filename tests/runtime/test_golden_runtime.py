"""Every golden module, imported and declared on a real node, reads back its defaults.

A case may hold ``overrides.yaml`` (relative name -> value) for its required and
optional parameters; those values must read back too (an optional one not given: None).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml

from genparams.runtime.core.entries import expand
from genparams.runtime.core.spec import compile_schema
from genparams.runtime.core.tree import get_path
from genparams.runtime.core.types import TYPES
from genparams.runtime.node.declaring import ros_parameter
from tests.golden import runtime_cases
from tests.readback import mismatches, params_class, read_back
from tests.support import RosHarness, import_file


def overrides(case: Path) -> dict[str, Any]:
    path = case / "overrides.yaml"
    data = yaml.safe_load(path.read_text(encoding="utf-8")) if path.exists() else {}
    assert isinstance(data, dict)
    return data


@pytest.mark.parametrize("case", runtime_cases(), ids=lambda case: case.name)
def test_golden_module_declares_and_reads_back(ros: RosHarness, case: Path) -> None:
    cls = params_class(import_file(case / "expected_params.py"))
    compiled = compile_schema(cls._SPEC)
    given = overrides(case)
    expected: dict[str, Any] = {}
    for name, param in compiled.parameters.items():
        param_type = TYPES[param.spec.type]
        if param.spec.optional and name not in given:
            expected[name] = None  # declared by type only: not set
            continue
        source = given[name] if name in given else param.spec.default
        expected[name] = param_type.coerce_default(source)
    for name, entry in expand(compiled, expected).items():  # entries of mapped groups
        expected[name] = TYPES[entry.spec.type].coerce_default(entry.spec.default)
    parameters = [ros_parameter(compiled.parameters[name], name, expected[name]) for name in given]
    node = ros.node(parameter_overrides=parameters)
    cfg = cls.declare(node)
    # A parameter whose condition (when) does not hold is not declared, and reads None.
    left_out = [n for n, p in compiled.parameters.items() if not p.spec.declared_with(expected)]
    assert [get_path(cfg, compiled.parameters[n].attribute_path) for n in left_out] == [
        None for _ in left_out
    ]
    assert not any(node.has_parameter(name) for name in left_out)
    declared = {n: v for n, v in expected.items() if n not in left_out}
    assert mismatches(read_back(ros, node, cfg), declared) == {}
    assert cls.defaults(given).to_dict() == cfg.to_dict()
