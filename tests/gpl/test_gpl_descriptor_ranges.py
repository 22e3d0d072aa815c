"""What GPL's Python module gives a node, for shapes its users write: the descriptor range
of `gt<>`, `gt_eq<>`, `lt<>`, `lt_eq<>`, `bounds<>` and the element bounds on int and double
parameters and arrays, a key list of `[""]`, NaN items against element bounds, and custom
validators in GPL's Python convention.

The expected ranges are not computed here: they are what GPL's own generated Python module
declared on a real rclpy node, recorded once as literal data (see GPL_DECLARED).
"""

from __future__ import annotations

import math
import sys
import textwrap
import types
from pathlib import Path
from typing import Any

import pytest
from rclpy.parameter import Parameter

import genparams
from genparams.gpl.convert import GplImported, import_gpl
from genparams.gpl.emit import schema_text, stub_text
from genparams.schema.errors import SchemaError
from genparams.schema.loader import load_yaml
from tests.support import RosHarness, import_file, unique_name

# (GPL type, default, validation as written in a GPL file)
SHAPES: dict[str, tuple[str, str, str]] = {
    "d_gt": ("double", "1.0", "gt<>: [0.5]"),
    "d_gt_zero": ("double", "1.0", "gt<>: [0.0]"),
    "d_gt_int_limit": ("double", "1.0", "gt<>: [0]"),
    "d_gt_negative": ("double", "1.0", "gt<>: [-2.5]"),
    "d_gt_large": ("double", "2000000000.0", "gt<>: [1000000000.0]"),
    "d_gt_eq": ("double", "1.0", "gt_eq<>: [0.0]"),
    "d_gt_eq_two": ("double", "3.0", "gt_eq<>: [2.0]"),
    "d_lt": ("double", "1.0", "lt<>: [2.0]"),
    "d_lt_zero": ("double", "-1.0", "lt<>: [0.0]"),
    "d_lt_eq": ("double", "1.0", "lt_eq<>: [15.0]"),
    "d_bounds": ("double", "1.0", "bounds<>: [0.0, 5.0]"),
    "d_gt_lt_eq": ("double", "16.0", "{gt<>: [15.0], lt_eq<>: [20.0]}"),
    "d_gt_lt": ("double", "0.5", "{gt<>: [0.0], lt<>: [1.0]}"),
    "i_gt": ("int", "5", "gt<>: [0]"),
    "i_gt_eq": ("int", "5", "gt_eq<>: [2]"),
    "i_lt": ("int", "5", "lt<>: [20]"),
    "i_lt_eq": ("int", "5", "lt_eq<>: [15]"),
    "i_bounds": ("int", "5", "bounds<>: [0, 100]"),
    "i_gt_lt": ("int", "16", "{gt<>: [15], lt<>: [20]}"),
    "i_gt_eq_lt_eq": ("int", "3", "{gt_eq<>: [-4], lt_eq<>: [4]}"),
    "i_size_gt_only": ("int_array", "[1]", "size_gt<>: [0]"),
    "da_lower": ("double_array", "[1.0]", "lower_element_bounds<>: [0.0]"),
    "da_upper": ("double_array", "[1.0]", "upper_element_bounds<>: [3.0]"),
    "da_both": (
        "double_array",
        "[1.0]",
        "{lower_element_bounds<>: [-1.0], upper_element_bounds<>: [1.0]}",
    ),
    "da_element_bounds": ("double_array", "[0.5]", "element_bounds<>: [0.1, 10.0]"),
    "ia_lower": ("int_array", "[1]", "lower_element_bounds<>: [0]"),
    "ia_upper": ("int_array", "[1]", "upper_element_bounds<>: [7]"),
    "ia_element_bounds": ("int_array", "[1]", "element_bounds<>: [0, 9]"),
    "s_not_numeric": ("string", "a", "not_empty<>: []"),
}

