"""Lists holding mappings, and files that are not mappings: read as rcl reads them.

Each file is read by genparams and loaded by rcl: the problems genparams reports
are exact, a file rcl refuses has at least one, and a file rcl loads gives the
node exactly the entries genparams reads (names, values and their places).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.paramsfile.params_reader import read_params_file
from tests.paramsfile.rcl_load import RclRefusedError, overrides

HEAD = "/a:\n  ros__parameters:\n"
CASES = {
    "not_a_mapping": (
        "- a\n- b\n",
        [
            "p.yaml:1:1: a params file is a mapping of node names to sections "
            "(/node_name: {ros__parameters: {...}})"
        ],
    ),
    "lists_in_a_mapping": (HEAD + "    v: [{k: [1, 2], m: [x]}]\n    w: 1\n", []),
    "a_list_after_a_mapping": (HEAD + "    v: [{k: 1}, [1, 2]]\n", []),
    "a_value_after_a_mapping": (HEAD + "    v: [{k: 1}, 2]\n", []),
    "two_mappings": (HEAD + "    v: [{k: [1]}, {m: [2]}]\n    w: 3\n", []),
    "nested_in_a_group": (HEAD + "    g:\n      v: [{k: {m: [1]}}]\n      w: 3\n", []),
    "a_mapping_after_a_value": (HEAD + "    v: [1, {k: 2}]\n", []),
    "mixed_types": (
        HEAD + "    v: [{k: [1, x]}]\n",
        ["p.yaml:3:17: v: a string in a list of integers: ROS refuses the file"],
    ),
    "no_value": (HEAD + "    v: [{k: }]\n", ["p.yaml:3:13: v: no value: ROS refuses the file"]),
    "a_list_where_a_key_belongs": (
        HEAD + "    v: [{k: [1]}, [2]]\n",
        ["p.yaml:3:19: v: a list where rcl expects a key: ROS refuses the file"],
    ),
}
PLACES = {
    "lists_in_a_mapping": [
        ("v.k", "3:10", "3:14"),
        ("v.m", "3:21", "3:25"),
        ("w", "4:5", "4:8"),
    ],
    "two_mappings": [("v.k.m", "3:20", "3:24"), ("w", "4:5", "4:8")],
    "a_mapping_after_a_value": [("v.k", "3:13", "3:9")],
}


@pytest.mark.parametrize(("text", "problems"), CASES.values(), ids=CASES.keys())
def test_rcl_and_genparams_read_the_same(text: str, problems: list[str], tmp_path: Path) -> None:
    document = read_params_file(text, "p.yaml")
    assert [str(p) for p in document.problems] == problems
    params = tmp_path / "p.yaml"
    params.write_text(text, encoding="utf-8")
    try:
        given = overrides("/a", ["--params-file", str(params)])
    except RclRefusedError:
        assert problems, "rcl refuses a file genparams passes"
        return
    assert not problems
    read = {e.name: e.value for s in document.sections for e in s.entries}
    assert read == given


@pytest.mark.parametrize(("case", "places"), PLACES.items(), ids=PLACES.keys())
def test_entries_keep_their_places(case: str, places: list[tuple[str, str, str]]) -> None:
    document = read_params_file(CASES[case][0], "p.yaml")
    assert [
        (e.name, str(e.key_location).removeprefix("p.yaml:"), str(e.value_location)[7:])
        for s in document.sections
        for e in s.entries
    ] == places


MISNAMED = {
    "in_a_group": (
        HEAD + "    g:\n      v: [{k: [1]}, {m: [2]}]\n      w: 3\n",
        "p.yaml:4:10: g.v: rcl reads this list of mappings as 'g.v.k.m' and then misnames the "
        "keys after it: write g.v.<key>: value, not a list",
        {"g.v.k.m": [2], "g.v.w": 3},
    ),
    "two_groups_deep": (
        HEAD + "    g:\n      h:\n        v: [{k: {m: [1]}}, {n: [2]}]\n        w: 3\n",
        "p.yaml:5:12: g.h.v: rcl reads this list of mappings as 'g.h.v.k.m.n' and then "
        "misnames the keys after it: write g.h.v.<key>: value, not a list",
        {"g.h.v.k.m.n": [2], "g.h.v.k.w": 3},
    ),
}


@pytest.mark.parametrize(("text", "problem", "given"), MISNAMED.values(), ids=MISNAMED.keys())
def test_a_list_that_shifts_the_names_after_it_is_reported(
    text: str, problem: str, given: dict[str, object], tmp_path: Path
) -> None:
    assert [str(p) for p in read_params_file(text, "p.yaml").problems] == [problem]
    params = tmp_path / "p.yaml"
    params.write_text(text, encoding="utf-8")
    assert overrides("/a", ["--params-file", str(params)]) == given
