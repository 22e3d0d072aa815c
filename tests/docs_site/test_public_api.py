"""The public API is what docs/public-api.md lists, and docs and examples use nothing else.

The page is the one list: its Python blocks are read here, every name in them is
imported, and every genparams import in docs/, examples/ and the README must be one
of them.
"""

from __future__ import annotations

import ast
import importlib
import re
import warnings
from collections.abc import Iterator
from pathlib import Path

import pytest

import genparams
import genparams.runtime
from tests.docs_site.pages import DOCS, README, blocks
from tests.support import ROOT

pytestmark = pytest.mark.docs

PAGE = DOCS / "public-api.md"
# An import line inside text that may not parse as a whole (a Markdown block with `...`).
_IMPORT_LINE = re.compile(
    r"^\s*(?:from\s+(?P<module>[\w.]+)\s+import\s+(?P<names>[\w, ]+)|import\s+(?P<plain>[\w.]+))",
    re.MULTILINE,
)


def imports_in(source: str) -> Iterator[tuple[str, str | None]]:
    """(module, name) for each `from module import name`; (module, None) for `import module`."""
    try:
        tree = ast.parse(source)
    except SyntaxError:
        for match in _IMPORT_LINE.finditer(source):
            if match["plain"]:
                yield match["plain"], None
            else:
                for name in match["names"].split(","):
                    if name.strip():
                        yield match["module"], name.strip().split()[0]
        return
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            for alias in node.names:
                yield node.module, alias.name
        elif isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name, None


def python_blocks(page: Path) -> list[str]:
    return [b.body for b in blocks(page.read_text(encoding="utf-8")) if b.lang == "python"]


def documented() -> dict[str, set[str]]:
    """Each public module the page lists, with the names it lists from it."""
    names: dict[str, set[str]] = {}
    for body in python_blocks(PAGE):
        for module, name in imports_in(body):
            names.setdefault(module, set())
            if name is not None:
                names[module].add(name)
    return names


def test_the_page_lists_the_root_and_the_runtime() -> None:
    listed = documented()
    assert listed["genparams"] == set(genparams.__all__)
    assert listed["genparams.runtime"] == set(genparams.runtime.__all__)
    assert sum(map(len, listed.values())) > 25


@pytest.mark.parametrize(
    ("module", "name"),
    sorted((module, name) for module, names in documented().items() for name in names),
)
def test_every_documented_name_imports_without_warning(module: str, name: str) -> None:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert getattr(importlib.import_module(module), name) is not None
    # Others' warnings (setuptools' own) are theirs; none may be a genparams deprecation.
    assert [str(w.message) for w in caught if "genparams" in str(w.message)] == []


def user_code() -> Iterator[tuple[str, str]]:
    """(where, source) of every Python file and Python block in docs/, examples/, the README."""
    for path in sorted([*DOCS.rglob("*.py"), *(ROOT / "examples").rglob("*.py")]):
        if not {"build", "install", "log"} & set(path.relative_to(ROOT).parts):
            yield str(path.relative_to(ROOT)), path.read_text(encoding="utf-8")
    for page in [README, *sorted(DOCS.glob("*.md"))]:
        for number, body in enumerate(python_blocks(page)):
            yield f"{page.relative_to(ROOT)} block {number}", body


def private_imports(where: str, source: str, public: dict[str, set[str]]) -> list[str]:
    found = []
    for module, name in imports_in(source):
        if module.split(".")[0] != "genparams":
            continue
        if module not in public or (name is not None and name not in public[module]):
            found.append(f"{where}: {module}" + (f" {name}" if name else ""))
    return found


def test_docs_and_examples_import_public_paths_only() -> None:
    public = documented()
    sources = list(user_code())
    assert len(sources) > 20
    offenders = [
        line for where, source in sources for line in private_imports(where, source, public)
    ]
    assert offenders == []


def test_an_internal_import_is_caught() -> None:
    public = documented()
    source = "from genparams.runtime.core.errors import ParameterDeclarationError\n"
    assert private_imports("x.py", source, public) == [
        "x.py: genparams.runtime.core.errors ParameterDeclarationError"
    ]
    assert private_imports("x.md", "import genparams.schema.loader\n...", public) == [
        "x.md: genparams.schema.loader"
    ]
    assert private_imports("x.py", "from genparams.runtime import Secret\n", public) != []


OLD_ERRORS = {
    "DetachedSnapshotError": "genparams.runtime",
    "GenparamsError": "genparams",
    "ParameterDeclarationError": "genparams.runtime",
    "RemoteParameterError": "genparams.runtime",
    "RemoteSetError": "genparams.runtime",
}


@pytest.mark.parametrize(("name", "new_home"), sorted(OLD_ERRORS.items()))
def test_the_moved_errors_module_is_a_deprecated_alias(name: str, new_home: str) -> None:
    old = importlib.import_module("genparams.runtime.errors")
    with pytest.warns(DeprecationWarning, match=f"import {name} from {new_home}$") as caught:
        moved = getattr(old, name)
    assert moved is getattr(importlib.import_module(new_home), name)
    assert caught[0].filename == __file__  # the warning points at the line that used it
    with pytest.raises(AttributeError):
        old.NotAnError  # noqa: B018
