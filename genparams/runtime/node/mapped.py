"""Mapped groups (``for_each``): one group of parameters per item of a string_array parameter.

A mapped group's parameters are templates (``gains.*.p``). The entries that
exist are the templates expanded over the current items of each map's key
parameter (``gains.shoulder.p``). When a key parameter changes, the entries of
new items are checked in the on-set round (a bad override for one of them
rejects the change), then declared, and the entries of removed items
undeclared, from the post-set callback; the typed view moves to the new shape
in one commit, so no snapshot ever sees keys and entries disagree.

The work is split in two: ``plan`` computes what a change of keys does (the
entries to declare and undeclare, every value after it, the changes), and the
binding applies the plan in one place (``Binding.apply``).

Two on-set checks keep node and view in step around that:

- The new entries and the removals are shown to every other on-set callback of
  the node in the on-set round, so a callback that would refuse them refuses
  the change of keys instead of leaving keys without entries.
- A set of an entry that is not declared is refused. rclpy checks that a
  parameter is declared before it takes the set lock: a set of an entry racing
  a change of keys that removes it, or any set on a node that allows
  undeclared parameters, would otherwise store it as a stray parameter
  that blocks the key from ever coming back.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime.core.changes import Change
from genparams.runtime.core.entries import expand, key_slot, map_chain, open_maps, template_keys
from genparams.runtime.core.naming import join_prefix, strip_prefix
from genparams.runtime.core.problems import ParameterProblem, render_problems
from genparams.runtime.core.resolve import resolve_values
from genparams.runtime.core.spec import CompiledParam, CompiledSchema
from genparams.runtime.core.tree import get_path
from genparams.runtime.node import rclpy_internals as internals
from genparams.runtime.node.declaring import descriptor_for, replace_batch, ros_parameter
from genparams.runtime.node.deprecation import Notices
from genparams.runtime.node.overrides import OverrideReader


@dataclass(frozen=True)
class EntryOwner:
    """What mapped entries use of the class declared on a node that owns them."""

    node: Node
    prefix: str
    declared: Mapping[str, CompiledParam]  # its parameters by full ROS name, kept current by it
    own_check: Callable[[Sequence[Parameter]], SetParametersResult]  # genparams' on-set callback


@dataclass(frozen=True)
class EntryPlan:
    """What one change of keys does: entries in and out, every value after it, the changes."""

    declare: Mapping[str, CompiledParam]  # relative name -> parameter of each new entry
    declare_values: Mapping[str, Any]  # their starting values (override, else default)
    undeclare: Sequence[str]  # relative names of the entries of removed keys
    entries: dict[str, CompiledParam]  # the table of entries after the change
    values: Mapping[str, Any]  # every parameter's value after the change, by relative name
    changed: list[Change]
    reader: OverrideReader  # releases what rclpy pre-declared from overrides
    given: Sequence[str]  # new entries an override was given for (deprecation notices)


class MappedEntries:
    """Keeps the mapped entries of one declared class in step with its key parameters."""

    def __init__(
        self,
        owner: EntryOwner,
        compiled: CompiledSchema,
        entries: Mapping[str, CompiledParam],
        notices: Notices,
    ) -> None:
        self.owner = owner
        self.compiled = compiled
        self.notices = notices
        self.full_name = functools.partial(join_prefix, owner.prefix)
        self.entries = dict(entries)  # relative name -> parameter, in key order
        # relative names of key parameters (open groups have none: their keys stay)
        self.key_names = frozenset(n for n in compiled.maps.values() if n in compiled.parameters)
        self.keys_by_full_name = {self.full_name(k): k for k in self.key_names}
        self.templates = tuple(compiled.templates)  # "gains.*.p"
        self.open_keys = self._open_keys()  # the keys of open groups, fixed at declaration

    def _open_keys(self) -> dict[str, list[str]]:
        """The keys of each open group (``for_each: overrides``), by key slot, as declared."""
        keys: dict[str, list[str]] = {}
        for map_path in open_maps(self.compiled):
            found = keys.setdefault(key_slot(self.compiled, map_path), [])
            for template in self.templates:
                chain = map_chain(template)
                if map_path not in chain:
                    continue
                for name in self.entries:
                    filled = template_keys(template, name)
                    if filled is not None and filled[chain.index(map_path)] not in found:
                        found.append(filled[chain.index(map_path)])
        return keys

    @classmethod
    def attach(
        cls,
        owner: EntryOwner,
        compiled: CompiledSchema,
        parameters: Mapping[str, CompiledParam],
        notices: Notices,
    ) -> MappedEntries | None:
        if not compiled.maps:
            return None
        entries = {n: p for n, p in parameters.items() if n not in compiled.parameters}
        return cls(owner, compiled, entries, notices)

    def changes_keys(self, updates: Mapping[CompiledParam, Any]) -> bool:
        return any(param.name in self.key_names for param in updates)

    def check(
        self,
        current: Any,
        parameters: Sequence[Parameter],
        typed: Mapping[CompiledParam, Any],
        declaring: bool,
    ) -> list[ParameterProblem]:
        """Refuse sets of undeclared entries, and changes of keys whose new entries cannot be
        declared (bad override, refused by another on-set callback). ``current`` is the
        owner's committed view."""
        if not declaring:  # the entries' own declaration round declares them
            strays = self.strays(parameters)
            if strays:
                return strays
        proposed = {
            param.name: value
            for param, value in typed.items()
            if param.name in self.key_names and param.check(value) is None
        }
        if not proposed:
            return []
        values = {
            name: get_path(current, self.compiled.parameters[name].attribute_path)
            for name in self.key_names
        }
        values.update(proposed)
        expanded = expand(self.compiled, {**values, **self.open_keys}, self.entries)
        added = {n: p for n, p in expanded.items() if n not in self.entries}
        reader = OverrideReader(self.owner.node, self.full_name)
        new_values, problems = resolve_values(
            self.compiled, reader.read(added), self.full_name, parameters=added
        )
        problems = reader.with_problems(problems)
        changed = ", ".join(self.full_name(name) for name in proposed)
        if problems:
            reasons = render_problems(problems)
            return [ParameterProblem(changed, f"cannot declare the new entries: {reasons}")]
        removed = [name for name in self.entries if name not in expanded]
        refusal = self._refusal_of_others(added, new_values, removed)
        if refusal is None:
            return []
        return [ParameterProblem(changed, f"the new entries were refused: {refusal}")]

    def strays(self, parameters: Sequence[Parameter]) -> list[ParameterProblem]:
        """A problem per parameter of a request that has an entry's name but is not declared."""
        return [
            ParameterProblem(p.name, "no such entry: its key is not in the key list")
            for p in parameters
            if self.is_undeclared_entry(p.name)
        ]

    def is_undeclared_entry(self, full_name: str) -> bool:
        """``full_name`` has the shape of an entry of the owner but is not declared."""
        if full_name in self.owner.declared:
            return False
        name = strip_prefix(self.owner.prefix, full_name)
        if name is None:
            return False
        shaped = any(template_keys(template, name) is not None for template in self.templates)
        return shaped and not self.owner.node.has_parameter(full_name)

    def _refusal_of_others(
        self,
        added: Mapping[str, CompiledParam],
        values: Mapping[str, Any],
        removed: Sequence[str],
    ) -> str | None:
        """What another on-set callback of the node says to the entries' declaration round."""
        node = self.owner.node
        batch = [ros_parameter(p, self.full_name(n), values[n]) for n, p in added.items()]
        batch.extend(Parameter(self.full_name(name)) for name in removed)
        if not batch:
            return None
        ours = self.owner.own_check  # genparams' own check passes the round by design
        for callback in internals.on_set_callbacks(node):
            if callback == ours:
                continue
            result = callback(batch)
            if isinstance(result, SetParametersResult) and not result.successful:
                return str(result.reason)
        return None

    def plan(self, current: Any, updates: Mapping[CompiledParam, Any]) -> EntryPlan | None:
        """The plan of a change of keys the node stored; None if its entries cannot be made."""
        owner = self.owner
        values = {p.name: get_path(current, p.attribute_path) for p in owner.declared.values()}
        changed = []
        for param, value in updates.items():
            if values[param.name] != value:
                changed.append(Change(param.name, values[param.name], value))
                values[param.name] = value
        # A parameter left out by its condition (``when``) is None.
        fixed = {name: values.get(name) for name in self.compiled.parameters}
        entries = expand(self.compiled, {**fixed, **self.open_keys}, self.entries)
        added = {n: p for n, p in entries.items() if n not in self.entries}
        removed = [n for n in self.entries if n not in entries]
        reader = OverrideReader(owner.node, self.full_name)
        given = reader.read(added)
        new_values, problems = resolve_values(
            self.compiled, given, self.full_name, parameters=added
        )
        problems = reader.with_problems(problems)
        if problems:
            owner.node.get_logger().error(
                "mapped entries keep their previous keys: " + render_problems(problems)
            )
            return None
        changed.extend(Change(name, values[name], None) for name in removed)
        changed.extend(Change(name, None, new_values[name]) for name in added)
        after = dict(fixed)
        for name in entries:
            after[name] = new_values[name] if name in added else values[name]
        return EntryPlan(added, new_values, removed, entries, after, changed, reader, list(given))

    def replace_on_node(self, plan: EntryPlan) -> bool:
        """Declare the plan's new entries and undeclare its removed ones, in one atomic change;
        the plan's table of entries is then this one's."""
        declarations = []
        for name, param in plan.declare.items():
            full_name = self.full_name(name)
            declarations.append(
                (
                    ros_parameter(param, full_name, plan.declare_values[name]),
                    descriptor_for(param, full_name),
                )
            )
        plan.reader.release_predeclared()
        node = self.owner.node
        result = replace_batch(node, declarations, [self.full_name(n) for n in plan.undeclare])
        if not result.successful:
            node.get_logger().error(f"cannot change mapped entries: {result.reason}")
            return False
        self.entries = plan.entries
        for name in plan.given:
            if plan.declare[name].spec.deprecated:
                self.notices.deprecated(self.full_name(name), plan.declare[name].spec.deprecated)
        return True
