"""Read the README and docs/ pages as a reader does: links, headings and shell blocks."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from tests.support import ROOT

DOCS = ROOT / "docs"
README = ROOT / "README.md"

_FENCE = re.compile(r"^```(?P<lang>[^\n`]*)\n(?P<body>.*?)^```\s*$", re.M | re.S)
_LINK = re.compile(r"\[[^\]]*\]\((?P<target>[^)\s]+)\)")
_HEADING = re.compile(r"^#{1,6} +(?P<title>.+?) *$", re.M)


@dataclass(frozen=True)
class Block:
    lang: str
    body: str
    followed_by: Block | None  # the block right after this one, when only blank lines part them


def pages() -> list[Path]:
    return [README, *sorted(DOCS.glob("*.md"))]


def blocks(text: str) -> list[Block]:
    found = list(_FENCE.finditer(text))
    result: list[Block] = []
    for index in reversed(range(len(found))):
        match = found[index]
        after = None
        if index + 1 < len(found) and not text[match.end() : found[index + 1].start()].strip():
            after = result[0]
        result.insert(0, Block(match["lang"].strip(), match["body"], after))
    return result


def prose(text: str) -> str:
    """The text outside fenced blocks, where links and headings live."""
    return _FENCE.sub("", text)


def links(text: str) -> list[str]:
    return [m["target"] for m in _LINK.finditer(prose(text)) if "://" not in m["target"]]


def slug(title: str) -> str:
    """A heading's anchor as GitHub and MyST (myst_heading_anchors) spell it."""
    title = re.sub(r"[`*]", "", title).strip().lower()
    title = re.sub(r"[^\w\- ]", "", title)
    return title.replace(" ", "-")


def anchors(text: str) -> set[str]:
    return {slug(m["title"]) for m in _HEADING.finditer(prose(text))}


def shell_lines(body: str) -> list[str]:
    """The lines of a shell block, with backslash continuations joined."""
    return body.replace("\\\n", " ").splitlines()


_REPO_PATH = re.compile(
    r"(?<![\w./-])((?:tests|examples|genparams|bench|docs|schemas|templates)/[\w./-]*\w)"
)


def repository_paths(text: str) -> set[str]:
    """Paths into the repository that a page names (in code text, commands or links)."""
    return {m[1] for m in _REPO_PATH.finditer(text)}
