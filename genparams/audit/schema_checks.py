"""Check live values against a published schema with the runtime's own validators and rules.

The schema message carries each validator in its schema spelling, so the audit
rebuilds exactly the checks the node runs (``compile_param``) and the rules it
evaluates (``compile_rule``), without the schema file. A value equals its
default as the runtime counts a change: a NaN default holding NaN is no drift.

Any node can publish a schema message, and a custom validator names a function
to import and call. The audit runs one only from a package it was told to
trust: otherwise a message naming ``os:system`` would run it on a value.
"""

from __future__ import annotations

from collections.abc import Collection, Iterator, Mapping
from typing import Any

from genparams.audit.findings import DRIFT_DEFAULT, NOT_CHECKED, VIOLATION, Finding
from genparams.runtime.core.changes import same_value
from genparams.runtime.core.entries import map_places
from genparams.runtime.core.naming import strip_prefix
from genparams.runtime.core.rules import RuleError, compile_rule
from genparams.runtime.core.schema_message import param_from_json, why_not_run
from genparams.runtime.core.spec import CompiledParam, compile_param
from genparams.runtime.core.validators import Custom


def not_runnable(check: Any, packages: Collection[str]) -> str | None:
    """Why the audit does not run a check here, if it does not."""
    if not isinstance(check, Custom):
        return None
    why = why_not_run(check, packages)
    return None if why is None else f"{check.describe()}: not run, {why}"


def described_parameters(
    described: Mapping[str, Any], values: Mapping[str, Any]
) -> Iterator[tuple[str, Mapping[str, Any]]]:
    """Every parameter a class covers, mapped entries expanded with the live keys (an open
    group's: the names declared under it), a group inside an entry once per entry."""
    for param in described["parameters"]:
        yield param["name"], param
    for place in map_places(described["maps"], values):
        yield from place.entries()


def check_class(
    node: str,
    described: Mapping[str, Any],
    values: Mapping[str, Any],
    packages: Collection[str] = (),
) -> list[Finding]:
    findings: list[Finding] = []
    typed: dict[str, Any] = {}
    for name, param_json in described_parameters(described, values):
        spec = param_from_json(param_json, name)
        compiled = compile_param(spec)
        if name not in values and (spec.optional or spec.when):
            # Not set (the services read it as "unset"), or left out by its condition.
            typed[name] = None
            continue
        if name not in values:
            findings.append(
                Finding(node, VIOLATION, name, "declared in the schema, not on the node")
            )
            continue
        findings.extend(check_value(node, compiled, values[name], typed, packages))
    findings.extend(check_rules(node, described, typed))
    return findings


def check_value(
    node: str,
    compiled: CompiledParam,
    raw: Any,
    typed: dict[str, Any],
    packages: Collection[str] = (),
) -> list[Finding]:
    name = compiled.name
    spec = compiled.spec
    try:
        value = compiled.from_ros(raw)
    except ValueError as exc:
        return [Finding(node, VIOLATION, name, f"{exc}", compiled.spec.type, raw)]
    typed[name] = value
    if value is None:  # an optional parameter not set: nothing to check
        return []
    found = []
    for check in compiled.checks:
        skipped = not_runnable(check, packages)
        if skipped is not None:
            found.append(Finding(node, NOT_CHECKED, name, skipped))
            continue
        reason = check(value)
        if reason is not None:
            found.append(Finding(node, VIOLATION, name, reason, check.describe(), raw))
    if not spec.required and not spec.optional and not same_value(value, spec.default):
        found.append(
            Finding(node, DRIFT_DEFAULT, name, "differs from the schema default", spec.default, raw)
        )
    return found


def check_rules(node: str, described: Mapping[str, Any], typed: Mapping[str, Any]) -> list[Finding]:
    prefix = described["prefix"]
    relative = {strip_prefix(prefix, name) or name: value for name, value in typed.items()}
    types = {
        strip_prefix(prefix, p["name"]) or p["name"]: p["type"] for p in described["parameters"]
    }
    found = []
    for rule_json in described["rules"]:
        try:
            rule = compile_rule(rule_json["name"], rule_json["check"], "", types)
        except RuleError as exc:
            found.append(Finding(node, NOT_CHECKED, "", f"rule {rule_json['name']!r}: {exc}"))
            continue
        if not set(rule.parameters) <= relative.keys():
            continue  # a parameter it reads is missing: reported above
        shown = lambda n: f"{prefix}.{n}" if prefix else n  # noqa: E731
        reason = rule.violation(relative, shown)
        if reason is not None:
            found.append(Finding(node, VIOLATION, "", reason, rule_json["check"]))
    return found


def check_node(
    node: str,
    schema: Mapping[str, Any],
    values: Mapping[str, Any],
    packages: Collection[str] = (),
) -> list[Finding]:
    """Findings of a node's values against its schema; custom validators of ``packages`` run."""
    findings = []
    for described in schema.get("classes", []):
        findings.extend(check_class(node, described, values, packages))
    return findings
