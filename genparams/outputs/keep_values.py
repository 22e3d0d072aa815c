"""Keep tuned values: a node's values written back into the params files they came from.

Each value that differs from what the files give the node is written at the place that
gave it, the entry that wins in rcl's order (the place explain traces): only the text of
that value changes, so comments, order and formatting stay. A value no file gave (one
that differs from its default) goes to a file the user names: into the node's own
section there when it has one, else in a new section at its end.

Pure: the result is each file's new text, and what changed; writing is the caller's.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from genparams.errors import GenparamsError
from genparams.outputs.yaml_text import key_text, node_key_text, value_text
from genparams.paramsfile.node_rules import equal_values
from genparams.paramsfile.node_sections import entries_in_force, sections_for
from genparams.paramsfile.params_reader import ParamEntry, ParamsDocument, Section
from genparams.runtime.core.types import TYPES
from genparams.schema.errors import Location

ANY = TYPES["any"]


class KeepError(GenparamsError, ValueError):
    """A value cannot be written back at its place (a flow mapping, a file changed)."""


@dataclass(frozen=True)
class Change:
    node: str
    name: str
    old: Any  # what the file gave, or the default; None when unknown
    new: Any
    file: str
    location: Location | None  # of the value replaced; None: a line added

    def __str__(self) -> str:
        where = str(self.location) if self.location else f"{self.file} (added)"
        old = "unset" if self.old is None else value_text(self.old, ANY)
        return f"{where}: {self.node}: {self.name}: {old} -> {value_text(self.new, ANY)}"


@dataclass(frozen=True)
class NodeValues:
    node: str
    values: Mapping[str, Any]  # what the node holds now
    changed_from_default: Mapping[str, Any]  # name -> default, for values off their default


def plan(
    nodes: Sequence[NodeValues], documents: Sequence[ParamsDocument], new_file: str | None
) -> list[Change]:
    """Every change that keeps the nodes' values, in the files they came from."""
    files = [d.sections for d in documents]
    changes: list[Change] = []
    for item in nodes:
        winners = _winning_entries(files, documents, item.node)
        for name, value in sorted(item.values.items()):
            if name in winners:
                document, entry = winners[name]
                if entry.value is not None and not equal_values(entry.value, value):
                    changes.append(
                        Change(
                            item.node, name, entry.value, value, document.file, entry.value_location
                        )
                    )
            elif name in item.changed_from_default and new_file is not None:
                default = item.changed_from_default[name]
                if not equal_values(default, value):
                    changes.append(Change(item.node, name, default, value, new_file, None))
    return changes


def _winning_entries(
    files: Sequence[Sequence[Section]], documents: Sequence[ParamsDocument], node: str
) -> dict[str, tuple[ParamsDocument, ParamEntry]]:
    """The entry that gives each name its value, with the file it is in."""
    owner = {id(s): d for d in documents for s in d.sections}
    in_force = entries_in_force(sections_for(files, node)[0])
    return {name: (owner[id(section)], entry) for name, (section, entry) in in_force.items()}


def apply(changes: Sequence[Change], texts: Mapping[str, str]) -> dict[str, str]:
    """Each touched file's new text; ``texts`` holds the current text of each (the new-values
    file may be absent: it is then made). Raises KeepError when a place cannot be written."""
    result: dict[str, str] = {}
    by_file: dict[str, list[Change]] = {}
    for change in changes:
        by_file.setdefault(change.file, []).append(change)
    for file, found in by_file.items():
        text = texts.get(file, "")
        in_place = [c for c in found if c.location is not None]
        added = [c for c in found if c.location is None]
        text = _replace_values(text, in_place, file)
        result[file] = _add_values(text, added, file)
    return result


def _replace_values(text: str, changes: Sequence[Change], file: str) -> str:
    if not changes:
        return text
    spans = _value_spans(text, file)
    edits = []
    for change in changes:
        assert change.location is not None  # only in-place changes come here
        span = spans.get((change.location.line, change.location.column))
        if span is None:
            raise KeepError(f"{change.location}: {change.name}: the file changed since it was read")
        edits.append((span, value_text(change.new, ANY)))
    for (start, end), written in sorted(edits, reverse=True):
        text = text[:start] + written + text[end:]
    return text


def _value_spans(text: str, file: str) -> dict[tuple[int, int], tuple[int, int]]:
    """Where each scalar or sequence value starts (line, column) -> its character span."""
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.YAMLError as exc:
        raise KeepError(f"{file}: not YAML any more ({exc.__class__.__name__})") from None
    spans: dict[tuple[int, int], tuple[int, int]] = {}
    stack = [root] if root is not None else []
    while stack:
        node = stack.pop()
        if isinstance(node, yaml.MappingNode):
            stack.extend(value for _, value in node.value)
            continue
        start, end = node.start_mark.index, node.end_mark.index
        # A block list ends where the next key starts: its span stops at its last item.
        end = start + len(text[start:end].rstrip())
        spans[(node.start_mark.line + 1, node.start_mark.column + 1)] = (start, end)
    return spans


def _add_values(text: str, changes: Sequence[Change], file: str) -> str:
    if not changes:
        return text
    from genparams.paramsfile.params_reader import read_params_file

    sections = {s.node: s for s in read_params_file(text, file).sections} if text else {}
    lines = text.splitlines(keepends=True)
    if lines and not lines[-1].endswith("\n"):
        lines[-1] += "\n"
    appended: dict[str, list[Change]] = {}
    inserts: list[tuple[int, str]] = []
    for change in changes:
        section = sections.get(change.node)
        if section is None:
            appended.setdefault(change.node, []).append(change)
            continue
        after = section.params_location.line  # the `ros__parameters:` line
        rest = lines[after - 1].split(":", 1)[1].strip() if after <= len(lines) else ""
        if rest and not rest.startswith("#"):
            raise KeepError(
                f"{section.params_location}: {change.node}: write its values one per line "
                "(block style) to add to them"
            )
        column = (
            section.entries[0].key_location.column - 1
            if section.entries
            else section.params_location.column + 1
        )
        line = f"{' ' * column}{key_text(change.name)}: {value_text(change.new, ANY)}\n"
        inserts.append((after, line))
    for after, line in sorted(inserts, key=lambda pair: pair[0], reverse=True):
        lines.insert(after, line)
    for node, found in appended.items():
        lines.append(f"{node_key_text(node)}:\n  ros__parameters:\n")
        lines.extend(f"    {key_text(c.name)}: {value_text(c.new, ANY)}\n" for c in found)
    return "".join(lines)


def read_texts(files: Sequence[str]) -> dict[str, str]:
    """The current text of each file that exists."""
    return {f: Path(f).read_text(encoding="utf-8") for f in files if Path(f).is_file()}
