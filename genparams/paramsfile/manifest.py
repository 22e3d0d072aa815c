"""A deployment manifest: which schemas run on which node, and what other code owns.

```yaml
genparams_deployment: 1
known: [use_sim_time]              # owned by other code on every node (names or globs)
nodes:
  /controller_manager:             # a node name, or a pattern (/*/controller_manager)
    known: [update_rate, "*.type"]
  /forward_position_controller:
    schemas: [forward_command_controller.yaml]   # paths relative to this file
    known: [type]
  /front_steering:
    schemas:
      - steering_library.yaml
      - {schema: odometry.yaml, prefix: odom}    # another class, under a prefix
rules:                             # across nodes (node_rules)
  - {name: one_clock, same: use_sim_time}
  - {name: same_base, check: /front_steering.wheel_base == /odometry.wheel_base}
```
The same mapping can be given on the command line (``--map NODE=SCHEMA[@PREFIX][,...]``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from genparams.paramsfile.node_rules import NodeRule, read_rules
from genparams.paramsfile.ros_yaml import absolute, node_pattern_problem
from genparams.runtime.core.naming import is_ros_token
from genparams.schema.errors import Location, SchemaError, SchemaProblem
from genparams.schema.input_file import read_input_file
from genparams.schema.loader import LoadedDocument, load_yaml
from genparams.schema.loader import Path as KeyPath

FORMAT_KEY = "genparams_deployment"


@dataclass(frozen=True)
class SchemaRef:
    path: Path
    prefix: str = ""


@dataclass(frozen=True)
class NodeEntry:
    node: str  # absolute name or pattern
    schemas: tuple[SchemaRef, ...]
    known: tuple[str, ...]


@dataclass(frozen=True)
class Manifest:
    nodes: tuple[NodeEntry, ...]
    known: tuple[str, ...]  # for every node
    rules: tuple[NodeRule, ...] = ()  # across nodes (node_rules)


def read_manifest(path: Path) -> Manifest:
    """The manifest at ``path``; raises SchemaError listing every problem (unreadable too)."""
    document = load_yaml(read_input_file(path, "manifest"), str(path))
    reader = _Reader(document, path.parent)
    manifest = reader.manifest()
    if reader.problems:
        raise SchemaError(reader.problems)
    return manifest


def parse_map(text: str) -> NodeEntry:
    """``/ns/node=a.yaml,b.yaml@odom`` -> NodeEntry; raises ValueError."""
    node, sep, schemas = text.partition("=")
    if not sep or not node:
        raise ValueError(f"expected NODE=SCHEMA[@PREFIX][,SCHEMA...], got {text!r}")
    problem = node_pattern_problem(node)
    if problem is not None:
        raise ValueError(f"invalid node {node!r}: {problem}")
    refs = []
    for spec in filter(None, schemas.split(",")):
        path, _, prefix = spec.rpartition("@") if "@" in spec else (spec, "", "")
        if prefix and not _valid_prefix(prefix):
            raise ValueError(f"invalid prefix {prefix!r} in {text!r}")
        refs.append(SchemaRef(Path(path), prefix))
    return NodeEntry(absolute(node), tuple(refs), ())


def _valid_prefix(prefix: str) -> bool:
    return all(is_ros_token(part) for part in prefix.split("."))


class _Reader:
    def __init__(self, document: LoadedDocument, base: Path) -> None:
        self.document = document
        self.base = base
        self.problems: list[SchemaProblem] = []

    def problem(self, path: KeyPath, message: str, *, key: bool = False) -> None:
        where = self.document.key_location(path) if key else self.document.value_location(path)
        self.problems.append(SchemaProblem(where, ".".join(map(str, path)), message))

    def manifest(self) -> Manifest:
        data = self.document.data
        if not isinstance(data, dict):
            self.problem((), f"a manifest is a mapping with {FORMAT_KEY}: 1 and nodes:")
            return Manifest((), ())
        if data.get(FORMAT_KEY) != 1:
            self.problem((FORMAT_KEY,), f"write {FORMAT_KEY}: 1 (the format version)")
        for key in data:
            if key not in (FORMAT_KEY, "known", "nodes", "rules"):
                self.problem((key,), f"unknown key {key!r} (known: known, nodes, rules)", key=True)
        nodes = data.get("nodes")
        if not isinstance(nodes, dict) or not nodes:
            self.problem(("nodes",), "nodes: a mapping of node names to their schemas")
            nodes = {}
        entries = tuple(self.node(str(name), value) for name, value in nodes.items())
        rules, problems = read_rules(data.get("rules", []), self.location)
        self.problems.extend(problems)
        return Manifest(entries, self.names(("known",), data.get("known", [])), rules)

    def location(self, path: tuple[object, ...], key: bool) -> Location:
        keys: KeyPath = tuple(p for p in path if isinstance(p, str | int))
        return self.document.key_location(keys) if key else self.document.value_location(keys)

    def node(self, name: str, value: Any) -> NodeEntry:
        path: KeyPath = ("nodes", name)
        problem = node_pattern_problem(name)
        if problem is not None:
            self.problem(path, f"invalid node name: {problem}", key=True)
        if value is None:
            value = {}
        if not isinstance(value, dict):
            self.problem(path, "a mapping with schemas: and known:")
            return NodeEntry(absolute(name), (), ())
        for key in value:
            if key not in ("schemas", "known"):
                self.problem((*path, key), f"unknown key {key!r} (known: schemas, known)", key=True)
        schemas = value.get("schemas", [])
        if not isinstance(schemas, list):
            self.problem((*path, "schemas"), "a list of schema files")
            schemas = []
        refs = tuple(
            ref
            for index, item in enumerate(schemas)
            if (ref := self.schema((*path, "schemas", index), item)) is not None
        )
        known = self.names((*path, "known"), value.get("known", []))
        return NodeEntry(absolute(name), refs, known)

    def schema(self, path: KeyPath, item: Any) -> SchemaRef | None:
        if isinstance(item, str):
            return SchemaRef(self.base / item)
        if isinstance(item, dict) and isinstance(item.get("schema"), str):
            prefix = item.get("prefix", "")
            extra = set(item) - {"schema", "prefix"}
            if extra or not isinstance(prefix, str) or (prefix and not _valid_prefix(prefix)):
                self.problem(path, "write {schema: FILE, prefix: dotted.name}")
                return None
            return SchemaRef(self.base / item["schema"], prefix)
        self.problem(path, "a schema file, or {schema: FILE, prefix: dotted.name}")
        return None

    def names(self, path: KeyPath, value: Any) -> tuple[str, ...]:
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            self.problem(path, "a list of parameter names (globs such as '*.type' too)")
            return ()
        return tuple(value)
