"""The rclpy glue: declare with full descriptors, check every set, commit what the node stored.

The node's coordinator (``consistency.NodeSets``) calls ``check`` in the on-set
round, after every other on-set callback, and ``commit`` once the node stored
the values, before any post-set callback runs. A veto anywhere leaves the view
untouched; a set nested in any callback is committed on its own.
"""

from __future__ import annotations

import collections
import functools
import threading
import traceback
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, Generic, TypeVar

from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime.core.changes import Change, Changes, same_typed_value, same_value
from genparams.runtime.core.entries import resolve_all
from genparams.runtime.core.errors import ParameterDeclarationError
from genparams.runtime.core.naming import check_prefix, join_prefix, strip_prefix
from genparams.runtime.core.params_view import ParamsView
from genparams.runtime.core.problems import READ_ONLY, ParameterProblem
from genparams.runtime.core.spec import CompiledParam, compile_schema
from genparams.runtime.core.tree import (
    build_tree,
    copy_node,
    field_names,
    get_path,
    replace_values,
    reuse_values,
)
from genparams.runtime.node.aliases import Aliases, old_names_by_current
from genparams.runtime.node.consistency import NodeSets, node_sets
from genparams.runtime.node.declaring import declare_batch, descriptor_for, ros_parameter
from genparams.runtime.node.deprecation import DeprecationWatch, Notices, report_overrides
from genparams.runtime.node.overrides import OverrideReader

if TYPE_CHECKING:
    from genparams.runtime.core.rule_check import RulesCheck
    from genparams.runtime.node.lifecycle import MutabilityCheck
    from genparams.runtime.node.mapped import EntryPlan, MappedEntries

P = TypeVar("P", bound=ParamsView)
_EXTRA = ("_binding",)  # the root's slot that is no field
_NOT_SET = Parameter.Type.NOT_SET  # reading an Enum member costs on every set


