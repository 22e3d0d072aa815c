"""How deeply a YAML text nests collections, read from the text before any YAML library.

genparams refuses a document nested deeper than ``MAX_DEPTH`` collections, at the place
where the first collection too deep starts. YAML libraries each have their own ideas
about deep input (one composer recursed in C and crashed, a later libyaml stops at its
own depth with its own message, the pure-Python composer recurses in Python), so the
depth is read here, in one linear pass over the text, and the refusal is the same under
every one of them.

The pass follows YAML's tokens only as far as depth needs: block collections by their
indentation, rolled and unwound as YAML's scanner does; flow collections by their
brackets; and it steps over what cannot open a collection: quoted scalars, comments,
block scalars, and plain scalars (which may hold brackets in block context). A text
that is not valid YAML still gets a depth, and the YAML parser reports its error later.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from genparams.schema.errors import Location, SchemaError, SchemaProblem

MAX_DEPTH = 64

_SPACES = re.compile(r"[ \t]*")
_WHITESPACE = re.compile(r"\s*")
# Where a plain scalar of block context ends: before ": ", " #" or the line's end.
_BLOCK_PLAIN_END = re.compile(r":(?=\s|\Z)|[ \t]#|[\r\n]|\Z")
# In flow context, a run of what cannot open a collection: spaces, commas, "?" and ":",
# and plain scalars (words without flow indicators, a ":" in one only before another
# character; the words after a space go on, unless a comment starts).
_WORD = r"(?:[^\s,?\[\]{}:]+|:(?![\s,\[\]{}]|\Z))"
_FLOW_PLAIN = rf"[^\s,?\[\]{{}}:'\"#!&*]{_WORD}*(?:\s+(?!#){_WORD}+)*+"
_FLOW_RUN = re.compile(rf"(?:\s+|[,?:]|{_FLOW_PLAIN})*+")
# A tag runs to a space or a flow indicator; an anchor or alias name is letters, digits, _ -.
_PROPERTY = re.compile(r"![^\s,\[\]{}]*|[&*][0-9A-Za-z_-]*")
_QUOTED = {
    '"': re.compile(r'"[^"\\]*(?:\\.[^"\\]*)*"', re.DOTALL),
    "'": re.compile(r"'[^']*(?:''[^']*)*'"),
}
_BLOCK_SCALAR_HEADER = re.compile(r"[|>][+-]?([1-9]?)")
_BLANKS = " \t\r\n"


def check_nesting(text: str, file: str) -> None:
    """Raise SchemaError where ``text`` first nests deeper than MAX_DEPTH collections."""
    if "\r" in text:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    _Reader(text, file).read()


@dataclass
class _Block:
    column: int
    is_sequence: bool
    indentless: bool = False  # a sequence at its parent mapping's own column


@dataclass
class _Reader:
    text: str
    file: str
    blocks: list[_Block] = field(default_factory=list)
    flow: int = 0
    node_start: int | None = None  # where the node being read starts (with its properties)

    def read(self) -> None:
        text, pos = self.text, 0
        if text.startswith("\ufeff"):
            pos = 1
        plain_open = False  # the last line ended inside a plain scalar
        block_scalar: tuple[int, int] | None = None  # (smallest indent, indent or 0)
        while pos < len(text):
            first = _skip(_SPACES, text, pos)
            column = first - pos
            blank = first == len(text) or text[first] == "\n"
            if block_scalar is not None:
                least, indent = block_scalar
                if blank or column >= (indent or least):
                    block_scalar = (least, indent or (0 if blank else column))
                    pos = self._next_line(first)
                    continue
                block_scalar = None
            if blank:  # a plain scalar runs on over blank lines
                pos = self._next_line(first)
                continue
            if plain_open:
                plain_open = text[first] != "#" and column > self._indent()
                if plain_open and not (column == 0 and self._document_marker(first)):
                    pos = self._next_line(first)
                    continue
                plain_open = False
            pos, plain_open, block_scalar = self._line(first)

    def _line(self, pos: int) -> tuple[int, bool, tuple[int, int] | None]:
        """Read the tokens of one line of block context from ``pos``; return where the next
        line starts, whether a plain scalar runs on, and a block scalar that starts."""
        text = self.text
        self.node_start = None
        first_token = True
        while True:
            pos = _skip(_SPACES, text, pos)
            if pos == len(text) or text[pos] == "\n":
                return self._next_line(pos), False, None
            char = text[pos]
            if char == "#":
                return self._next_line(pos), False, None
            column = self._column(pos)
            indicator = char in "-?:" and (pos + 1 == len(text) or text[pos + 1] in _BLANKS)
            if first_token:
                self._unwind(column, entry=indicator and char == "-")
                first_token = False
            if indicator:
                if char == ":" and self.node_start is not None:
                    self._roll(self._column(self.node_start), False, self.node_start)
                else:
                    self._roll(column, char == "-", pos)
                self.node_start = None
                pos += 1
                continue
            if column == 0 and self._document_marker(pos):
                self.blocks.clear()
                pos += 3
                continue
            if column == 0 and char == "%":
                return self._next_line(pos), False, None
            if self.node_start is None:
                self.node_start = pos
            if char in "[{":
                pos = self._flow(pos)
            elif char in _QUOTED:
                pos = self._quoted(pos)
            elif char in "!&*":
                pos = _skip(_PROPERTY, text, pos)
            elif char in "|>":
                header = _BLOCK_SCALAR_HEADER.match(text, pos)
                assert header is not None
                least = max(self._indent() + 1, 1)
                step = header[1]
                return self._next_line(pos), False, (least, least + int(step) - 1 if step else 0)
            else:
                end = _BLOCK_PLAIN_END.search(text, pos + 1)
                assert end is not None
                pos = end.start()
                if pos == len(text) or text[pos] == "\n":
                    return self._next_line(pos), True, None
                if text[pos] != ":":
                    return self._next_line(pos), False, None  # a comment follows

    def _flow(self, pos: int) -> int:
        """Read a flow collection from its opening bracket; return where it ends."""
        text = self.text
        depth_before = self.flow
        node_start = self.node_start  # properties written before the bracket start the node
        while pos < len(text):
            char = text[pos]
            if char in "[{":
                self.flow += 1
                self._check(node_start if node_start is not None else pos)
                node_start = None
                pos += 1
            elif char in "]}":
                self.flow -= 1
                pos += 1
                if self.flow == depth_before:
                    return pos
            elif char == "#":
                pos = self._line_end(pos)
            elif char in _QUOTED:
                pos = self._quoted(pos)
            elif char in "!&*":
                node_start = pos if node_start is None else node_start
                pos = _skip(_WHITESPACE, text, _skip(_PROPERTY, text, pos))
                continue  # the node the properties belong to follows
            else:
                pos = max(pos + 1, _skip(_FLOW_RUN, text, pos))
            node_start = None
            pos = _skip(_FLOW_RUN, text, pos)
        self.flow = depth_before
        return pos

    def _quoted(self, pos: int) -> int:
        quoted = _QUOTED[self.text[pos]].match(self.text, pos)
        return quoted.end() if quoted else len(self.text)

    def _indent(self) -> int:
        """The column of the innermost block collection, -1 at the top."""
        return self.blocks[-1].column if self.blocks else -1

    def _unwind(self, column: int, entry: bool) -> None:
        blocks = self.blocks
        while blocks and blocks[-1].column > column:
            blocks.pop()
        if blocks and blocks[-1].indentless and blocks[-1].column == column and not entry:
            blocks.pop()

    def _roll(self, column: int, sequence: bool, start: int) -> None:
        top = self.blocks[-1] if self.blocks else None
        if top is None or column > top.column:
            self.blocks.append(_Block(column, sequence))
        elif sequence and not top.is_sequence and column == top.column:
            self.blocks.append(_Block(column, True, indentless=True))
        else:
            return
        self._check(start)

    def _check(self, start: int) -> None:
        if len(self.blocks) + self.flow <= MAX_DEPTH:
            return
        line = self.text.count("\n", 0, start) + 1
        location = Location(self.file, line, self._column(start) + 1)
        raise SchemaError([SchemaProblem(location, "", f"nested deeper than {MAX_DEPTH} levels")])

    def _column(self, pos: int) -> int:
        return pos - (self.text.rfind("\n", 0, pos) + 1)

    def _document_marker(self, pos: int) -> bool:
        return self.text.startswith(("---", "..."), pos) and (
            pos + 3 == len(self.text) or self.text[pos + 3] in _BLANKS
        )

    def _line_end(self, pos: int) -> int:
        end = self.text.find("\n", pos)
        return len(self.text) if end < 0 else end

    def _next_line(self, pos: int) -> int:
        return min(self._line_end(pos) + 1, len(self.text))


def _skip(pattern: re.Pattern[str], text: str, pos: int) -> int:
    """Where ``pattern`` (which may match nothing) stops matching from ``pos``."""
    found = pattern.match(text, pos)
    return found.end() if found else pos
