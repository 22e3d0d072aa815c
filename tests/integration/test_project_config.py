"""[tool.genparams] in pyproject.toml: what it lists, and errors that name the key."""

from __future__ import annotations

from pathlib import Path

import pytest

from genparams.integration.project_config import (
    ProjectConfigError,
    find_pyproject,
    load_project_config,
)


def write(folder: Path, text: str) -> Path:
    path = folder / "pyproject.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_modules_resolve_against_the_pyproject_folder(tmp_path: Path) -> None:
    pyproject = write(
        tmp_path,
        '[project]\nname = "x"\n\n'
        '[[tool.genparams.modules]]\nschema = "config/a.yaml"\noutput = "src/pkg/a_params.py"\n\n'
        '[[tool.genparams.modules]]\nschema = "config/b.yaml"\noutput = "src/pkg/b_params.py"\n',
    )
    config = load_project_config(pyproject)
    assert config.root == tmp_path
    assert [(m.schema, m.output) for m in config.modules] == [
        (tmp_path / "config/a.yaml", tmp_path / "src/pkg/a_params.py"),
        (tmp_path / "config/b.yaml", tmp_path / "src/pkg/b_params.py"),
    ]


def test_nearest_pyproject_wins(tmp_path: Path) -> None:
    write(tmp_path, "")
    inner = tmp_path / "inner"
    (inner / "deep").mkdir(parents=True)
    write(inner, "")
    assert find_pyproject(inner / "deep") == inner / "pyproject.toml"
    assert find_pyproject(tmp_path) == tmp_path / "pyproject.toml"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('[project]\nname = "x"\n', "no [tool.genparams] table"),
        ("[tool.genparams]\n", "tool.genparams.modules: must be a non-empty array of tables"),
        (
            "[tool.genparams]\nmodule = []\n",
            "tool.genparams: unknown key 'module' (expected 'modules')",
        ),
        (
            '[[tool.genparams.modules]]\nschema = "a.yaml"\n',
            "tool.genparams.modules[0].output: must be a path string",
        ),
        (
            '[[tool.genparams.modules]]\nschema = "a.yaml"\noutput = "a_params.txt"\n',
            "tool.genparams.modules[0].output: must name a .py file, got 'a_params.txt'",
        ),
        (
            '[[tool.genparams.modules]]\nschema = "/abs/a.yaml"\noutput = "a.py"\n',
            "tool.genparams.modules[0].schema: must be relative to pyproject.toml",
        ),
        (
            '[[tool.genparams.modules]]\nschema = "a.yaml"\noutput = "a.py"\nout = "b.py"\n',
            "tool.genparams.modules[0]: unknown key 'out'",
        ),
        (
            '[[tool.genparams.modules]]\nschema = "a.yaml"\noutput = "pkg/a.py"\n'
            '[[tool.genparams.modules]]\nschema = "b.yaml"\noutput = "pkg/../pkg/a.py"\n',
            "tool.genparams.modules[1].output: 'pkg/../pkg/a.py' is also the output of modules[0]",
        ),
        ("[tool.genparams\n", "cannot read"),
    ],
)
def test_malformed_table_names_file_and_key(tmp_path: Path, text: str, message: str) -> None:
    pyproject = write(tmp_path, text)
    with pytest.raises(ProjectConfigError) as caught:
        load_project_config(pyproject)
    assert str(caught.value).startswith(f"{pyproject}: ")
    assert message in str(caught.value)


def test_every_problem_is_reported_at_once(tmp_path: Path) -> None:
    pyproject = write(
        tmp_path,
        '[[tool.genparams.modules]]\nschema = "a.yaml"\n'
        '[[tool.genparams.modules]]\noutput = "b.py"\n',
    )
    with pytest.raises(ProjectConfigError) as caught:
        load_project_config(pyproject)
    assert str(caught.value).splitlines() == [
        f"{pyproject}: tool.genparams.modules[0].output: must be a path string, "
        "relative to pyproject.toml",
        f"{pyproject}: tool.genparams.modules[1].schema: must be a path string, "
        "relative to pyproject.toml",
    ]
