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

import jsonschema
import yaml
from hypothesis import given, settings
from rclpy.parameter import Parameter

import genparams
from genparams.outputs.docs_model import FORMATS, docs_page
from genparams.outputs.json_schema import params_file_schema
from genparams.outputs.params_file import default_params_file
from genparams.outputs.render import render_docs, render_params_file
from genparams.paramsfile.check_params import check_params
from genparams.paramsfile.params_reader import read_params_file
from genparams.runtime.core.tree import get_path
from tests.budget import examples
from tests.golden import ROOT
from tests.readback import mismatches, params_class, read_back, same
from tests.strategies import SchemaCase, schemas
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
        assert same(get_path(snapshot, case.path(name)), expected), name


@settings(max_examples=examples(25))
@given(case=schemas())
def test_declared_values_read_back_through_cfg_node_and_service(
    ros_harness: RosHarness, case: SchemaCase
) -> None:
    """The schema's default params file is loaded too (--params-file): it changes nothing."""
    with tempfile.TemporaryDirectory() as folder:
        cls = params_class(import_case(case, Path(folder)))
        defaults_file = Path(folder) / "defaults.yaml"
        schema = genparams.load_schema(f"{case.name}.yaml", case.text)
        defaults_file.write_text(render_params_file(default_params_file(schema)), "utf-8")
        given_values = [
            Parameter(name, ROS_TYPES[case.types[name]], ros_value(case.types[name], value))
            for name, value in overrides(case).items()
        ]
        node = ros_harness.node(
            args=["--params-file", str(defaults_file)], parameter_overrides=given_values
        )
    try:
        cfg = cls.declare(node)
        assert mismatches(read_back(ros_harness, node, cfg), case.values) == {}
    finally:
        ros_harness.destroy_test_nodes()


@settings(max_examples=examples(40))
@given(case=schemas())
def test_docs_defaults_file_and_json_schema_agree(case: SchemaCase) -> None:
    """Docs render; the defaults file passes the JSON Schema and check-params.

    Required parameters have no default, so the file leaves them out: they are
    the only thing either check may report.
    """
    schema = genparams.load_schema(f"{case.name}.yaml", case.text)
    for format in FORMATS:
        assert render_docs(docs_page(schema), format).strip()
    text = render_params_file(default_params_file(schema))
    validator = jsonschema.Draft202012Validator(params_file_schema(schema))
    errors = list(validator.iter_errors(yaml.safe_load(text)))
    if case.required:  # reported as "required", or "anyOf" (nested or dotted) below the top
        assert errors and {e.validator for e in errors} <= {"required", "anyOf"}, errors
    else:
        assert errors == []
    report = check_params(schema, read_params_file(text, "defaults.yaml"))
    assert {p.key for p in report.problems} == set(case.required), report.problems


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
            [sys.executable, "-m", *argv], cwd=tmp_path, capture_output=True, text=True, timeout=300
        )
        assert result.returncode == 0, f"{argv[0]} in {tmp_path}:\n{result.stdout}{result.stderr}"
