"""Text edits of a Python source: spans of syntax nodes (ast gives byte columns), edits
applied in order, and the clean-up after a patch (imports and descriptor variables whose
last use went)."""

from __future__ import annotations

import ast
from collections.abc import Iterable
from dataclasses import dataclass

from genparams.rclpy_import.overrides import reads_overrides


@dataclass(frozen=True)
class Edit:
    start: int  # character offsets into the source
    end: int
    text: str


class Source:
    def __init__(self, text: str) -> None:
        self.text = text
        self.lines = text.splitlines(keepends=True)
        self.starts = [0]
        for line in self.lines:
            self.starts.append(self.starts[-1] + len(line))

    def offset(self, line: int, byte_column: int) -> int:
        return self.starts[line - 1] + self.column(line, byte_column)

    def column(self, line: int, byte_column: int) -> int:
        """The character column of a byte column (as ast gives it) on ``line``."""
        text = self.lines[line - 1] if line - 1 < len(self.lines) else ""
        return len(text.encode("utf-8")[:byte_column].decode("utf-8", errors="replace"))

    def span(self, node: ast.AST) -> tuple[int, int]:
        start = self.offset(node.lineno, node.col_offset)  # type: ignore[attr-defined]
        end = self.offset(node.end_lineno, node.end_col_offset)  # type: ignore[attr-defined]
        return start, end

    def line_span(self, node: ast.stmt) -> tuple[int, int] | None:
        """The whole lines of ``node``, if nothing else stands on them (comments may)."""
        start, end = self.span(node)
        line_start = self.starts[node.lineno - 1]
        line_end = self.starts[node.end_lineno or node.lineno]
        before = self.text[line_start:start]
        after = self.text[end:line_end].strip()
        if before.strip() or (after and not after.startswith("#")):
            return None
        return line_start, line_end

    def indent(self, node: ast.stmt) -> str:
        line = self.lines[node.lineno - 1]
        return line[: len(line) - len(line.lstrip())]


def apply_edits(text: str, edits: list[Edit]) -> str:
    out = []
    position = 0
    for edit in sorted(edits, key=lambda e: (e.start, e.end)):
        if edit.start < position:
            continue  # overlapping: the first edit wins
        out.append(text[position : edit.start])
        out.append(edit.text)
        position = edit.end
    out.append(text[position:])
    return "".join(out)


def drop_unused_imports(before: str, text: str) -> str:
    """Imported names the patch took the last use of leave their import statements."""
    try:
        tree = ast.parse(text)
        was_used = _used_names(ast.parse(before))
    except SyntaxError:
        return text
    used = _used_names(tree)
    source = Source(text)
    edits = []
    for statement in tree.body:
        if not isinstance(statement, (ast.Import, ast.ImportFrom)):
            continue
        if isinstance(statement, ast.ImportFrom) and statement.module == "__future__":
            continue
        kept = [
            a
            for a in statement.names
            if (bound := a.asname or a.name.partition(".")[0]) in used or bound not in was_used
        ]
        span = source.line_span(statement)
        if len(kept) == len(statement.names) or span is None:
            continue
        names = ", ".join(a.name + (f" as {a.asname}" if a.asname else "") for a in kept)
        if not kept:
            replacement = ""
        elif isinstance(statement, ast.ImportFrom):
            module = "." * statement.level + (statement.module or "")
            replacement = f"from {module} import {names}\n"
        else:
            replacement = f"import {names}\n"
        edits.append(Edit(span[0], span[1], replacement))
    return apply_edits(text, edits)


def _used_names(tree: ast.Module) -> set[str]:
    return {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)}


_MESSAGES = ("ParameterDescriptor", "FloatingPointRange", "IntegerRange")


def drop_unused_descriptors(text: str) -> str:
    """``desc = ParameterDescriptor(...)`` (and ``desc.x = ...``) whose declaration went,
    and ``names = {...}`` of the keys under a prefix in the overrides whose loop went."""
    try:
        tree = ast.parse(text)
    except SyntaxError:
        return text
    source = Source(text)
    edits = []
    for function in ast.walk(tree):
        if not isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        setters = {
            target.value: statement
            for statement in ast.walk(function)
            if isinstance(statement, ast.Assign)
            for target in statement.targets
            if isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name)
        }
        loaded = {
            n.id
            for n in ast.walk(function)
            if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load) and n not in setters
        }
        for statement in ast.walk(function):
            if not isinstance(statement, ast.Assign) or len(statement.targets) != 1:
                continue
            target = statement.targets[0]
            value = statement.value
            if (
                isinstance(target, ast.Name)
                and target.id not in loaded
                and (
                    (isinstance(value, ast.Call) and _called(value) in _MESSAGES)
                    or reads_overrides(value)
                )
            ):
                for dropped in [statement, *_sets_of(target.id, setters.values())]:
                    span = source.line_span(dropped)
                    if span is not None:
                        edits.append(Edit(span[0], span[1], ""))
    return apply_edits(text, edits)


def _sets_of(name: str, setters: Iterable[ast.Assign]) -> list[ast.Assign]:
    return [
        s
        for s in setters
        if any(
            isinstance(t, ast.Attribute) and isinstance(t.value, ast.Name) and t.value.id == name
            for t in s.targets
        )
    ]


def _called(call: ast.Call) -> str:
    func = call.func
    return func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
