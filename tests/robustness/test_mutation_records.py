"""How the mutation sample reads its records of killed mutants (tests/mutate.py)."""

from __future__ import annotations

from tests.mutate import function_of, read_records, rerecorded, runnable, sibling_tests


def test_an_id_cut_inside_its_parameters_stands_for_its_function() -> None:
    whole = "tests/a.py::test_x[1-two words]"
    assert runnable(whole) == whole
    assert runnable("tests/a.py::test_x[1-two") == "tests/a.py::test_x"
    assert runnable("tests/a.py::test_y") == "tests/a.py::test_y"


def test_a_mutant_belongs_to_the_function_it_changes() -> None:
    assert function_of("genparams.m.x_same__mutmut_30") == "genparams.m.x_same"
    assert function_of("genparams.m.xǁGroupǁ__repr____mutmut_4") == "genparams.m.xǁGroupǁ__repr__"


def test_siblings_are_the_other_tests_of_the_same_function() -> None:
    recorded = {
        "m.x_f__mutmut_1": ("h", "tests/a.py::test_one"),
        "m.x_f__mutmut_2": ("h", "tests/a.py::test_two"),
        "m.x_f__mutmut_3": ("h", "tests/a.py::test_two"),
        "m.x_f__mutmut_4": ("h", "tests/a.py::test_one"),
        "m.x_f2__mutmut_1": ("h", "tests/a.py::test_other_function"),
    }
    assert sibling_tests("m.x_f__mutmut_1", recorded) == ["tests/a.py::test_two"]
    assert sibling_tests("m.x_f2__mutmut_1", recorded) == []


def test_records_are_read_with_their_hash_and_test() -> None:
    text = "# header\nm.x_f__mutmut_1 h1 tests/a.py::test_x[a b]\nm.x_f__mutmut_2 h1\n\n"
    assert read_records(text) == {"m.x_f__mutmut_1": ("h1", "tests/a.py::test_x[a b]")}


def test_a_module_recorded_again_keeps_only_what_still_holds() -> None:
    old = {
        "m.x_f__mutmut_1": ("old", "tests/a.py::test_one"),  # f changed: renumbered
        "m.x_g__mutmut_1": ("g", "tests/a.py::test_g"),  # not checked yet, g unchanged
        "m.x_h__mutmut_1": ("old", "tests/a.py::test_h"),  # not checked yet, h changed
        "m.x_g__mutmut_2": ("g", "tests/a.py::test_g"),  # survives now
        "m.x_gone__mutmut_1": ("x", "tests/a.py::test_gone"),  # its function went
    }
    codes = {
        "m.x_f__mutmut_1": 1,
        "m.x_f__mutmut_2": 1,  # killed, but no test recorded as failing first
        "m.x_g__mutmut_1": None,
        "m.x_g__mutmut_2": 0,
        "m.x_h__mutmut_1": None,
        "m.x_h__mutmut_2": 37,  # refused by mypy: not a kill a test can repeat
    }
    hashes = {name: name.split("_")[1] for name in codes}
    tests = {"m.x_f__mutmut_1": "tests/a.py::test_new", "m.x_h__mutmut_2": "tests/a.py::t"}
    assert rerecorded(old, codes, hashes, tests) == {
        "m.x_f__mutmut_1": ("f", "tests/a.py::test_new"),
        "m.x_g__mutmut_1": ("g", "tests/a.py::test_g"),
    }
