"""docs/architecture.md names files, functions and classes that exist.

Every repository path the page names (``genparams/...``, ``tests/...``, ``docs/...``,
``schemas/...``) must exist, and in its "To change X, open Y" table every name that
follows a Python file must be defined in that file: a top-level function or class, or
``Class.method``.
"""

from __future__ import annotations

import ast
import re
from functools import cache
from pathlib import Path

from tests.support import ROOT

PAGE = ROOT / "docs" / "architecture.md"
_PATH = re.compile(r"\b(?:genparams|tests|docs|schemas)/[\w./-]*\w")
_CODE = re.compile(r"`([^`]+)`")


def page_text() -> str:
    return PAGE.read_text(encoding="utf-8")


def table_rows() -> list[tuple[str, str]]:
    """(what to change, where to look) for each row of the "To change X, open Y" table."""
    section = page_text().split("## To change X, open Y", 1)[1].split("\n## ", 1)[0]
    rows = []
    for line in section.splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if len(cells) == 2 and line.startswith("| ") and not cells[1].startswith("---"):
            rows.append((cells[0], cells[1]))
    return rows[1:]  # the header


def named_in(where: str) -> list[tuple[str, list[str]]]:
    """Each path in a cell, with the names that follow it up to the next path."""
    found: list[tuple[str, list[str]]] = []
    for code in _CODE.findall(where):
        if _PATH.fullmatch(code):
            found.append((code, []))
        elif found and re.fullmatch(r"[A-Za-z_]\w*(\.[A-Za-z_]\w*)?", code):
            found[-1][1].append(code)
    return found


@cache
def definitions(path: Path) -> frozenset[str]:
    """Top-level functions and classes of a module, and ``Class.method`` of its classes."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names = set()
    for node in tree.body:
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
            names.add(node.name)
        if isinstance(node, ast.ClassDef):
            names.update(
                f"{node.name}.{item.name}"
                for item in node.body
                if isinstance(item, ast.FunctionDef | ast.AsyncFunctionDef)
            )
        if isinstance(node, ast.Assign | ast.AnnAssign):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names.update(t.id for t in targets if isinstance(t, ast.Name))
    return frozenset(names)


def js_definitions(path: Path) -> frozenset[str]:
    text = path.read_text(encoding="utf-8")
    return frozenset(re.findall(r"\b(?:function|class|const|let)\s+([A-Za-z_]\w*)", text))


def test_every_path_the_page_names_exists() -> None:
    paths = set(_PATH.findall(page_text()))
    assert len(paths) > 20  # the table and the sections name many
    missing = sorted(p for p in paths if not (ROOT / p).exists())
    assert missing == []


def test_the_table_answers_the_questions_it_promises() -> None:
    asked = {what for what, _ in table_rows()}
    for question in (
        "how a set is validated",
        "how a params file is read",
        "what the tune page shows",
        "how a schema key is added",
        "how a validator is added",
        "how a command reports errors",
    ):
        assert question in asked


def test_every_name_in_the_table_is_defined_where_it_says() -> None:
    checked = 0
    wrong = []
    for _, where in table_rows():
        for path, names in named_in(where):
            file = ROOT / path
            assert file.exists(), path
            if file.suffix == ".py":
                defined = definitions(file)
            elif file.suffix == ".js":
                defined = js_definitions(file)
            else:
                assert names == [], f"{path} is not code, yet names {names}"
                continue
            wrong += [f"{path}: {name}" for name in names if name not in defined]
            checked += len(names)
    assert checked > 20
    assert wrong == []


def test_the_checks_catch_a_wrong_name(tmp_path: Path) -> None:
    module = tmp_path / "module.py"
    module.write_text("class Kept:\n    def method(self): ...\n\ndef function(): ...\n")
    assert {"Kept", "Kept.method", "function"} <= definitions(module)
    assert "Kept.gone" not in definitions(module)
    cell = "`genparams/cli.py` `main`; `docs/cli.md`; `genparams/errors.py` `CommandError`"
    assert named_in(cell) == [
        ("genparams/cli.py", ["main"]),
        ("docs/cli.md", []),
        ("genparams/errors.py", ["CommandError"]),
    ]
