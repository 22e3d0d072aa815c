"""How the mutation sample reads its records of killed mutants (tests/mutate.py)."""

from __future__ import annotations

from tests.mutate import function_of, runnable, sibling_tests


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