# The range (from_value, to_value; step 0) of each shape's descriptor as GPL's generated
# Python module declares it, or None for no range. Recorded, not derived: the SHAPES
# alone were written as a GPL file (each parameter as _gpl_file writes it), GPL's Python
# generator (generate_parameter_library_py 1.2.0, commit 1f74d68, the commit the corpus
# was copied from) made its module with `python -m
# generate_parameter_library_py.generate_python_module OUT.py shapes.yaml`, its
# ParamListener was declared on a real rclpy (Jazzy) node, and node.describe_parameter
# gave these; the parameter services report the same. Integers are integer_range, the
# rest floating_point_range. GPL's C++ header declares other values (see
# docs/migrating-from-gpl.md, "Descriptor ranges"); genparams generates Python.
GPL_DECLARED: dict[str, tuple[float, float] | None] = {
    "d_gt": (0.5000000000000002, math.inf),
    "d_gt_zero": (2.220446049250313e-16, math.inf),
    "d_gt_int_limit": (2.220446049250313e-16, math.inf),
    "d_gt_negative": (-2.5, math.inf),
    "d_gt_large": (1000000000.0, math.inf),
    "d_gt_eq": (0.0, math.inf),
    "d_gt_eq_two": (2.0, math.inf),
    "d_lt": (-math.inf, 1.9999999999999998),
    "d_lt_zero": (-math.inf, -2.220446049250313e-16),
    "d_lt_eq": (-math.inf, 15.0),
    "d_bounds": (0.0, 5.0),
    "d_gt_lt_eq": (15.0, 20.0),
    "d_gt_lt": (2.220446049250313e-16, 0.9999999999999998),
    "i_gt": (1, 2147483647),
    "i_gt_eq": (2, 2147483647),
    "i_lt": (-2147483649, 19),
    "i_lt_eq": (-2147483649, 15),
    "i_bounds": (0, 100),
    "i_gt_lt": (16, 19),
    "i_gt_eq_lt_eq": (-4, 4),
    "i_size_gt_only": None,
    "da_lower": (0.0, math.inf),
    "da_upper": (-math.inf, 3.0),
    "da_both": (-1.0, 1.0),
    "da_element_bounds": (0.1, 10.0),
    "ia_lower": (0, 2147483647),
    "ia_upper": (-2147483649, 7),
    "ia_element_bounds": (0, 9),
    "s_not_numeric": None,
}


def _gpl_file(tmp_path: Path) -> Path:
    lines = ["shapes:", "  joints:", "    type: string_array", '    default_value: [""]']
    lines += ["    description: the joints, none by default as GPL users write it"]
    lines += ["  gains:", "    __map_joints:", "      p:", "        type: double"]
    lines += ["        default_value: 1.0", "        validation:", "          gt_eq<>: [0.0]"]
    lines += ["  check:", "    type: double", "    default_value: 1.0", "    validation:"]
    lines += ['      "shapes_checks::positive_or_empty": null']
    for name, (gpl_type, default, validation) in SHAPES.items():
        lines += [f"  {name}:", f"    type: {gpl_type}", f"    default_value: {default}"]
        lines += [f"    validation: {validation if validation.startswith('{') else ''}"]
        if not validation.startswith("{"):
            lines += [f"      {validation}"]
    path = tmp_path / "shapes.yaml"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def imported(tmp_path_factory: pytest.TempPathFactory) -> tuple[GplImported, types.ModuleType]:
    folder = tmp_path_factory.mktemp("gpl_shapes")
    source = _gpl_file(folder)
    checks = unique_name("shapes_checks")
    result = import_gpl(load_yaml(source.read_text("utf-8"), str(source)), checks)
    assert [str(w) for w in result.warnings] == []
    schema = folder / "shapes.yaml"
    schema.write_text(schema_text(result, source.name), encoding="utf-8")
    stub = stub_text(result, checks).replace(
        "    return None",
        '    return "" if value > 0 else "must be positive"',  # GPL's Python convention
    )
    (folder / f"{checks}.py").write_text(stub, encoding="utf-8")
    sys.path.insert(0, str(folder))
    module_name = unique_name("gen_shapes")
    (folder / f"{module_name}.py").write_text(genparams.generate(schema), encoding="utf-8")
    return result, import_file(folder / f"{module_name}.py", module_name)


def _declared(ros: RosHarness, module: types.ModuleType) -> Any:
    node = ros.node()
    module.ShapesParams.declare(node)
    return node


def test_every_shape_has_a_recorded_range() -> None:
    assert set(GPL_DECLARED) == set(SHAPES)


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_converted_range_is_gpls(imported: tuple[GplImported, types.ModuleType], name: str) -> None:
    """The schema's range (a number) or element bounds (an array) hold GPL's numbers."""
    leaf = imported[0].data["parameters"][name]
    expected = GPL_DECLARED[name]
    if leaf["type"].endswith("_array"):
        bounds = [v for v in leaf.get("validators", []) if "element_bounds" in v]
        found: Any = [_element_limits(b["element_bounds"]) for b in bounds]
    else:
        found = [(leaf["range"]["min"], leaf["range"]["max"])] if "range" in leaf else []
    assert found == ([] if expected is None else [expected])


