"""User text in a message, with every character that does not show written as an escape.

A key ``gain`` followed by a zero-width space looks like ``gain`` on a terminal,
and U+202E (right-to-left override) reverses the rest of the line it is printed
on. Every message that repeats text from a file, the command line or another
node shows it through ``visible``: ``gain\\u200b``, ``x\\u202eabc``.

Escaped are the characters Python does not print as themselves (controls,
format characters such as the bidirectional ones, separators other than the
space, private-use, unassigned and surrogate code points) and the default
ignorable ones that Python does print but a terminal shows as nothing (U+034F,
the Hangul fillers, variation selectors, tags). They are written as Python's
``repr`` writes them: ``\\n``, ``\\x00``, ``\\u200b``, ``\\U000e0041``.
"""

from __future__ import annotations

import functools
import re

# Unicode's Default_Ignorable_Code_Point: drawn as nothing, whatever their category.
_IGNORABLE_CLASS = (
    "[\u00ad\u034f\u061c\u115f\u1160\u17b4\u17b5\u180b-\u180f\u200b-\u200f\u202a-\u202e"
    "\u2060-\u206f\u3164\ufe00-\ufe0f\ufeff\uffa0\ufff0-\ufff8\U0001bca0-\U0001bca3"
    "\U0001d173-\U0001d17a\U000e0000-\U000e0fff]"
)


@functools.cache
def _ignorable() -> re.Pattern[str]:
    """Compiled with the first text that is not plain ASCII (about 0.5 ms, not at import)."""
    return re.compile(_IGNORABLE_CLASS)


def visible(text: str) -> str:
    """``text`` with each character that would not show escaped; other text unchanged."""
    if text.isascii() and text.isprintable():  # most messages; no ASCII character is ignorable
        return text
    if text.isprintable() and _ignorable().search(text) is None:
        return text
    return "".join(_escaped(char) for char in text)


def _escaped(char: str) -> str:
    if char.isprintable() and _ignorable().match(char) is None:
        return char
    return char.encode("unicode_escape", "backslashreplace").decode("ascii")