class Binding(Generic[P]):
    """One generated class declared on one node under one prefix."""

    def __init__(self, node: Node, prefix: str, owned: dict[str, CompiledParam]) -> None:
        self.node = node
        self.prefix = prefix
        self.owned = owned  # full ROS name -> parameter
        self.old_names: dict[str, CompiledParam] = {}  # full old name (aliases) -> parameter
        self.aliases: Aliases | None = None
        self.lock = threading.Lock()  # guards the subscriber list
        self.subscribers: list[Callable[[Changes[P]], None]] = []
        self.current: P  # the frozen root: snapshots hand this out
        self.live: P  # the root users hold: top-level attributes follow `current`
        # The root `current` replaced, which no reader can reach any more: the next
        # commit brings it up to date (`behind`: the changes it misses) instead of
        # copying `current` (see tree.reuse_values); None after a change of shape.
        self.spare: P | None = None
        self.behind: dict[tuple[str, ...], Any] = {}
        self.mapped: MappedEntries | None = None
        # Loaded only by a class that has rules, or configure-only parameters.
        self.broken_rules: RulesCheck | None = None
        self.mutability_problem: MutabilityCheck | None = None
        self.sets: NodeSets
        self.schema_name = ""

    @classmethod
    def declare(cls, params_cls: type[P], node: Node, prefix: str = "") -> Binding[P]:
        sets = node_sets(node)
        with sets.lock:  # no set may run between declaring and validating
            binding = cls._declare(params_cls, node, check_prefix(prefix), sets)
            sets.bindings.append(binding)
            return binding

    @classmethod
    def _declare(cls, params_cls: type[P], node: Node, prefix: str, sets: NodeSets) -> Binding[P]:
        spec = params_cls._SPEC
        compiled = compile_schema(spec)
        full = functools.partial(join_prefix, prefix)
        twice = [b for b in sets.bindings if type(b.live) is params_cls and b.prefix == prefix]
        if twice:
            where = f"prefix {prefix!r}" if prefix else "the root"
            raise ParameterDeclarationError(
                spec.name,
                node.get_fully_qualified_name(),
                [
                    ParameterProblem(
                        "",
                        f"{params_cls.__name__} is already declared at {where}: declare a class "
                        "once per prefix and share the view it returns",
                    )
                ],
            )

        reader = OverrideReader(
            node, full, old_names_by_current(compiled.aliases), adopted=compiled.adopted
        )
        given_names = (strip_prefix(prefix, name) for name in reader.overrides)
        parameters, values, problems = resolve_all(
            compiled, reader.read, full, given_names=[n for n in given_names if n is not None]
        )
        clashes = [
            ParameterProblem(full(name), f"already declared on this node by {owner.schema_name}")
            for name in parameters
            if (owner := sets.owner_of(full(name))) is not None
        ]
        # The reader's "declared by other code" of a name a clash already explains goes.
        clashing = {clash.key for clash in clashes}
        problems = [
            *clashes,
            *(p for p in reader.with_problems(problems) if p.key not in clashing),
        ]
        if problems:
            raise ParameterDeclarationError(spec.name, node.get_fully_qualified_name(), problems)

        reader.release_predeclared()
        notices = Notices(node)
        aliases = Aliases(notices, compiled.aliases, full)
        owned = {full(name): param for name, param in parameters.items()}
        by_full_name = {full(name): value for name, value in values.items()}
        declare_batch(
            node,
            [
                (
                    ros_parameter(p, full(name), by_full_name[full(name)]),
                    descriptor_for(p, full(name), compiled.rules_by_parameter.get(name, ())),
                )
                for name, p in parameters.items()
            ]
            + aliases.declarations(owned, by_full_name),
            spec.name,
        )
        given = [name for name in reader.given if name in parameters]  # conditions that hold
        report_overrides(notices, parameters, given, reader.renamed, full)

        binding: Binding[P] = cls(node, prefix, owned)
        binding.sets = sets
        binding.schema_name = params_cls.__name__
        binding.old_names = {old: owned[cur] for old, cur in aliases.current_of.items()}
        if compiled.rules:
            from genparams.runtime.core.rule_check import broken_rules

            binding.broken_rules = broken_rules
        every = (*compiled.parameters.values(), *compiled.templates.values())
        if any(p.spec.configure_only for p in every):
            from genparams.runtime.node.lifecycle import mutability_problem

            binding.mutability_problem = mutability_problem
        binding.current = build_tree(
            params_cls, spec.groups, values, extra={"_binding": None}, maps=spec.maps
        )
        live = copy_node(binding.current)
        object.__setattr__(live, "_binding", binding)
        binding.live = live
        if any(param.type.is_array for param in every):
            sets.retype_empty_arrays(collections.ChainMap(binding.owned, binding.old_names))
        # Mapped groups, old names and deprecations each watch the node on their own.
        if compiled.maps:  # loaded only by classes that have mapped groups
            from genparams.runtime.node.mapped import EntryOwner, MappedEntries

            entry_owner = EntryOwner(node, prefix, binding.owned, sets.check)
            binding.mapped = MappedEntries.attach(entry_owner, compiled, parameters, notices)
            if binding.mapped is not None:
                sets.explain_undeclared_entries()
        if compiled.aliases:
            binding.aliases = aliases
            sets.add_renames(aliases.mirrored)
        DeprecationWatch.attach(node, notices, binding.owned, compiled)
        return binding

    def declares(self, full_name: str) -> bool:
        return full_name in self.owned or full_name in self.old_names

    def check(
        self, parameters: Sequence[Parameter], declaring: bool
    ) -> dict[CompiledParam, Any] | list[ParameterProblem]:
        """This class's part of a request, typed, or the problems it is refused for."""
        if self.aliases is not None and not declaring:
            renamed = self.aliases.problems(parameters)
            if renamed:
                return renamed
        typed, reasons = check_each(self.owned, parameters)
        if self.mapped is not None and not reasons:
            reasons.extend(self.mapped.check(self.current, parameters, typed, declaring))
        if reasons:
            return reasons
        if not typed:
            return typed
        if self.mutability_problem is not None and not declaring:
            reasons = self.mutability_problem(self.node, typed, self.full_name)
        if not reasons and self.broken_rules is not None:
            proposed = {param.name: value for param, value in typed.items()}
            reasons = self.broken_rules(self.current, proposed, self.full_name)
        return reasons or typed

    def full_name(self, name: str) -> str:
        return join_prefix(self.prefix, name)

    def refusals(self, parameters: Sequence[Parameter]) -> list[ParameterProblem]:
        """Why each of this class's values in a request (current or old names) is refused on
        its own: read-only, then as ``check_each`` refuses it."""
        return refusals(collections.ChainMap(self.owned, self.old_names), parameters)

    def undeclared_entries(self, parameters: Sequence[Parameter]) -> list[ParameterProblem]:
        mapped = self.mapped
        return [] if mapped is None else mapped.strays(parameters)

    def commit(self, updates: dict[CompiledParam, Any]) -> bool:
        """Commit values the node stored; False (nothing done) when they change mapped keys."""
        mapped = self.mapped
        if mapped is not None and mapped.changes_keys(updates):
            return False
        before = self.current
        # Change records are built only for subscribers: a set is on the hot path.
        subscribed = bool(self.subscribers)
        changed = []
        paths = {}
        for param, value in updates.items():
            path = param.attribute_path
            old = get_path(before, path)
            unchanged = old == value or (
                (old != old or type(old) is tuple) and same_value(old, value)
            )  # only a NaN or an array may equal without ==
            if unchanged and (not param.type.is_dynamic or same_typed_value(old, value)):
                continue  # no change (a dynamic parameter's 1 -> 1.0 is one)
            paths[path] = value
            if subscribed:
                changed.append(Change(param.name, old, value))
        if not paths:
            return True
        if self.spare is None:
            self.publish(before, replace_values(before, paths, _EXTRA), changed, paths)
            return True
        behind = self.behind
        behind.update(paths)
        self.spare = reuse_values(self.spare, behind, _EXTRA)
        self.publish(before, self.spare, changed, paths, behind)
        return True

    def reshape(self, updates: dict[CompiledParam, Any]) -> None:
        """Commit a change of mapped keys: the entries' plan, applied in one place."""
        mapped = self.mapped
        plan = None if mapped is None else mapped.plan(self.current, updates)
        if plan is None or not self.apply(plan):
            # Only a concurrent declaration gets here (the on-set round checked the
            # entries): the keys change, the entries keep their previous shape.
            self.commit_values(updates)

    def apply(self, plan: EntryPlan) -> bool:
        """Declare and undeclare the plan's entries on the node, then commit its values."""
        mapped = self.mapped
        if mapped is None:
            return False
        full = self.full_name
        owned = self.owned
        # Removed entries leave the table first, so the check lets them go; added ones
        # join after, so their declaration round does not commit them one by one.
        dropped = {full(name): owned.pop(full(name)) for name in plan.undeclare}
        if not mapped.replace_on_node(plan):
            owned.update(dropped)
            return False
        owned.update((full(name), param) for name, param in plan.declare.items())
        before = self.current
        spec = type(before)._SPEC
        after = build_tree(
            type(before), spec.groups, plan.values, extra={"_binding": None}, maps=spec.maps
        )
        self.publish(
            before, after, plan.changed, None, {(head,): None for head in field_names(type(after))}
        )
        return True

    def commit_values(self, updates: dict[CompiledParam, Any]) -> None:
        paths = {param.attribute_path: value for param, value in updates.items()}
        before = self.current
        after = replace_values(before, paths, extra=("_binding",))
        changed = [
            Change(p.name, get_path(before, p.attribute_path), v) for p, v in updates.items()
        ]
        self.publish(before, after, changed, paths)

    def publish(
        self,
        before: P,
        after: P,
        changed: list[Change],
        paths: dict[tuple[str, ...], Any] | None,
        replaced: Mapping[tuple[str, ...], Any] | None = None,
    ) -> None:
        """Make ``after`` current: ``before`` with ``paths`` changed (None: reshaped), and
        the live view follows every top-level attribute under ``replaced`` (default
        ``paths``); ``before`` becomes the spare. Queue the delivery to subscribers,
        made in the node's order of changes."""
        self.current = after
        live = self.live
        for path in replaced or paths or ():  # a head set twice is set to the same group
            head = path[0]
            _set_slot(live, head, getattr(after, head))
        if paths is None:
            self.spare, self.behind = None, {}
        else:
            self.spare, self.behind = before, paths
        if self.subscribers:
            self.sets.deliver(
                functools.partial(self.notify, Changes(before, after, tuple(changed)))
            )

    def notify(self, changes: Changes[P]) -> None:
        for callback in tuple(self.subscribers):
            try:
                callback(changes)
            except Exception:  # a subscriber's bug must not break the parameter service
                self.node.get_logger().error(
                    f"on_change callback {callback!r} raised:\n{traceback.format_exc()}"
                )

    def subscribe(self, callback: Callable[[Changes[P]], None]) -> Callable[[], None]:
        with self.lock:
            self.subscribers.append(callback)

        def unsubscribe() -> None:
            with self.lock:
                if callback in self.subscribers:
                    self.subscribers.remove(callback)

        return unsubscribe


