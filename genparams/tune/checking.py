"""Check proposed values as the node would, before they are sent: the page's one checker.

A node refuses a set in two steps, and this module runs the same code for each:

1. rclpy checks each value against the parameter's descriptor (read-only, type,
   range and step): :func:`genparams.runtime.node.rclpy_internals.descriptor_check`
   runs rclpy's own check.
2. genparams' on-set callback checks each class's part: every value's type and
   validators (:func:`genparams.runtime.node.binding.check_each`), then the rules over
   the proposal merged into the node's values
   (:func:`genparams.runtime.core.rule_check.violations`). The classes come from the
   node's schema message, compiled by the runtime's own compiler.

Custom validators are functions of the node's package. The message names them,
so a node on the network could name any function of the tuning machine: they run
here only from packages the user trusts (``genparams tune --trust-package``)
that import, by the rule the audit follows
(:func:`genparams.runtime.core.schema_message.why_not_run`); any other is checked by
the node when the value is applied, and the answer says so.

What only the node knows is left to it: its other on-set callbacks, the
lifecycle state that configure-only parameters need, and the overrides of new
mapped entries.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.errors import GenparamsError, ParameterProblem, render_problem, render_problems
from genparams.runtime.core.entries import template_keys
from genparams.runtime.core.naming import join_prefix
from genparams.runtime.core.rule_check import violations
from genparams.runtime.core.schema_message import class_spec, why_not_run
from genparams.runtime.core.spec import CompiledParam, CompiledSchema, compile_uncached
from genparams.runtime.core.types import TYPES
from genparams.runtime.core.validators import Custom, Validator
from genparams.runtime.node.binding import check_each, refusals
from genparams.runtime.node.rclpy_internals import descriptor_check, undeclared_check


class SchemaMessageError(GenparamsError, ValueError):
    """A schema message this checker cannot compile."""


def json_parameter(name: str, type_name: str, value: Any) -> Parameter:
    """A JSON value as an rclpy Parameter of ``type_name``, typed by the runtime's rules.

    Wrong JSON types are refused (ValueError naming the parameter), never converted:
    ``true`` is not an int, ``"2.5"`` not a double, ``2.5`` not an int.
    """
    param_type = TYPES.get(type_name) if isinstance(type_name, str) else None
    if param_type is None:
        raise ValueError(f"{name}: unknown parameter type {type_name!r}")
    try:
        typed = param_type.from_json(value)
    except ValueError as exc:
        raise ValueError(f"{name}: {exc}") from None
    return Parameter(name, Parameter.Type(param_type.ros_type), param_type.to_ros(typed))


# Custom validators --------------------------------------------------------------


@dataclass(frozen=True)
class CheckedByNode:
    """A custom validator not run here: the node checks it when the value is applied."""

    custom: Custom
    why: str
    rule: str = "custom"

    def __call__(self, value: Any) -> str | None:
        return None

    def describe(self) -> str:
        return f"{self.custom.describe()} (checked by the node on apply: {self.why})"


def runnable(check: Validator, trusted: Sequence[str]) -> Validator:
    """``check``, or a stand-in saying why the node alone runs it."""
    if not isinstance(check, Custom):
        return check
    why = why_not_run(check, trusted)
    return check if why is None else CheckedByNode(check, why)


def not_run_here(param: CompiledParam) -> list[str]:
    return [check.describe() for check in param.checks if isinstance(check, CheckedByNode)]


# A node's schema message, compiled -------------------------------------------------


@dataclass(frozen=True)
class ClassChecks:
    """One class of a schema message, compiled."""

    prefix: str
    compiled: CompiledSchema

    def relative(self, full_name: str) -> str:
        return full_name[len(self.prefix) + 1 :] if self.prefix else full_name

    def full(self, name: str) -> str:
        return join_prefix(self.prefix, name)

    def param(self, full_name: str, old_names: bool = False) -> CompiledParam | None:
        """The parameter ``full_name`` names (with ``old_names``, also by an old name)."""
        if self.prefix and not full_name.startswith(self.prefix + "."):
            return None
        name = self.relative(full_name)
        if old_names:
            name = self.compiled.aliases.get(name, name)
        found = self.compiled.parameters.get(name)
        if found is not None:
            return found
        for template_name, template in self.compiled.templates.items():
            keys = template_keys(template_name, name)  # a mapped entry: no key is empty
            if keys is not None and all(keys):
                return template
        return None


def compile_class(body: Mapping[str, Any], trusted: Sequence[str]) -> ClassChecks:
    compiled = compile_uncached(class_spec(body))

    def runnable_here(param: CompiledParam) -> CompiledParam:
        checks = tuple(runnable(check, trusted) for check in param.checks)
        return param if checks == param.checks else param.with_checks(checks)

    compiled = compiled.replaced(
        parameters={n: runnable_here(p) for n, p in compiled.parameters.items()},
        templates={n: runnable_here(p) for n, p in compiled.templates.items()},
    )
    return ClassChecks(str(body["prefix"]), compiled)


def compile_message(message: Mapping[str, Any], trusted: Sequence[str]) -> tuple[ClassChecks, ...]:
    """Every class of a node's schema message; SchemaMessageError if it is not one."""
    try:
        return tuple(compile_class(body, trusted) for body in message["classes"])
    except Exception as exc:  # a message is data from the network: any shape may come
        raise SchemaMessageError(f"{type(exc).__name__}: {exc}") from None


