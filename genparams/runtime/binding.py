"""The rclpy glue: declare with full descriptors, validate every set, commit after acceptance.

Values reach the typed view only from the post-set callback, which rclpy calls
after every on-set callback accepted the change and the node stored it. A veto
anywhere leaves the view untouched.
"""

from __future__ import annotations

import collections
import functools
import threading
import traceback
from collections.abc import Callable, Iterable, Sequence
from typing import Any, Generic, TypeVar

from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime.aliases import Aliases, old_names_by_current
from genparams.runtime.changes import Change, Changes
from genparams.runtime.consistency import parameter_set_lock
from genparams.runtime.declaring import declare_batch, descriptor_for, ros_parameter
from genparams.runtime.deprecation import DeprecationWatch, Notices, report_overrides
from genparams.runtime.entries import resolve_all
from genparams.runtime.errors import ParameterDeclarationError
from genparams.runtime.mapped import MappedEntries
from genparams.runtime.naming import is_ros_token, join_prefix
from genparams.runtime.overrides import OverrideReader
from genparams.runtime.params import Params
from genparams.runtime.rewrites import add_rewrite, typed_empty_arrays
from genparams.runtime.rule_check import broken_rules
from genparams.runtime.spec import CompiledParam, compile_schema
from genparams.runtime.tree import build_tree, copy_node, get_path, replace_values

P = TypeVar("P", bound=Params)

_ACCEPTED = SetParametersResult(successful=True)


def check_prefix(prefix: str) -> str:
    if prefix and not all(is_ros_token(part) for part in prefix.split(".")):
        raise ValueError(
            f"invalid parameter prefix {prefix!r}: dot-separated names of letters, "
            "digits and underscores, each starting with a letter"
        )
    return prefix


class Binding(Generic[P]):
    """One generated class declared on one node under one prefix."""

    def __init__(self, node: Node, prefix: str, owned: dict[str, CompiledParam]) -> None:
        self.node = node
        self.prefix = prefix
        self.owned = owned  # full ROS name -> parameter
        self.lock = threading.RLock()
        self.subscribers: list[Callable[[Changes[P]], None]] = []
        self.current: P  # the frozen root: snapshots hand this out
        self.live: P  # the root users hold: top-level attributes follow `current`
        self.mapped: MappedEntries | None = None
        self.has_rules = False
        # The last request on_set accepted, with its values converted: (request, values).
        self.accepted: tuple[Sequence[Parameter], dict[CompiledParam, Any]] | None = None

    @classmethod
    def declare(cls, params_cls: type[P], node: Node, prefix: str = "") -> Binding[P]:
        with parameter_set_lock(node):  # no set may run between declaring and validating
            return cls._declare(params_cls, node, prefix)

    @classmethod
    def _declare(cls, params_cls: type[P], node: Node, prefix: str) -> Binding[P]:
        prefix = check_prefix(prefix)
        spec = params_cls._SPEC
        compiled = compile_schema(spec)
        full = functools.partial(join_prefix, prefix)

        reader = OverrideReader(
            node, full, old_names_by_current(compiled.aliases), adopted=compiled.adopted
        )
        parameters, values, problems = resolve_all(compiled, reader.read, full)
        problems = reader.with_problems(problems)
        if problems:
            raise ParameterDeclarationError(spec.name, node.get_fully_qualified_name(), problems)

        reader.release_predeclared()
        notices = Notices(node)
        aliases = Aliases(node, notices, compiled.aliases, full)
        owned = {full(name): param for name, param in parameters.items()}
        by_full_name = {full(name): value for name, value in values.items()}
        declare_batch(
            node,
            [(ros_parameter(p, n, by_full_name[n]), descriptor_for(p, n)) for n, p in owned.items()]
            + aliases.declarations(owned, by_full_name),
        )
        report_overrides(notices, parameters, reader.given, reader.renamed, full)

        binding: Binding[P] = cls(node, prefix, owned)
        binding.has_rules = bool(compiled.rules)
        binding.current = build_tree(
            params_cls, spec.groups, values, extra={"_binding": None}, maps=spec.maps
        )
        live = copy_node(binding.current)
        object.__setattr__(live, "_binding", binding)
        binding.live = live
        if any(param.type.is_array for param in owned.values()):
            old_names = {old: owned[cur] for old, cur in aliases.current_of.items()}
            add_rewrite(node, typed_empty_arrays(collections.ChainMap(binding.owned, old_names)))
        node.add_on_set_parameters_callback(binding.on_set)
        node.add_post_set_parameters_callback(binding.on_post_set)
        # Mapped groups, old names and deprecations each watch the node on their own.
        binding.mapped = MappedEntries.attach(binding, compiled, parameters, notices)
        if compiled.aliases:
            aliases.attach()
        DeprecationWatch.attach(node, notices, binding.owned, compiled)
        return binding

    def on_set(self, parameters: Sequence[Parameter]) -> SetParametersResult:
        reasons = []
        typed: dict[CompiledParam, Any] = {}
        for parameter in parameters:
            param = self.owned.get(parameter.name)
            if param is None:
                continue
            if parameter.type_ == Parameter.Type.NOT_SET:
                reasons.append(f"{parameter.name}: cannot be undeclared")
                continue
            try:
                value = param.type.from_ros(parameter.value)
            except ValueError as exc:
                reasons.append(f"{parameter.name}: {exc}")
                continue
            reason = param.check(value)
            if reason is not None:
                reasons.append(f"{parameter.name}: {reason}")
            typed[param] = value
        if not reasons and typed and self.has_rules:
            proposed = {param.name: value for param, value in typed.items()}
            reasons = broken_rules(self.current, proposed, self.full_name)
        if reasons:
            return SetParametersResult(successful=False, reason="; ".join(reasons))
        # The post-set callback of this very request commits these values as converted
        # here; holding the request keeps its identity from being reused by another.
        self.accepted = (parameters, typed)
        return _ACCEPTED

    def full_name(self, name: str) -> str:
        return join_prefix(self.prefix, name)

    def on_post_set(self, parameters: Sequence[Parameter]) -> None:
        accepted, self.accepted = self.accepted, None
        if accepted is not None and accepted[0] is parameters:
            updates = accepted[1]
        else:  # a request this binding did not check (declarations of mapped entries)
            updates = {}
            for parameter in parameters:
                param = self.owned.get(parameter.name)
                if param is not None:
                    updates[param] = param.type.from_ros(parameter.value)
        if self.mapped is not None and self.mapped.changes_keys(updates):
            self.mapped.reshape(updates)
        elif updates:
            self.commit(updates)

    def commit(self, updates: dict[CompiledParam, Any]) -> None:
        with self.lock:
            before = self.current
            # Change records are built only for subscribers: a set is on the hot path.
            subscribed = bool(self.subscribers)
            changed = []
            paths = {}
            for param, value in updates.items():
                path = param.attribute_path
                old = get_path(before, path)
                if old != value:
                    paths[path] = value
                    if subscribed:
                        changed.append(Change(param.name, old, value))
            if not paths:
                return
            after = replace_values(before, paths, extra=("_binding",))
            self.publish(before, after, changed, {path[0] for path in paths})

    def publish(self, before: P, after: P, changed: list[Change], heads: Iterable[str]) -> None:
        """Make ``after`` current (``heads``: the top-level attributes it replaced), notify."""
        with self.lock:
            self.current = after
            for head in heads:
                object.__setattr__(self.live, head, getattr(after, head))
            if not self.subscribers:
                return
        self.notify(Changes(before, after, tuple(changed)))

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