_set_slot = object.__setattr__  # a module global: no attribute lookup on every set


def refusals(
    own: Mapping[str, CompiledParam], parameters: Sequence[Parameter]
) -> list[ParameterProblem]:
    """Why each value in a request of a parameter of ``own`` (by full name, old names
    included) is refused on its own: read-only, then as ``check_each`` refuses it. The
    node words rclpy's descriptor refusals with these; the tuning page likewise."""
    problems = []
    for parameter in parameters:
        param = own.get(parameter.name)
        if param is not None and param.spec.read_only:
            problems.append(ParameterProblem(parameter.name, READ_ONLY))
        elif param is not None:
            problems.extend(check_each(own, [parameter])[1])
    return problems


def check_each(
    owned: Mapping[str, CompiledParam], parameters: Sequence[Parameter]
) -> tuple[dict[CompiledParam, Any], list[ParameterProblem]]:
    """The values of ``owned`` parameters (by full ROS name) in a request, typed, and a
    problem per value refused: its type, then its own rules. Other names are skipped."""
    reasons = []
    typed: dict[CompiledParam, Any] = {}
    for parameter in parameters:
        param = owned.get(parameter.name)
        if param is None:
            continue
        value = parameter.value
        if value is None and parameter.type_ is _NOT_SET:  # only NOT_SET carries None
            reasons.append(ParameterProblem(parameter.name, "cannot be undeclared"))
            continue
        try:
            value = param.type.from_ros(value)
        except ValueError as exc:
            reasons.append(ParameterProblem(parameter.name, str(exc)))
            continue
        for check in param.checks:  # param.check inlined: a call less on every set
            reason = check(value)
            if reason is not None:
                reasons.append(ParameterProblem(parameter.name, reason))
                break
        typed[param] = value
    return typed, reasons