# The node's verdict ----------------------------------------------------------------


@dataclass
class Verdict:
    """What the node would answer for one proposed value."""

    name: str
    reasons: list[str]
    not_checked: list[str]

    def as_json(self) -> dict[str, Any]:
        return {
            "name": self.name,
            "successful": not self.reasons,
            "reason": "; ".join(self.reasons) or None,
            "not_checked": self.not_checked,
        }


def descriptor_of(read: Mapping[str, Any]) -> ParameterDescriptor:
    """The descriptor a node reported (``reader.parameters_of``), for rclpy's check."""
    param_type = TYPES.get(read["type"])
    descriptor = ParameterDescriptor(
        name=read["name"],
        type=0 if param_type is None else param_type.ros_type,
        read_only=bool(read.get("read_only", False)),
        dynamic_typing=param_type is None,
    )
    found = read.get("range")
    if found is not None and read["type"] == "int":
        descriptor.integer_range = [
            IntegerRange(from_value=found["min"], to_value=found["max"], step=found["step"])
        ]
    elif found is not None and read["type"] == "double":
        descriptor.floating_point_range = [
            FloatingPointRange(from_value=found["min"], to_value=found["max"], step=found["step"])
        ]
    return descriptor


class ProposalCheck:
    """One proposed set (atomic) against one node's state: the reason the node would give."""

    def __init__(
        self,
        node: Node,
        classes: Sequence[ClassChecks],
        current: Sequence[Mapping[str, Any]],
        declared: Collection[str],
    ) -> None:
        self.node = node
        self.classes = classes
        self.current = {p["name"]: p for p in current}
        self.declared = declared

    def run(self, proposed: Sequence[Parameter]) -> tuple[str | None, list[Verdict]]:
        verdicts = {p.name: Verdict(p.name, [], []) for p in proposed}
        reason = undeclared_check(proposed, self.declared)
        if reason is not None:
            for parameter in proposed:
                if parameter.name not in self.declared:
                    verdicts[parameter.name].reasons.append(reason)
            return reason, list(verdicts.values())
        # rclpy's descriptor check: the first value it refuses refuses the set.
        first: tuple[str, str] | None = None
        for parameter in proposed:
            result = descriptor_check(
                self.node, parameter, descriptor_of(self.current[parameter.name])
            )
            if not result.successful:
                verdicts[parameter.name].reasons.append(result.reason)
                first = first or (parameter.name, result.reason)
        if first is not None:
            return self.descriptor_refusal(*first, proposed, verdicts), list(verdicts.values())
        reasons: list[ParameterProblem] = []
        for checks in self.classes:
            reasons.extend(self.class_reasons(checks, proposed, verdicts))
        return render_problems(reasons) or None, list(verdicts.values())

    def descriptor_refusal(
        self, name: str, reason: str, proposed: Sequence[Parameter], verdicts: dict[str, Verdict]
    ) -> str:
        """The node words rclpy's refusal of a value a class owns as the classes do
        (``consistency.NodeSets.in_own_words``); other refusals keep rclpy's words."""
        owned = [
            {p.name: param for p in proposed if (param := checks.param(p.name, True)) is not None}
            for checks in self.classes
        ]
        if not any(name in own for own in owned):
            return reason
        problems = [problem for own in owned for problem in refusals(own, proposed)]
        if not problems:
            return reason
        for verdict in verdicts.values():
            verdict.reasons.clear()
        for problem in problems:
            verdicts[problem.key].reasons.append(render_problem(problem))
        return render_problems(problems)

    def class_reasons(
        self, checks: ClassChecks, proposed: Sequence[Parameter], verdicts: dict[str, Verdict]
    ) -> list[ParameterProblem]:
        """What the node's genparams check says of this class's part of the proposal."""
        owned = {p.name: param for p in proposed if (param := checks.param(p.name)) is not None}
        if not owned:
            return []
        for name, param in owned.items():
            verdicts[name].not_checked.extend(not_run_here(param))
        typed, reasons = check_each(owned, proposed)
        if reasons:
            for parameter in proposed:  # each reason names its parameter first
                alone = check_each(owned, [parameter])[1]
                verdicts[parameter.name].reasons.extend(map(render_problem, alone))
        # The node evaluates the rules only when every value passed its own checks; they
        # are shown anyway on the values that did, so a rule shows before the last fix.
        passing = {
            checks.relative(name): typed[param]
            for name, param in owned.items()
            if param in typed and not verdicts[name].reasons
        }
        broken = self.broken_rules(checks, passing, verdicts)
        return reasons or broken

    def broken_rules(
        self, checks: ClassChecks, proposed: dict[str, Any], verdicts: dict[str, Verdict]
    ) -> list[ParameterProblem]:
        """A problem per rule the proposal (relative names, typed) breaks over the node's values;
        each goes to every proposed parameter the rule reads."""
        rules = checks.compiled.rules_reading(proposed)
        values = dict(proposed)
        for rule in rules:
            for name in rule.parameters:
                if name not in values:
                    values[name] = self.current_value(checks, name)
        broken = []
        for rule in rules:
            reason = violations([rule], values, checks.full)
            broken.extend(reason)
            for name in rule.parameters:
                if reason and checks.full(name) in verdicts:
                    verdicts[checks.full(name)].reasons.extend(map(render_problem, reason))
        return broken

    def current_value(self, checks: ClassChecks, name: str) -> Any:
        read = self.current.get(checks.full(name))
        param = checks.compiled.parameters.get(name)
        if read is None or param is None:
            raise SchemaMessageError(f"the node holds no parameter {checks.full(name)!r}")
        return param.type.from_ros(read["value"])


