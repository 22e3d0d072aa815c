"""Escaping schema text for Markdown and reStructuredText pages (jinja2 filters).

Schema text is plain text: whatever it holds (``|``, ``*``, backquotes, line
breaks, lines that look like headings or directives) shows up as written and
never changes the page's structure. A Markdown table cell stays one cell; an
RST page builds under ``sphinx-build -W``.
"""

from __future__ import annotations

import re
import unicodedata

# ---- Markdown (CommonMark with GitHub tables) --------------------------------------------

_MD_SPECIAL = re.compile(r"([\\`*_\[\]|~])")
_MD_LINE_START = re.compile(r"([#>+=\-]|\d+[.)])")


def md_text(text: str) -> str:
    """Inline text, one line: safe inside a table cell (line breaks become ``<br>``)."""
    lines = [_md_line(line) for line in text.splitlines()]
    return "<br>".join(lines)


def md_paragraphs(text: str) -> str:
    """Block text: line breaks kept, blank lines separate paragraphs."""
    return "\n".join(_md_line(line) for line in text.splitlines())


def _md_line(line: str) -> str:
    line = line.strip()
    line = line.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    line = _MD_SPECIAL.sub(r"\\\1", line)
    # A line that would start a heading, quote, list or rule in a paragraph.
    match = _MD_LINE_START.match(line)
    if match:
        start = match.group(1)
        line = (
            f"{start[:-1]}\\{start[-1]}{line[len(start) :]}" if start[-1] in ".)" else "\\" + line
        )
    return line


def md_code(text: str) -> str:
    """A code span for a table cell: ``|`` escaped, fence longer than any backquote run."""
    longest = max((len(run) for run in re.findall(r"`+", text)), default=0)
    fence = "`" * (longest + 1)
    body = text.replace("|", "\\|")
    if body.startswith("`") or body.endswith("`"):
        body = f" {body} "
    return f"{fence}{body}{fence}"


# ---- reStructuredText ---------------------------------------------------------------------

_RST_SPECIAL = re.compile(r"([\\`*_|])")
# docutils turns ``scheme:rest`` into a live link (``javascript:alert(1)`` included):
# a backslash before the colon keeps it text.
_RST_URI_SCHEME = re.compile(r"(?<![\w.+-])([A-Za-z][A-Za-z0-9.+-]*):(?=\S)")


def rst_text(text: str, indent: int = 0) -> str:
    """Body text for RST; continuation lines are indented by ``indent`` spaces.

    Every line is stripped (no accidental block quotes), markup characters are
    backslash-escaped, and a line starting with punctuation has that character
    escaped, so it can start no directive, field list, list or section rule.
    The colon after a URI scheme is escaped too: no text becomes a link.
    """
    pad = " " * indent
    out = []
    for line in text.splitlines():
        line = _RST_SPECIAL.sub(r"\\\1", line.strip()).replace("::", "\\:\\:")
        line = _RST_URI_SCHEME.sub(r"\1\\:", line)
        if line and not line[0].isalnum() and line[0] != "\\":
            line = "\\" + line
        out.append(line)
    return ("\n").join(f"{pad}{line}" if line and index else line for index, line in enumerate(out))


def rst_literal(text: str) -> str:
    """An inline literal, or escaped text where an inline literal cannot hold ``text``."""
    if not text or "``" in text or text != text.strip() or text[0] == "`" or text[-1] == "`":
        return rst_text(text)
    if "\n" in text or "\r" in text:
        return rst_text(text)
    return f"``{text}``"


def rst_heading(title: str, char: str, overline: bool = False) -> str:
    """A section title (already escaped) with its adornment, as wide as docutils measures it."""
    rule = char * max(column_width(title), 1)
    return f"{rule}\n{title}\n{rule}" if overline else f"{title}\n{rule}"


def column_width(text: str) -> int:
    """Columns a line takes: wide East Asian characters count 2, combining marks 0."""
    width = 0
    for char in text:
        if unicodedata.combining(char):
            continue
        width += 2 if unicodedata.east_asian_width(char) in ("W", "F") else 1
    return width
