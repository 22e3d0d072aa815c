"""Check the sections a node gets against one schema, offline, as the node would on start.

Values go through the runtime's own type conversion (``ParamType.from_ros``)
and checks (``CompiledParam.check``, built by ``compile_param`` from the same
spec a generated module holds), so what passes here passes on the robot and
what fails here makes the node refuse to start. Entries the schema does
not own are collected, not reported: other schemas on the same node, rclpy and
frameworks may own them (check_params decides).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from genparams.paramsfile.params_reader import ParamEntry, Section
from genparams.runtime.core.entries import expand, override_keys
from genparams.runtime.core.naming import ENTRY_KEY, ENTRY_KEY_RULE, OVERRIDE_KEYS, is_entry_key
from genparams.runtime.core.spec import CompiledParam
from genparams.runtime.core.types import ValueTypeError
from genparams.runtime.core.validators import Custom
from genparams.schema.errors import Location, SchemaProblem
from genparams.schema.model import Schema
from genparams.schema.specs import compiled_schema


class SectionChecker:
    def __init__(self, schema: Schema, file: str) -> None:
        self.schema = schema
        self.file = file
        self.problems: list[SchemaProblem] = []
        self.warnings: list[SchemaProblem] = []
        self.unknown_entries: list[ParamEntry] = []  # owned by nothing in this schema
        self.deprecated = {p.ros_name: p.deprecated for p in schema.parameters if p.deprecated}
        compiled = compiled_schema(schema)
        self.compiled = compiled.replaced(
            parameters={n: self.offline(p) for n, p in compiled.parameters.items()},
            templates={n: self.offline(p) for n, p in compiled.templates.items()},
        )
        self.params: dict[str, CompiledParam] = dict(self.compiled.parameters)
        self.old_names: dict[str, ParamEntry] = {}  # old name -> the entry that used it
        self.conditions: dict[str, Any] = {}  # start values that conditions (when) read

    def offline(self, param: CompiledParam) -> CompiledParam:
        """The checks that can run here: a custom validator whose module is missing is skipped."""
        kept = []
        for check in param.checks:
            if isinstance(check, Custom):
                try:
                    check.resolve()
                except Exception as exc:
                    self.warnings.append(
                        SchemaProblem(
                            Location(self.file, 1, 1),
                            param.name,
                            f"warning: custom validator {check.target} not checked "
                            f"(cannot import it here: {type(exc).__name__})",
                        )
                    )
                    continue
            kept.append(check)
        return param.with_checks(tuple(kept))

    def run(self, applied: Sequence[Section], nodes: Sequence[tuple[str, list[Section]]]) -> None:
        """Check the entries of ``applied``, then each node's required parameters and rules.

        ``nodes`` pairs each node ("" when unnamed) with its sections in rcl's order.
        """
        self.params.update(expand(self.compiled, self.key_lists(applied)))
        self.conditions = self.start_values(applied)
        for section in applied:
            for entry in section.entries:
                self.entry(entry)
        self.renamed_twice(applied)
        for node, sections in nodes:
            self.required(node, sections)
            self.rules(node, sections)

    def names(self) -> list[str]:
        """Every name this schema owns, for suggestions."""
        return [*self.params, *self.compiled.templates]

    def key_lists(self, sections: Sequence[Section]) -> dict[str, Any]:
        """The items of each for_each parameter: as the file gives them (valid), else default."""
        names = [entry.name for section in sections for entry in section.entries]
        keys: dict[str, Any] = dict(override_keys(self.compiled, names, str)[0])  # open groups
        for name in set(self.compiled.maps.values()) & set(self.compiled.parameters):
            param = self.params[name]
            if not param.spec.required:
                keys[name] = param.type.coerce_default(param.spec.default)
        for section in sections:
            for entry in section.entries:
                name = self.compiled.aliases.get(entry.name, entry.name)
                if name in keys or name in self.compiled.maps.values():
                    try:
                        value = self.params[name].type.from_ros(entry.value)
                    except ValueTypeError:
                        continue
                    if self.params[name].check(value) is None:
                        keys[name] = value
        return keys

    def entry(self, entry: ParamEntry) -> None:
        param = self.params.get(entry.name)
        current = self.compiled.aliases.get(entry.name)
        if param is None and current is not None:
            self.warnings.append(
                SchemaProblem(
                    entry.key_location,
                    entry.name,
                    f"warning: deprecated: old name of {current}; write {current}",
                )
            )
            self.old_names[entry.name] = entry
            param = self.params[current]
        if param is None:
            if not self.in_open_namespace(entry) and not self.unmapped(entry):
                self.unknown(entry)
            return
        if entry.name in self.deprecated:
            self.warnings.append(
                SchemaProblem(
                    entry.key_location,
                    entry.name,
                    f"warning: deprecated: {self.deprecated[entry.name]}",
                )
            )
        if param.spec.optional and entry.value is None:
            return  # "not set" (ROS reads [] so): the node leaves an optional parameter unset
        if not param.spec.declared_with(self.conditions):
            message = f"warning: {param.spec.condition_text}: the node ignores this value"
            self.warnings.append(SchemaProblem(entry.key_location, entry.name, message))
            return
        try:
            value = param.type.from_ros(entry.value)
        except ValueTypeError as exc:
            message = f"wrong type: {exc}"
            if entry.written_empty:
                message = (
                    'ROS reads an empty list as "not set", which the node refuses: '
                    "leave the parameter out to keep its default"
                )
            self.problems.append(SchemaProblem(entry.value_location, entry.name, message))
            return
        reason = param.check(value)
        if reason is not None:
            self.problems.append(SchemaProblem(entry.value_location, entry.name, reason))

    def in_open_namespace(self, entry: ParamEntry) -> bool:
        """Under a namespace other code declares: not the schema's to check."""
        parts = entry.name.split(".")
        return any(
            len(parts) > len(ns.path)
            and all(t in (p, ENTRY_KEY) for p, t in zip(parts, ns.path, strict=False))
            for ns in self.schema.open_namespaces
        )

    def unmapped(self, entry: ParamEntry) -> bool:
        """An entry of a mapped group for a key the key list does not hold; False if none."""
        parts = entry.name.split(".")
        for template in self.compiled.templates:
            pattern = template.split(".")
            if len(pattern) != len(parts) or any(
                t not in (p, ENTRY_KEY) for p, t in zip(parts, pattern, strict=True)
            ):
                continue
            keys = [p for p, t in zip(parts, pattern, strict=True) if t == ENTRY_KEY]
            maps = [".".join(pattern[:i]) for i, t in enumerate(pattern) if t == ENTRY_KEY]
            for key, mapped in zip(keys, maps, strict=True):
                key_name = self.compiled.maps[mapped]
                if key_name == OVERRIDE_KEYS:
                    key_name = f"the keys under {mapped}"
                if not is_entry_key(key):
                    message = (
                        f"unknown parameter: {key!r} cannot be an item of {key_name} (use "
                        f"{ENTRY_KEY_RULE}): no entry would ever have this name"
                    )
                    self.problems.append(SchemaProblem(entry.key_location, entry.name, message))
                    return True
            key_names = ", ".join(self.compiled.maps[m] for m in maps)
            self.warnings.append(
                SchemaProblem(
                    entry.key_location,
                    entry.name,
                    f"warning: {'.'.join(keys)!r} is not among the items of {key_names}; "
                    "the node uses this only once they hold it",
                )
            )
            return True
        return False

    def renamed_twice(self, sections: Sequence[Section]) -> None:
        """An old name and the current one, given different values: the node refuses."""
        given = {e.name: e for section in sections for e in section.entries}
        for old, entry in self.old_names.items():
            current = self.compiled.aliases[old]
            if current in given and given[current].value != entry.value:
                self.problems.append(
                    SchemaProblem(
                        entry.key_location,
                        old,
                        f"old name of {current}, which is given another value: keep only {current}",
                    )
                )

    def unknown(self, entry: ParamEntry) -> None:
        self.unknown_entries.append(entry)

    def required(self, node: str, sections: list[Section]) -> None:
        given = {
            self.compiled.aliases.get(entry.name, entry.name)
            for section in sections
            for entry in section.entries
        }
        where = sections[-1].params_location if sections else Location(self.file, 1, 1)
        conditions = self.start_values(sections)
        for name, param in self.params.items():
            if not param.spec.declared_with(conditions):
                continue  # left out by its condition: nothing to give
            # An adopted parameter may get its value from the code that declares it first.
            if param.spec.required and not param.spec.adopt and name not in given:
                for_node = f" for {node}" if node else ""
                self.problems.append(
                    SchemaProblem(
                        where,
                        name,
                        f"required parameter is not set{for_node} "
                        f"(it has no default: add {name.rsplit('.', 1)[-1]}: "
                        f"<{param.type.name}>)",
                    )
                )

    def start_values(self, sections: Sequence[Section]) -> dict[str, Any]:
        """The fixed parameters' values a node would start with: defaults, then the valid
        values of ``sections``."""
        values: dict[str, Any] = {}
        for name, param in self.compiled.parameters.items():
            if not (param.spec.required or param.spec.optional):
                values[name] = param.type.coerce_default(param.spec.default)
        for section in sections:
            for entry in section.entries:
                name = self.compiled.aliases.get(entry.name, entry.name)
                given = self.compiled.parameters.get(name)
                if given is None:
                    continue
                try:
                    value = given.type.from_ros(entry.value)
                except ValueTypeError:
                    continue
                if given.check(value) is None:
                    values[name] = value
        return values

    def rules(self, node: str, sections: list[Section]) -> None:
        """Rules over the values the node would start with: its defaults, then this file."""
        if not self.compiled.rules:
            return
        conditions = self.start_values(sections)
        values: dict[str, Any] = {}
        unusable: set[str] = set()  # given with a wrong value, already reported
        entries: dict[str, ParamEntry] = {}
        for name, param in self.compiled.parameters.items():
            if param.spec.optional:
                values[name] = None  # not set: rules reading it are not checked
            elif not param.spec.required:
                values[name] = param.type.coerce_default(param.spec.default)
        for section in sections:
            for entry in section.entries:
                name = self.compiled.aliases.get(entry.name, entry.name)
                if name not in self.compiled.parameters:
                    continue
                param = self.compiled.parameters[name]
                entries[name] = entry
                try:
                    value = param.type.from_ros(entry.value)
                except ValueTypeError:
                    unusable.add(name)
                    continue
                if param.check(value) is None:
                    values[name] = value
                    unusable.discard(name)
                else:
                    unusable.add(name)
        for name, param in self.compiled.parameters.items():
            if not param.spec.declared_with(conditions):
                values[name] = None  # left out by its condition: rules reading it hold
        for rule in self.compiled.rules:
            if any(n not in values or n in unusable for n in rule.parameters):
                continue  # a required parameter missing, or a bad value: already reported
            reason = rule.violation(values)
            if reason is None:
                continue
            given = [entries[n] for n in rule.parameters if n in entries]
            where = given[0].key_location if given else Location(self.file, 1, 1)
            key = given[0].name if given else ""
            for_node = f" (for {node})" if node else ""
            self.problems.append(SchemaProblem(where, key, reason + for_node))