MAX_COMPILED = 64
"""Nodes whose compiled messages are kept: nodes come and go, the server stays flat."""


class Checker:
    """The tuning server's checks: each node's schema message compiled once, on demand."""

    def __init__(self, node: Node, trusted_packages: Sequence[str] = ()) -> None:
        self.node = node
        self.trusted = tuple(trusted_packages)
        # node name -> (the message compiled, its classes or why it could not be); the
        # least recently compiled go first past MAX_COMPILED nodes.
        self.compiled: dict[str, tuple[object, tuple[ClassChecks, ...] | str]] = {}

    def classes(
        self, node_name: str, message: Mapping[str, Any] | None
    ) -> tuple[tuple[ClassChecks, ...], str | None]:
        if message is None:
            return (), None
        cached = self.compiled.get(node_name)
        if cached is None or cached[0] is not message:
            try:
                found: tuple[ClassChecks, ...] | str = compile_message(message, self.trusted)
            except SchemaMessageError as exc:
                found = f"its schema message cannot be checked here: {exc}"
            self.compiled.pop(node_name, None)
            while len(self.compiled) >= MAX_COMPILED:
                del self.compiled[next(iter(self.compiled))]
            cached = self.compiled[node_name] = (message, found)
        found = cached[1]
        return ((), found) if isinstance(found, str) else (found, None)

    def wanted(
        self,
        node_name: str,
        message: Mapping[str, Any] | None,
        edits: Sequence[tuple[str, Any, Any]],
    ) -> list[str]:
        """The parameters a check of ``edits`` reads: the edited ones and those rules read."""
        names = [str(name) for name, _, _ in edits]
        for checks in self.classes(node_name, message)[0]:
            names.extend(checks.full(n) for rule in checks.compiled.rules for n in rule.parameters)
        return names

    def check(
        self,
        node_name: str,
        message: Mapping[str, Any] | None,
        current: Sequence[Mapping[str, Any]],
        edits: Sequence[tuple[str, Any, Any]],
        declared: Collection[str] | None = None,
    ) -> dict[str, Any]:
        """The node's answer to setting ``edits`` (name, type, JSON value) atomically.

        ``current``: what the node holds of the parameters :meth:`wanted` names (or all);
        ``declared``: every name the node declares (by default, those of ``current``).
        """
        if declared is None:
            declared = {p["name"] for p in current}
        classes, problem = self.classes(node_name, message)
        typed: list[Parameter] = []
        refused: dict[str, Verdict] = {}
        for name, type_name, value in edits:
            try:
                typed.append(json_parameter(str(name), type_name, value))
            except ValueError as exc:
                refused[str(name)] = Verdict(str(name), [str(exc)], [])
        try:
            reason, verdicts = ProposalCheck(self.node, classes, current, declared).run(typed)
        except SchemaMessageError as exc:  # a rule reads a parameter the node does not hold
            problem = f"its schema message cannot be checked here: {exc}"
            reason, verdicts = ProposalCheck(self.node, (), current, declared).run(typed)
        if refused:
            reason = "; ".join(v.reasons[0] for v in refused.values())
        by_name = {v.name: v for v in (*verdicts, *refused.values())}
        return {
            "node": node_name,
            "successful": reason is None,
            "reason": reason,
            "results": [by_name[str(name)].as_json() for name, _, _ in edits],
            "schema": bool(classes),
            "schema_problem": problem,
        }
