"""Safe YAML loading that remembers where every key and value came from.

Returns plain Python data plus a table of source locations by document path.
Mapping keys are always strings, taken as written (so ``on:`` stays "on").
Duplicate keys are errors. Aliases are expanded within a fixed node budget,
so an alias bomb fails fast instead of exhausting memory.
"""

from __future__ import annotations

import contextlib
import gc
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

import yaml

from genparams.runtime.core.types import ros_text_problem
from genparams.schema.errors import Location, SchemaError, SchemaProblem
from genparams.schema.nesting import MAX_DEPTH as MAX_DEPTH
from genparams.schema.nesting import check_nesting

Path = tuple[str | int, ...]

# An integer this long fits no parameter type, and Python would refuse to write it in
# decimal (past 4,300 digits, about 14,280 bits) for a message: it is refused as read.
MAX_INT_BITS = 14_000

# Limits that keep hostile input cheap: a 2 MB schema (some 20,000 parameters) loads
# in seconds; anything beyond fails at once, before it is built.
MAX_NODES = 250_000
MAX_BYTES = 2_000_000

_BaseLoader: type[yaml.SafeLoader] = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


class _SafeLoader(_BaseLoader):  # type: ignore[valid-type,misc]
    """Safe loading; also reads ``1e3`` as a float, as ROS's params-file parser does."""


_SafeLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9][0-9_]*(?:\.[0-9_]*)?|\.[0-9_]+)[eE][-+]?[0-9]+$"),
    list("-+0123456789."),
)


@dataclass
class LoadedDocument:
    file: str
    data: Any
    key_locations: dict[Path, Location] = field(default_factory=dict)
    value_locations: dict[Path, Location] = field(default_factory=dict)
    # The problems that are a key written twice in one mapping (also among the problems).
    duplicate_keys: list[SchemaProblem] = field(default_factory=list)

    def key_location(self, path: Path) -> Location:
        """Where the key of ``path`` is written (falls back to its nearest ancestor)."""
        return self._nearest(self.key_locations, path)

    def value_location(self, path: Path) -> Location:
        """Where the value at ``path`` starts (falls back to its nearest ancestor)."""
        return self._nearest(self.value_locations, path)

    def _nearest(self, table: dict[Path, Location], path: Path) -> Location:
        while path:
            if path in table:
                return table[path]
            path = path[:-1]
        return table.get((), Location(self.file, 1, 1))


def dotted(path: Path) -> str:
    return ".".join(f"[{p}]" if isinstance(p, int) else p for p in path).replace(".[", "[")


def load_yaml(text: str, file: str) -> LoadedDocument:
    """Load one YAML document; raises SchemaError on a syntax error or any duplicate key."""
    document, problems = compose_yaml(text, file)
    if problems:
        raise SchemaError(problems)
    return document


ScalarReader = Callable[[yaml.ScalarNode], Any]


def compose_yaml(
    text: str, file: str, scalar: ScalarReader | None = None
) -> tuple[LoadedDocument, list[SchemaProblem]]:
    """Load one YAML document, returning the problems found (duplicate keys) beside it.

    ``scalar`` turns each scalar node into a value; by default YAML's own safe
    types are used. Readers that type scalars differently (ROS's params-file
    parser does) pass their own. A syntax error still raises SchemaError: there
    is no document to return.
    """
    if len(text) > MAX_BYTES:
        raise SchemaError(
            [SchemaProblem(Location(file, 1, 1), "", f"file is larger than {MAX_BYTES} bytes")]
        )
    with _collector_paused():
        return _compose(text, file, scalar)


@contextlib.contextmanager
def _collector_paused() -> Iterator[None]:
    """Loading allocates many objects and no cycles; the cyclic garbage collector would
    rescan them over and over (a 3 MB file took 14 s with it, 2 s without)."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def _compose(
    text: str, file: str, scalar: ScalarReader | None
) -> tuple[LoadedDocument, list[SchemaProblem]]:
    try:
        check_nesting(text, file)
        _count_nodes(text, file)
        root = yaml.compose(text, Loader=_SafeLoader)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line, column = (mark.line + 1, mark.column + 1) if mark else (1, 1)
        message = " ".join(str(part) for part in (exc.context, exc.problem) if part)
        raise SchemaError(
            [SchemaProblem(Location(file, line, column), "", f"invalid YAML: {message}")]
        ) from None
    except yaml.YAMLError as exc:
        raise SchemaError(
            [SchemaProblem(Location(file, 1, 1), "", f"invalid YAML: {exc}")]
        ) from None
    document = LoadedDocument(file, None)
    if root is None:
        return document, []
    _check_expansion(root, file)
    builder = _Builder(document, scalar)
    document.value_locations[()] = builder.location(root)
    document.data = builder.build(root, ())
    return document, builder.problems


def yaml_events(text: str) -> Iterator[yaml.Event]:
    """The parser's events for ``text``, from libyaml when it is there (30x faster)."""
    return yaml.parse(text, Loader=_SafeLoader)


def _count_nodes(text: str, file: str) -> None:
    """Refuse too many values before composing, from the parser's events (the depth was
    read from the text already: composers recurse, and libyaml's recursed in C)."""
    nodes = 0
    for event in yaml_events(text):
        if isinstance(event, (yaml.ScalarEvent, yaml.CollectionStartEvent)):
            nodes += 1
            if nodes > MAX_NODES:
                raise _too_many_nodes(file, event.start_mark)


def _too_many_nodes(file: str, mark: Any) -> SchemaError:
    line, column = (mark.line + 1, mark.column + 1) if mark else (1, 1)
    message = f"more than {MAX_NODES} values (too large, or an alias bomb)"
    return SchemaError([SchemaProblem(Location(file, line, column), "", message)])


