"""No tracked file names a package index: installs go by package name through pip or uv,
and the machine's own client configuration decides where packages come from.

The shapes are matched, never a host: an index option on a command line or in a config
file, an index's environment variable, a URL whose path is a simple index or a file
store's package tree, a lock's registry source.
"""

from __future__ import annotations

import re
import subprocess

import pytest

from tests.support import ROOT

# Each pattern is written so that this file's own text does not match it.
INDEX_SHAPES = {
    "an index option": re.compile(r"--(?:extra-)?index-url\b|--find[-]links\b|--default[-]index\b"),
    "an index setting": re.compile(
        r"^\s*(?:extra[-_])?index[-_]url\s*=|^\s*find[-_]links\s*=|\[\[tool\.uv\.index\]\]",
        re.MULTILINE,
    ),
    "an index variable": re.compile(r"\b(?:PIP|UV)_(?:EXTRA_|DEFAULT_)?INDEX(?:_URL)?\b"),
    "a simple-index URL": re.compile(r"[a-z][a-z0-9+.-]*://[^\s/\"'<>]*(?:/[^\s\"'<>]*)?/simple\b"),
    "a package-file URL": re.compile(r"[a-z][a-z0-9+.-]*://[^\s/\"'<>]+/packages/[0-9a-f]{2}/"),
    "a lock's registry source": re.compile(r"\bregistry\s*=\s*[\"'][a-z][a-z0-9+.-]*:"),
}


def tracked_files() -> list[str]:
    listed = subprocess.run(
        ["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, text=True, check=False
    )
    if listed.returncode != 0:
        pytest.skip(f"not a git checkout: {listed.stderr.strip()}")
    return [name for name in listed.stdout.split("\0") if name]


def index_mentions(text: str) -> list[str]:
    found = []
    for shape, pattern in INDEX_SHAPES.items():
        for match in pattern.finditer(text):
            line = text.count("\n", 0, match.start()) + 1
            found.append(f"{line}: {shape}: {match.group().strip()}")
    return found


def test_no_tracked_file_names_a_package_index() -> None:
    offenders = []
    for name in tracked_files():
        path = ROOT / name
        if not path.is_file():  # deleted in the work tree, not yet committed
            continue
        text = path.read_bytes().decode("utf-8", errors="replace")
        offenders += [f"{name}:{mention}" for mention in index_mentions(text)]
    assert offenders == []


@pytest.mark.parametrize(
    "text",
    [
        "pip install --" + "index-url X pkg",
        "uv pip sync --" + "extra-index-url X r.txt",
        "pip install --" + "find-links ./wheels pkg",
        "uv pip install --" + "default-index X pkg",
        "[global]\n" + "index" + "-url = X\n",
        "export " + "PIP_" + "INDEX_URL=X",
        "source = { " + "registry" + ' = "https' + '://example.invalid/simple" }',
        "https" + "://mirror.example.invalid/" + "simple/",
        "file" + ":///opt/mirror/" + "simple",
        "https" + "://files.example.invalid/" + "packages/7e/b3/x.whl",
    ],
)
def test_every_index_shape_is_caught(text: str) -> None:
    assert index_mentions(text) != []


@pytest.mark.parametrize(
    "text",
    [
        "pip install 'genparams[tune]'",
        "uv pip sync --require-hashes requirements/dev.txt",
        "see https" + "://docs.ros.org/en/jazzy/ for the tutorials",
        "a simple schema, simple/ folders",
    ],
)
def test_ordinary_text_passes(text: str) -> None:
    assert index_mentions(text) == []
