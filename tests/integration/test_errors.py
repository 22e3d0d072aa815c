"""One error model: every error genparams defines is a GenparamsError, and problems read alike."""

from __future__ import annotations

import importlib
import inspect
import pkgutil

import pytest
from rclpy.exceptions import ParameterImmutableException

import genparams
from genparams.audit.findings import DRIFT_DEFAULT, VIOLATION, Finding
from genparams.errors import (
    CommandError,
    GenparamsError,
    ParameterProblem,
    render_problem,
    render_problems,
)
from genparams.runtime.node.consistency import UndeclareRefusedError
from genparams.schema.errors import Location, SchemaError, SchemaProblem


def genparams_exceptions() -> list[type[BaseException]]:
    found = []
    for module_info in pkgutil.walk_packages(genparams.__path__, "genparams."):
        if module_info.name.endswith("__main__"):  # runs the command
            continue
        module = importlib.import_module(module_info.name)
        for _, value in inspect.getmembers(module, inspect.isclass):
            if issubclass(value, BaseException) and value.__module__ == module.__name__:
                found.append(value)
    return found


def test_every_error_genparams_defines_is_a_genparams_error() -> None:
    exceptions = genparams_exceptions()
    assert len(exceptions) >= 15
    assert [e.__qualname__ for e in exceptions if not issubclass(e, GenparamsError)] == []


def test_errors_keep_the_kinds_users_catch() -> None:
    from genparams.runtime.core.errors import RemoteParameterError
    from genparams.runtime.core.types import ValueTypeError

    assert issubclass(UndeclareRefusedError, ParameterImmutableException)
    assert issubclass(RemoteParameterError, RuntimeError)
    assert issubclass(ValueTypeError, ValueError)


def test_one_record_and_one_renderer_from_the_runtime_up() -> None:
    from genparams.runtime.core import problems

    assert genparams.render_problem is render_problem is problems.render_problem
    assert genparams.ParameterProblem is ParameterProblem is problems.ParameterProblem


def test_the_package_root_exports_the_errors() -> None:
    for name in (
        "GenparamsError",
        "SchemaError",
        "ParameterDeclarationError",
        "RemoteParameterError",
        "RemoteSetError",
        "CommandError",
    ):
        error = getattr(genparams, name)
        assert name in genparams.__all__
        assert issubclass(error, genparams.GenparamsError)


def test_problems_render_one_way() -> None:
    problem = SchemaProblem(Location("p.yaml", 3, 5), "camera.fps", "500.0 is out of range")
    assert (
        str(problem) == render_problem(problem) == "p.yaml:3:5: camera.fps: 500.0 is out of range"
    )
    assert str(SchemaProblem(Location("p.yaml", 1, 1), "", "empty")) == "p.yaml:1:1: empty"
    finding = Finding("/cam", DRIFT_DEFAULT, "fps", "differs from the schema default", 30, 15)
    assert finding.text() == (
        "/cam: fps: differs from the schema default (expected 30, found 15) [drift-from-default]"
    )
    hidden = Finding("/cam", VIOLATION, "gain\u200b", "refused")
    assert hidden.text() == "/cam: gain\\u200b: refused [violation]"
    refused = ParameterProblem("camera.fps", "must be > 0 (gt), got -1")
    assert str(refused) == render_problem(refused) == "camera.fps: must be > 0 (gt), got -1"
    rule = ParameterProblem("", "rule 'order' broken: min <= max is false for min=2, max=1")
    assert render_problems([refused, rule]) == (
        "camera.fps: must be > 0 (gt), got -1; "
        "rule 'order' broken: min <= max is false for min=2, max=1"
    )
    assert render_problem(ParameterProblem("x", "got 'a\u3164'", rule="r", place="/n")) == (
        "/n: x: got 'a\\u3164' [r]"
    )


def test_a_command_error_shows_every_character_and_keeps_lines_of_errors() -> None:
    schema_error = SchemaError(
        [
            SchemaProblem(Location("s.yaml", 1, 1), "a", "one"),
            SchemaProblem(Location("s.yaml", 2, 1), "b", "two"),
        ]
    )
    error = CommandError(schema_error, "node 'a\nb\u202e' is wrong", exit_code=2)
    assert str(error).split("\n") == [
        "s.yaml:1:1: a: one",
        "s.yaml:2:1: b: two",
        "node 'a\\nb\\u202e' is wrong",
    ]
    assert error.exit_code == 2


def test_an_error_a_command_lets_through_is_reported_with_exit_2(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    from genparams.cli import main
    from genparams.commands import validate

    def unwrapped(args: object) -> int:
        raise SchemaError([SchemaProblem(Location("s.yaml", 3, 5), "gain", "must be a number")])

    monkeypatch.setattr(validate, "run", unwrapped)
    assert main(["validate", "s.yaml"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert "s.yaml:3:5: gain: must be a number" in captured.err
    assert "Traceback" not in captured.err