def _check_expansion(root: yaml.Node, file: str) -> None:
    """Count what aliases expand to on the composed graph, where each shared node is counted
    once, so an alias bomb is refused in milliseconds instead of being built."""
    sizes: dict[int, int] = {}
    active: set[int] = set()

    def fail(node: yaml.Node, message: str) -> SchemaError:
        mark = node.start_mark
        return SchemaError(
            [SchemaProblem(Location(file, mark.line + 1, mark.column + 1), "", message)]
        )

    def size(node: yaml.Node) -> int:
        key = id(node)
        if key in sizes:
            return sizes[key]
        if key in active:
            raise fail(node, "an alias refers to a collection that contains it")
        active.add(key)
        children: list[yaml.Node] = []
        if isinstance(node, yaml.MappingNode):
            children = [child for pair in node.value for child in pair]
        elif isinstance(node, yaml.SequenceNode):
            children = node.value
        total = 1 + sum(size(child) for child in children)
        if total > MAX_NODES:
            raise _too_many_nodes(file, node.start_mark)
        active.discard(key)
        sizes[key] = total
        return total

    try:
        size(root)
    except RecursionError:
        raise fail(root, "aliases nest too deeply") from None


_PLAIN_COLLECTION_TAGS = frozenset({"tag:yaml.org,2002:map", "tag:yaml.org,2002:seq"})


class _Builder:
    def __init__(self, document: LoadedDocument, scalar: ScalarReader | None) -> None:
        self.document = document
        self.problems: list[SchemaProblem] = []
        self.constructor = yaml.constructor.SafeConstructor()
        self.scalar = scalar

    def location(self, node: yaml.Node) -> Location:
        return Location(self.document.file, node.start_mark.line + 1, node.start_mark.column + 1)

    def build(self, node: yaml.Node, path: Path) -> Any:
        # No node count here: _check_expansion has bounded what aliases expand to. Depth
        # is checked again: check_nesting saw the text, where an alias of a deep
        # collection placed deep adds the depths of both.
        if len(path) > MAX_DEPTH:
            raise SchemaError(
                [
                    SchemaProblem(
                        self.location(node), dotted(path), f"nested deeper than {MAX_DEPTH}"
                    )
                ]
            )
        if isinstance(node, yaml.CollectionNode) and node.tag not in _PLAIN_COLLECTION_TAGS:
            # Scalars with unknown tags fail in the safe constructor; collections are built
            # here, so their tags (!!set, !!python/object...) are refused here.
            self.problems.append(
                SchemaProblem(self.location(node), dotted(path), f"unsupported YAML tag {node.tag}")
            )
            return None
        if isinstance(node, yaml.MappingNode):
            return self._mapping(node, path)
        if isinstance(node, yaml.SequenceNode):
            items = []
            for index, child in enumerate(node.value):
                child_path = (*path, index)
                self.document.key_locations[child_path] = self.location(child)
                self.document.value_locations[child_path] = self.location(child)
                items.append(self.build(child, child_path))
            return items
        if self.scalar is not None and isinstance(node, yaml.ScalarNode):
            return self.scalar(node)
        try:
            value = self.constructor.construct_object(node, deep=True)
        except yaml.constructor.ConstructorError as exc:
            self.problems.append(
                SchemaProblem(self.location(node), dotted(path), f"invalid value: {exc.problem}")
            )
            return None
        except (ArithmeticError, LookupError, TypeError, ValueError):
            # The safe constructor trusts explicit tags: `!!int abc`, `!!float ''`.
            self.problems.append(
                SchemaProblem(
                    self.location(node),
                    dotted(path),
                    f"invalid value: {repr(node.value)[:60]} cannot be read as {node.tag}",
                )
            )
            return None
        if isinstance(value, int) and value.bit_length() > MAX_INT_BITS:
            # A hex or octal literal is read whatever its length, but no type holds it,
            # and Python refuses to write it in decimal (past 4,300 digits) for a message.
            self.problems.append(
                SchemaProblem(
                    self.location(node),
                    dotted(path),
                    f"invalid value: {repr(node.value)[:60]} is an integer of "
                    f"{value.bit_length()} bits, too large for any parameter type",
                )
            )
            return None
        if isinstance(value, str):
            self.check_text(value, node, path)
        return value

    def check_text(self, text: str, node: yaml.Node, path: Path) -> None:
        problem = ros_text_problem(text)
        if problem is not None:
            self.problems.append(SchemaProblem(self.location(node), dotted(path), problem))

    def _mapping(self, node: yaml.MappingNode, path: Path) -> dict[str, Any]:
        result: dict[str, Any] = {}
        for key_node, value_node in node.value:
            if not isinstance(key_node, yaml.ScalarNode):
                self.problems.append(
                    SchemaProblem(
                        self.location(key_node), dotted(path), "keys must be plain strings"
                    )
                )
                continue
            key = str(key_node.value)
            child_path = (*path, key)
            self.check_text(key, key_node, child_path)
            if key in result:
                first = self.document.key_locations[child_path]
                duplicate = SchemaProblem(
                    self.location(key_node),
                    dotted(child_path),
                    f"duplicate key (first defined at line {first.line}, column {first.column})",
                )
                self.problems.append(duplicate)
                self.document.duplicate_keys.append(duplicate)
                continue
            self.document.key_locations[child_path] = self.location(key_node)
            self.document.value_locations[child_path] = self.location(value_node)
            result[key] = self.build(value_node, child_path)
        return result
