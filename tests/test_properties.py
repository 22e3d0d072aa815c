"""Property tests: random valid schemas generate code that compiles, types and holds its values.

Counts follow tests/budget.py (GENPARAMS_TEST_PROFILE=dev for a long run).
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import types
from pathlib import Path
from typing import Any

from hypothesis import given, settings
from rclpy.parameter import Parameter

import genparams
from genparams.runtime.tree import get_path
from tests.budget import examples
from tests.golden import ROOT
from tests.readback import mismatches, params_class, read_back, same
from tests.strategies import SchemaCase, python_attribute, schemas
from tests.support import RosHarness, import_file, unique_name

ROS_TYPES = {
    "bool": Parameter.Type.BOOL,
    "int": Parameter.Type.INTEGER,
    "double": Parameter.Type.DOUBLE,
    "string": Parameter.Type.STRING,
    "byte_array": Parameter.Type.BYTE_ARRAY,
    "bool_array": Parameter.Type.BOOL_ARRAY,
    "int_array": Parameter.Type.INTEGER_ARRAY,
    "double_array": Parameter.Type.DOUBLE_ARRAY,
    "string_array": Parameter.Type.STRING_ARRAY,
}


def import_case(case: SchemaCase, folder: Path) -> types.ModuleType:
    text = genparams.generate(f"{case.name}.yaml", case.text)
    assert genparams.generate(f"{case.name}.yaml", case.text) == text, "output is not stable"
    compile(text, f"{case.name}_params.py", "exec")
    path = folder / f"{unique_name(case.name)}_params.py"
    path.write_text(text, encoding="utf-8")
    return import_file(path)


def overrides(case: SchemaCase) -> dict[str, Any]:
    return {name: case.values[name] for name in case.required}


def ros_value(type_name: str, value: Any) -> Any:
    if type_name == "byte_array":
        return [bytes((b,)) for b in value]
    return list(value) if isinstance(value, tuple) else value


@settings(max_examples=examples(80))
@given(case=schemas())
def test_generated_module_holds_every_default(case: SchemaCase) -> None:
    with tempfile.TemporaryDirectory() as folder:
        cls = params_class(import_case(case, Path(folder)))
    snapshot = cls.defaults(overrides(case))
    for name, expected in case.values.items():
        path = tuple(python_attribute(part) for part in name.split("."))
        assert same(get_path(snapshot, path), expected), name


@settings(max_examples=examples(25))
@given(case=schemas())
def test_declared_values_read_back_through_cfg_node_and_service(
    ros_harness: RosHarness, case: SchemaCase
) -> None:
    with tempfile.TemporaryDirectory() as folder:
        cls = params_class(import_case(case, Path(folder)))
    given_values = [
        Parameter(name, ROS_TYPES[case.types[name]], ros_value(case.types[name], value))
        for name, value in overrides(case).items()
    ]
    node = ros_harness.node(parameter_overrides=given_values)
    try:
        cfg = cls.declare(node)
        assert mismatches(read_back(ros_harness, node, cfg), case.values) == {}
    finally:
        ros_harness.destroy_test_nodes()


def test_generated_modules_pass_mypy_strict_and_ruff(tmp_path: Path) -> None:
    """A batch of random modules, checked by one mypy run and one ruff run."""
    texts: dict[str, str] = {}

    @settings(max_examples=examples(40))
    @given(case=schemas())
    def collect(case: SchemaCase) -> None:
        texts[case.text] = genparams.generate(f"{case.name}.yaml", case.text)

    collect()
    for index, (schema_text, module_text) in enumerate(texts.items()):
        (tmp_path / f"m{index}_params.py").write_text(module_text, encoding="utf-8")
        (tmp_path / f"m{index}.yaml").write_text(schema_text, encoding="utf-8")
    config = str(ROOT / "pyproject.toml")
    checks = [
        ["mypy", "--strict", "--config-file", config, str(tmp_path)],
        ["ruff", "check", "--no-cache", "--config", config, str(tmp_path)],
        ["ruff", "format", "--check", "--no-cache", "--config", config, str(tmp_path)],
    ]
    for argv in checks:
        result = subprocess.run(
            [sys.executable, "-m", *argv], capture_output=True, text=True, timeout=300
        )
        assert result.returncode == 0, f"{argv[0]} in {tmp_path}:\n{result.stdout}{result.stderr}"
