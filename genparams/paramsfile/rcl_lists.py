"""How rcl reads a list that holds mappings, replayed step by step.

rcl's params-file parser (rcl_yaml_param_parser/parse.c) is a state machine
over YAML events, not a tree walk. Inside a list it stays in "sequence" mode,
so a mapping in a list does not make a list of mappings: its keys extend the
parameter's name and its values become list items. ``vacuum: [{interfaces:
[suction]}]`` reaches the node as ``vacuum.interfaces: [suction]``. This
module replays that machine on the list's nodes, so genparams reads such a
list exactly as a node receives it, and can say when rcl's bookkeeping goes
astray (a second mapping in the list, a plain value in the mapping) instead of
guessing.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from genparams.paramsfile.ros_yaml import NoValue, ros_type_name
from genparams.schema.loader import Path


@dataclass
class RclRecord:
    """One parameter slot of rcl's node table: renamed as namespaces are discovered."""

    name: str
    key_path: Path
    value_path: Path | None = None
    value: Any = None


@dataclass
class _State:
    records: list[RclRecord]
    current: RclRecord
    namespace: str | None
    depth: int  # rcl's count of parameter namespaces
    is_seq: bool = True
    is_key: bool = False
    is_new_map: bool = False
    seq_type: str | None = None
    problems: list[tuple[Path, str]] = field(default_factory=list)


def contains_mapping(value: Any) -> bool:
    return isinstance(value, list) and any(isinstance(item, dict) for item in value)


def read_list(
    name: str, path: Path, items: list[Any], parent: str
) -> tuple[list[RclRecord], list[tuple[Path, str]]]:
    """The parameters rcl makes of ``name: <items>`` (at ``path``) under the namespace ``parent``.

    Returns them with what went wrong, as (path, message) pairs. A list that
    leaves rcl's namespace somewhere else than where it started is reported:
    rcl would then misname the keys that follow it.
    """
    record = RclRecord(name, path)
    depth = parent.count(".") + 1 if parent else 0
    state = _State([record], record, parent or None, depth)
    for index, item in enumerate(items):
        _replay((*path, index), item, state)
    if (state.namespace or "") != parent:
        state.problems.append(
            (
                path,
                f"rcl reads this list of mappings as {state.current.name!r} and then "
                f"misnames the keys after it: write {name}.<key>: value, not a list",
            )
        )
    return [r for r in state.records if r.value is not None], state.problems


def _replay(path: Path, value: Any, state: _State) -> None:
    if isinstance(value, list):
        if state.is_key:
            state.problems.append((path, "a list where rcl expects a key: ROS refuses the file"))
            return
        state.is_seq, state.seq_type = True, None
        for index, item in enumerate(value):
            _replay((*path, index), item, state)
        state.is_seq, state.is_key = False, True
    elif isinstance(value, dict):
        state.is_new_map, state.is_key = True, True
        for key, item in value.items():
            _key((*path, key), key, state)
            _replay((*path, key), item, state)
        if state.depth > 0:
            state.depth -= 1
            if state.depth == 0 or state.namespace is None:
                state.namespace = None
            else:
                state.namespace = state.namespace.rpartition(".")[0] or state.namespace
    else:
        _value(path, value, state)


def _key(path: Path, key: str, state: _State) -> None:
    if not state.is_key:  # rcl, still in sequence mode, takes the key for a list item
        _value(path, key, state)
        return
    if state.is_new_map:
        state.namespace, state.depth = state.current.name, state.depth + 1
        state.is_new_map = False
    if state.namespace is None:
        state.current = _find(state, key, path)
    else:
        state.current = _find(state, state.namespace, path)
        state.current.name = f"{state.namespace}.{key}"
        state.current.key_path = path
    state.is_key = False


def _value(path: Path, value: Any, state: _State) -> None:
    if isinstance(value, NoValue):
        state.problems.append((path, "no value: ROS refuses the file"))
        return
    record = state.current
    if not state.is_seq:
        record.value, record.value_path = value, path
        state.is_key = True
        return
    kind = ros_type_name(value)
    if state.seq_type is None:
        state.seq_type = kind
        record.value, record.value_path = [value], path
    elif kind != state.seq_type:
        state.problems.append(
            (path, f"a {kind} in a list of {state.seq_type}s: ROS refuses the file")
        )
    elif not isinstance(record.value, list):
        state.problems.append(
            (path, "rcl adds this value to a list it never started: ROS refuses the file")
        )
    else:
        record.value.append(value)


def _find(state: _State, name: str, path: Path) -> RclRecord:
    for record in state.records:
        if record.name == name:
            return record
    record = RclRecord(name, path)
    state.records.append(record)
    return record
