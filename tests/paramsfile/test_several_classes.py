"""Several classes on one node: one defaults file and one JSON Schema for the node."""

from __future__ import annotations

import json
from pathlib import Path

import jsonschema
import pytest
import yaml

from genparams.api import load_schema
from genparams.cli import main
from tests.paramsfile.rcl_load import overrides, started
from tests.support import load_generated

SCHEMAS = Path(__file__).parent / "deployments" / "schemas"
LIBRARY = SCHEMAS / "steering_controllers_library.yaml"
BICYCLE = SCHEMAS / "bicycle_steering_controller.yaml"
FORWARD = SCHEMAS / "forward_command_controller.yaml"
NODE = "/robot/bicycle_steering_controller"


def _class(schema: Path, tmp_path: Path) -> type:
    return getattr(load_generated(schema, tmp_path), load_schema(schema).class_name)  # type: ignore[no-any-return]


@pytest.mark.parametrize(
    ("specs", "classes"),
    [
        ([str(LIBRARY), "--schema", str(BICYCLE)], [(LIBRARY, ""), (BICYCLE, "")]),
        (
            [f"{FORWARD}@fwd", "--schema", f"{BICYCLE}@bike.front"],
            [(FORWARD, "fwd"), (BICYCLE, "bike.front")],
        ),
    ],
    ids=["root", "prefixes"],
)
def test_one_defaults_file_loads_into_the_node(
    specs: list[str], classes: list[tuple[Path, str]], tmp_path: Path
) -> None:
    out = tmp_path / "defaults.yaml"
    assert main(["defaults", *specs, "--node", NODE, "-o", str(out)]) == 0
    args = ["--params-file", str(out)]
    # Every node can load it, one that declares whatever it is given too.
    assert overrides(NODE, args)
    loaded = [(_class(schema, tmp_path), prefix) for schema, prefix in classes]
    values = started(NODE, args, loaded)
    assert values is not None
    for params_class, prefix in loaded:
        defaults = params_class.defaults().to_dict()  # type: ignore[attr-defined]
        for name, value in defaults.items():
            full = f"{prefix}.{name}" if prefix else name
            assert values[full] == (list(value) if isinstance(value, tuple) else value), full


def test_one_json_schema_for_the_node(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["json-schema", str(LIBRARY), "--schema", str(BICYCLE)]) == 0
    document = json.loads(capsys.readouterr().out)
    good = yaml.safe_load(f"{NODE}:\n  ros__parameters:\n    wheelbase: 2.5\n    open_loop: true\n")
    jsonschema.validate(good, document)
    typo = yaml.safe_load(f"{NODE}:\n  ros__parameters:\n    wheelbse: 2.5\n")
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(typo, document)


def test_two_classes_declaring_one_name_are_refused(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["defaults", str(BICYCLE), "--schema", str(BICYCLE)]) == 2
    assert "both declare front_wheel_radius" in capsys.readouterr().err
