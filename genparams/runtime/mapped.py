"""Mapped groups (``for_each``): one group of parameters per item of a string_array parameter.

A mapped group's parameters are templates (``gains.*.p``). The entries that
exist are the templates expanded over the current items of each map's key
parameter (``gains.shoulder.p``). When a key parameter changes, the entries of
new items are checked in the on-set round (a bad override for one of them
rejects the change), then declared, and the entries of removed items
undeclared, from the post-set callback; the typed view moves to the new shape
in one commit, so no snapshot ever sees keys and entries disagree.

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
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from rcl_interfaces.msg import SetParametersResult
from rclpy.parameter import Parameter

from genparams.runtime.changes import Change
from genparams.runtime.declaring import descriptor_for, replace_batch, ros_parameter
from genparams.runtime.deprecation import Notices
from genparams.runtime.entries import expand, template_keys
from genparams.runtime.naming import join_prefix, strip_prefix
from genparams.runtime.overrides import OverrideReader
from genparams.runtime.resolve import resolve_values
from genparams.runtime.spec import CompiledParam, CompiledSchema
from genparams.runtime.tree import build_tree, field_names, get_path

if TYPE_CHECKING:
    from genparams.runtime.binding import Binding

_ACCEPTED = SetParametersResult(successful=True)


class MappedEntries:
    """Keeps one binding's mapped entries in step with its key parameters."""

    def __init__(
        self,
        binding: Binding[Any],
        compiled: CompiledSchema,
        entries: Mapping[str, CompiledParam],
        notices: Notices,
    ) -> None:
        self.binding = binding
        self.compiled = compiled
        self.notices = notices
        self.full_name = functools.partial(join_prefix, binding.prefix)
        self.entries = dict(entries)  # relative name -> parameter, in key order
        self.key_names = frozenset(compiled.maps.values())  # relative names of key parameters
        self.keys_by_full_name = {self.full_name(k): k for k in self.key_names}
        self.templates = tuple(compiled.templates)  # "gains.*.p"
        self.replacing = False  # True while this binding declares and undeclares its entries

    @classmethod
    def attach(
        cls,
        binding: Binding[Any],
        compiled: CompiledSchema,
        parameters: Mapping[str, CompiledParam],
        notices: Notices,
    ) -> MappedEntries | None:
        if not compiled.maps:
            return None
        entries = {n: p for n, p in parameters.items() if n not in compiled.parameters}
        mapped = cls(binding, compiled, entries, notices)
        binding.node.add_on_set_parameters_callback(mapped.on_set)
        return mapped

    def changes_keys(self, updates: Mapping[CompiledParam, Any]) -> bool:
        return any(param.name in self.key_names for param in updates)

    def on_set(self, parameters: Sequence[Parameter]) -> SetParametersResult:
        """Reject a change of keys whose new entries cannot be declared (bad override, ...)."""
        if not self.replacing:
            strays = [p.name for p in parameters if self.is_undeclared_entry(p.name)]
            if strays:
                return SetParametersResult(
                    successful=False,
                    reason="; ".join(
                        f"{name}: no such entry: its key is not in the key list" for name in strays
                    ),
                )
        proposed: dict[str, Any] = {}
        for parameter in parameters:
            key_name = self.keys_by_full_name.get(parameter.name)
            if key_name is None:
                continue
            param = self.compiled.parameters[key_name]
            try:
                keys = param.type.from_ros(parameter.value)
            except ValueError:
                continue  # the binding's own check names the problem
            if param.check(keys) is None:
                proposed[key_name] = keys
        if not proposed:
            return _ACCEPTED
        values = {
            name: get_path(self.binding.current, self.compiled.parameters[name].attribute_path)
            for name in self.key_names
        }
        values.update(proposed)
        expanded = expand(self.compiled, values, self.entries)
        added = {n: p for n, p in expanded.items() if n not in self.entries}
        reader = OverrideReader(self.binding.node, self.full_name)
        new_values, problems = resolve_values(
            self.compiled, reader.read(added), self.full_name, parameters=added
        )
        problems = reader.with_problems(problems)
        changed = ", ".join(self.full_name(name) for name in proposed)
        if problems:
            return SetParametersResult(
                successful=False,
                reason=f"{changed}: cannot declare the new entries: " + "; ".join(problems),
            )
        removed = [name for name in self.entries if name not in expanded]
        refusal = self._refusal_of_others(added, new_values, removed)
        if refusal is None:
            return _ACCEPTED
        return SetParametersResult(
            successful=False, reason=f"{changed}: the new entries were refused: {refusal}"
        )

    def is_undeclared_entry(self, full_name: str) -> bool:
        """``full_name`` has the shape of an entry of this binding but is not declared."""
        if full_name in self.binding.owned:
            return False
        name = strip_prefix(self.binding.prefix, full_name)
        if name is None:
            return False
        shaped = any(template_keys(template, name) is not None for template in self.templates)
        return shaped and not self.binding.node.has_parameter(full_name)

    def _refusal_of_others(
        self,
        added: Mapping[str, CompiledParam],
        values: Mapping[str, Any],
        removed: Sequence[str],
    ) -> str | None:
        """What another on-set callback of the node says to the entries' declaration round."""
        node = self.binding.node
        batch = [ros_parameter(p, self.full_name(n), values[n]) for n, p in added.items()]
        batch.extend(Parameter(self.full_name(name)) for name in removed)
        if not batch:
            return None
        ours = (self.on_set, self.binding.on_set)  # they pass the round itself by design
        for callback in tuple(node._on_set_parameters_callbacks):
            if callback in ours:
                continue
            result = callback(batch)
            if isinstance(result, SetParametersResult) and not result.successful:
                return str(result.reason)
        return None

    def reshape(self, updates: Mapping[CompiledParam, Any]) -> None:
        """Commit a change of keys: declare new entries, undeclare removed ones, one commit."""
        binding = self.binding
        with binding.lock:
            before = binding.current
            current = {p.name: get_path(before, p.attribute_path) for p in binding.owned.values()}
            changed = []
            for param, value in updates.items():
                if current[param.name] != value:
                    changed.append(Change(param.name, current[param.name], value))
                    current[param.name] = value
            fixed = {name: current[name] for name in self.compiled.parameters}
            entries = expand(self.compiled, fixed, self.entries)
            added = {n: p for n, p in entries.items() if n not in self.entries}
            removed = [n for n in self.entries if n not in entries]
            reader = OverrideReader(binding.node, self.full_name)
            given = reader.read(added)
            new_values, problems = resolve_values(
                self.compiled, given, self.full_name, parameters=added
            )
            problems = reader.with_problems(problems)
            if problems:
                # The on-set round checked these: only a concurrent declaration gets here.
                binding.node.get_logger().error(
                    "mapped entries keep their previous keys: " + "; ".join(problems)
                )
            if problems or not self._replace_on_node(reader, added, new_values, removed):
                binding.commit(dict(updates))
                return
            for name in given:
                if added[name].spec.deprecated:
                    self.notices.deprecated(self.full_name(name), added[name].spec.deprecated)
            changed.extend(Change(name, current[name], None) for name in removed)
            changed.extend(Change(name, None, new_values[name]) for name in added)
            values = dict(fixed)
            for name in entries:
                values[name] = new_values[name] if name in added else current[name]
            self.entries = entries
            spec = self.compiled.spec
            after = build_tree(
                type(before), spec.groups, values, extra={"_binding": None}, maps=spec.maps
            )
            binding.publish(before, after, changed, field_names(type(after)))

    def _replace_on_node(
        self,
        reader: OverrideReader,
        added: Mapping[str, CompiledParam],
        values: Mapping[str, Any],
        removed: Sequence[str],
    ) -> bool:
        owned = self.binding.owned
        # Removed entries leave the table first, so the binding's on-set check lets them go;
        # added ones join after, so their declaration round does not commit them one by one.
        dropped = {name: owned.pop(self.full_name(name)) for name in removed}
        declarations = []
        for name, param in added.items():
            full_name = self.full_name(name)
            declarations.append(
                (ros_parameter(param, full_name, values[name]), descriptor_for(param, full_name))
            )
        reader.release_predeclared()
        self.replacing = True
        try:
            result = replace_batch(
                self.binding.node, declarations, [self.full_name(n) for n in removed]
            )
        finally:
            self.replacing = False
        if not result.successful:
            for name, param in dropped.items():
                owned[self.full_name(name)] = param
            self.binding.node.get_logger().error(f"cannot change mapped entries: {result.reason}")
            return False
        for name, param in added.items():
            owned[self.full_name(name)] = param
        return True