def _element_limits(bounds: Any) -> tuple[float, float]:
    return (bounds["min"], bounds["max"]) if isinstance(bounds, dict) else tuple(bounds)


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_descriptor_range_is_gpls(
    ros: RosHarness, imported: tuple[GplImported, types.ModuleType], name: str
) -> None:
    node = _declared(ros, imported[1])
    descriptor = node.describe_parameter(name)
    ranges = [*descriptor.integer_range, *descriptor.floating_point_range]
    expected = GPL_DECLARED[name]
    if expected is None:
        assert ranges == []
        return
    (ros_range,) = ranges
    assert (ros_range.from_value, ros_range.to_value, ros_range.step) == (*expected, 0)
    kind = "int" if SHAPES[name][0].startswith("int") else "double"
    assert bool(descriptor.integer_range) == (kind == "int")


def test_strict_bounds_still_refuse_their_limit(
    ros: RosHarness, imported: tuple[GplImported, types.ModuleType]
) -> None:
    """ROS lets a value within 1e-6 of a range's edge pass; GPL's own check refuses it."""
    node = _declared(ros, imported[1])
    client = ros.client(node)
    refused = client.set(
        Parameter("d_gt", Parameter.Type.DOUBLE, 0.5),
        Parameter("d_lt_eq", Parameter.Type.DOUBLE, 15.000001),
        Parameter("i_gt", Parameter.Type.INTEGER, 0),
    )
    assert [r.successful for r in refused] == [False, False, False]
    accepted = client.set(
        Parameter("d_gt", Parameter.Type.DOUBLE, 0.6),
        Parameter("i_lt_eq", Parameter.Type.INTEGER, 15),
    )
    assert [r.successful for r in accepted] == [True, True]


def test_nan_items_pass_element_bounds_as_in_gpl(
    ros: RosHarness, imported: tuple[GplImported, types.ModuleType]
) -> None:
    node = _declared(ros, imported[1])
    client = ros.client(node)
    nan_items = client.set(
        Parameter("da_lower", Parameter.Type.DOUBLE_ARRAY, [math.nan, 2.0]),
        Parameter("da_element_bounds", Parameter.Type.DOUBLE_ARRAY, [math.nan]),
    )
    assert [r.successful for r in nan_items] == [True, True]
    (below,) = client.set(Parameter("da_lower", Parameter.Type.DOUBLE_ARRAY, [math.nan, -1.0]))
    assert not below.successful and "item 1" in below.reason


def test_key_list_of_one_empty_string_imports_as_no_keys(
    ros: RosHarness, imported: tuple[GplImported, types.ModuleType]
) -> None:
    result, module = imported
    assert result.data["parameters"]["joints"]["default"] == []
    note = next(str(n) for n in result.notes if "joints" in str(n))
    assert note.endswith('note: a key list of [""] means no keys: imported as []')
    node = ros.node(args=["-p", "joints:=[a]", "-p", "gains.a.p:=2.0"])
    cfg = module.ShapesParams.declare(node)
    assert node.get_parameter("gains.a.p").value == 2.0
    assert list(cfg.joints) == ["a"]


def test_custom_validator_in_gpls_python_convention(
    ros: RosHarness, imported: tuple[GplImported, types.ModuleType]
) -> None:
    """A check returning "" accepts (GPL's Python convention); any other text refuses."""
    result, module = imported
    assert "An empty string also means\nvalid" in stub_text(result, "m")
    node = _declared(ros, module)
    client = ros.client(node)
    (ok,) = client.set(Parameter("check", Parameter.Type.DOUBLE, 3.0))
    (refused,) = client.set(Parameter("check", Parameter.Type.DOUBLE, -3.0))
    assert ok.successful
    assert not refused.successful and "must be positive" in refused.reason


def test_top_level_key_list_message_names_the_top_level(tmp_path: Path) -> None:
    schema = tmp_path / "top.yaml"
    schema.write_text(
        textwrap.dedent(
            """\
            genparams: 1
            name: top
            parameters:
              joints: {type: string_array, default: ["a b"]}
              "*": {for_each: joints, gain: {type: double, default: 1.0}}
            """
        ),
        encoding="utf-8",
    )
    with pytest.raises(SchemaError) as error:
        genparams.load_schema(schema)
    assert "cannot name an entry of the top level" in str(error.value)
