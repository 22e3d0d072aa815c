"""What GPL itself refuses, refused the same way by the imported schema or noted by the import.

GPL's Python module was run on real nodes with these files (generate_parameter_library_py
1.2.0, commit 1f74d68, declared with its ParamListener): a key list whose default is `[""]`
makes GPL declare the map's parameters for the key "" (`.first`, `.second`); when they have
no default its listener refuses every params-file section that leaves the list unset
(ParameterUninitializedException: "The parameter '.first' is not initialized"), and a section
that names a key but leaves one of its parameters unset ("'cp_1.second' is not initialized").
A section that sets the keys and their parameters loads.
"""

from __future__ import annotations

import types
from pathlib import Path

import pytest

from genparams.gpl.convert import GplImported, import_gpl
from genparams.gpl.emit import schema_text
from genparams.runtime.core.errors import ParameterDeclarationError
from genparams.schema.loader import load_yaml
from tests.support import RosHarness, load_generated, unique_name

PAIRS = """\
pairs:
  rate: {type: double, default_value: 100.0}
  collision_pairs_names: {type: string_array, default_value: [""], read_only: true}
  __map_collision_pairs_names:
    first: {type: string, validation: {not_empty<>: []}}
    second: {type: string, validation: {not_empty<>: []}}
  joints: {type: string_array, default_value: [""]}
  gains:
    __map_joints:
      p: {type: double, default_value: 1.0}
"""


def _import(text: str, tmp_path: Path) -> GplImported:
    source = tmp_path / "gpl.yaml"
    source.write_text(text, encoding="utf-8")
    return import_gpl(load_yaml(text, str(source)))


@pytest.fixture
def pairs(tmp_path: Path) -> tuple[GplImported, types.ModuleType]:
    imported = _import(PAIRS, tmp_path)
    schema = tmp_path / "pairs.yaml"
    schema.write_text(schema_text(imported, "gpl.yaml"), encoding="utf-8")
    return imported, load_generated(schema, tmp_path)


def test_a_key_list_of_one_empty_string_over_unset_parameters_is_required(
    pairs: tuple[GplImported, types.ModuleType],
) -> None:
    imported, _ = pairs
    parameters = imported.data["parameters"]
    assert parameters["collision_pairs_names"] == {"type": "string_array", "read_only": True}
    assert parameters["joints"]["default"] == []  # its map's parameters all have defaults
    notes = [str(n) for n in imported.notes]
    assert any(
        'collision_pairs_names.default_value: note: a key list of [""] over a map whose '
        "parameters are not all set by default"
        in note
        and "imported as a required parameter" in note
        for note in notes
    ), notes
    assert imported.warnings == ()


def _section(tmp_path: Path, node: str, body: str) -> Path:
    path = tmp_path / f"{unique_name('section')}.yaml"
    path.write_text(f"{node}:\n  ros__parameters:\n{body}", encoding="utf-8")
    return path


def test_sections_are_refused_and_loaded_as_gpls_listener_does(
    ros: RosHarness, pairs: tuple[GplImported, types.ModuleType], tmp_path: Path
) -> None:
    module = pairs[1]
    name = unique_name("pairs")
    unset = _section(tmp_path, name, "    rate: 10.0\n")
    with pytest.raises(ParameterDeclarationError, match="collision_pairs_names: required"):
        module.PairsParams.declare(ros.node(name, args=["--params-file", str(unset)]))
    half = _section(tmp_path, name, "    collision_pairs_names: [cp_1]\n    cp_1: {first: a}\n")
    with pytest.raises(ParameterDeclarationError, match=r"cp_1\.second: required"):
        module.PairsParams.declare(ros.node(name, args=["--params-file", str(half)]))
    whole = _section(
        tmp_path, name, "    collision_pairs_names: [cp_1]\n    cp_1: {first: a, second: b}\n"
    )
    loaded = ros.node(name, args=["--params-file", str(whole)])
    module.PairsParams.declare(loaded)
    assert loaded.get_parameter("cp_1.second").value == "b"


@pytest.mark.parametrize(
    ("validation", "words"),
    [
        ("{bounds<>: [0, 100], lt_eq<>: [10]}", "'bounds' beside gt/gt_eq/lt/lt_eq"),
        (
            "{element_bounds<>: [0, 9], lower_element_bounds<>: [1]}",
            "'element_bounds' beside lower_element_bounds/upper_element_bounds",
        ),
    ],
)
def test_a_combination_gpl_refuses_is_imported_with_a_note(
    tmp_path: Path, validation: str, words: str
) -> None:
    kind = "int_array" if "element" in validation else "int"
    default = "[5]" if kind == "int_array" else "5"
    text = f"c:\n  n:\n    type: {kind}\n    default_value: {default}\n"
    text += f"    validation: {validation}\n"
    imported = _import(text, tmp_path)
    (note,) = [str(n) for n in imported.notes]
    assert note.endswith(
        f"c.n.validation: note: GPL 1.0 and later refuse {words} (earlier ones warn): imported "
        "with each validation setting its side of the range in file order, as they did"
    )
    assert imported.warnings == ()
