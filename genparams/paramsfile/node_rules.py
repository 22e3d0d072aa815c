"""Rules across nodes of a deployment: one value equal on several nodes, or a check over
values of different nodes (``/base.wheel_base == /odometry.wheel_base``).

A manifest holds them under ``rules:``. ``check`` is the schema rules' own expression
language (genparams.runtime.core.rules), with every parameter written after its node:
``/ns/node.dotted.name``. The node part is turned into a name the language reads (each
``/`` into a letter no ROS name holds, so every offset of an error stays right), and the
expression is typed from the values it meets: a node's schema types them, or the params
file, or the running node. ``same`` names a parameter that must hold one value on every
node the rule's ``nodes`` patterns match (every node by default).

The same rules run offline (check-deployment: each node's effective values, as explain
traces them) and on a running graph (audit: each node's values, read over its services).
"""

from __future__ import annotations

import ast
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from genparams.paramsfile.ros_yaml import absolute, node_matches, node_pattern_problem
from genparams.runtime.core.changes import same_value
from genparams.runtime.core.naming import NODE_TOKEN, attribute_parts, is_ros_name
from genparams.runtime.core.rules import RuleError, compile_rule
from genparams.schema.errors import Location, SchemaProblem

ALL_NODES = "/**"
# Stands for "/" in a node name inside an expression: a letter Python names may hold
# (so `/a/b.x` reads as the dotted name `ǀaǀb.x`) that no ROS name can.
SLASH = "\u01c0"
# `/ns/node.param.path`: a `/` that does not follow a value (so not a division), node
# tokens, then a dotted parameter name. Division is written with spaces: `/a.x / 2`.
REFERENCE = re.compile(
    r"(?<![\w.)\]])(/(?:[A-Za-z_][A-Za-z0-9_]*/)*[A-Za-z_][A-Za-z0-9_]*)"
    r"\.([A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*)"
)
WILDCARD_REFERENCE = re.compile(r"(?<![\w.)\]])/[\w/]*\*")
RULE_KEYS = ("name", "check", "same", "nodes", "description")


@dataclass(frozen=True)
class NodeRule:
    """One rule of a manifest: exactly one of ``check`` and ``same`` is set."""

    name: str
    location: Location  # of its check (or same) value: where its problems point
    check: str = ""
    same: str = ""
    nodes: tuple[str, ...] = (ALL_NODES,)  # the nodes a `same` rule covers
    description: str = ""


@dataclass(frozen=True)
class NodeValue:
    value: Any
    place: str  # where it came from: "bringup.yaml:3:5 (/**)", "default"; "" on a live node


# node -> parameter -> its value there
NodeValues = Mapping[str, Mapping[str, NodeValue]]


def references(check: str) -> list[tuple[str, str]]:
    """Every ``(node, parameter)`` a check reads, in order."""
    return [(m[1], m[2]) for m in REFERENCE.finditer(check)]


def spelled(node: str, parameter: str) -> str:
    """The name a reference takes in the expression language."""
    return f"{node.replace('/', SLASH)}.{parameter}"


def shown(name: str) -> str:
    return name.replace(SLASH, "/")


def _translated(check: str) -> str:
    return REFERENCE.sub(lambda m: spelled(m[1], m[2]), check)


def read_rules(
    value: Any, where: Callable[[tuple[object, ...], bool], Location]
) -> tuple[tuple[NodeRule, ...], list[SchemaProblem]]:
    """The ``rules:`` list of a manifest; ``where(path, key)`` places a value (or its key)."""
    problems: list[SchemaProblem] = []

    def problem(path: tuple[object, ...], message: str, *, key: bool = False) -> None:
        problems.append(SchemaProblem(where(path, key), ".".join(map(str, path)), message))

    if not isinstance(value, list):
        problem(("rules",), "a list of rules: {name: N, check: EXPR} or {name: N, same: PARAM}")
        return (), problems
    rules: list[NodeRule] = []
    seen: set[str] = set()
    for index, entry in enumerate(value):
        path: tuple[object, ...] = ("rules", index)
        if not isinstance(entry, dict) or not isinstance(entry.get("name"), str):
            problem(path, "a rule is a mapping with a name: and a check: or same:")
            continue
        for key in entry:
            if key not in RULE_KEYS:
                problem(
                    (*path, key), f"unknown key {key!r} (known: {', '.join(RULE_KEYS)})", key=True
                )
        name = entry["name"]
        if name in seen:
            problem((*path, "name"), f"rule name {name!r} is already used")
        seen.add(name)
        kinds = [k for k in ("check", "same") if k in entry]
        if len(kinds) != 1 or not isinstance(entry[kinds[0]], str):
            problem(path, "give exactly one of check: EXPRESSION and same: PARAMETER")
            continue
        kind = kinds[0]
        text = entry[kind]
        description = entry.get("description", "")
        nodes = entry.get("nodes", [ALL_NODES])
        if not isinstance(description, str):
            problem((*path, "description"), "a description is a string")
            description = ""
        if not isinstance(nodes, list) or not all(isinstance(n, str) for n in nodes) or not nodes:
            problem((*path, "nodes"), "a list of node names or patterns (/**/controller)")
            nodes = [ALL_NODES]
        for number, node in enumerate(nodes):
            bad = node_pattern_problem(node)
            if bad is not None:
                problem((*path, "nodes", number), f"invalid node name: {bad}")
        message = _check_problem(text) if kind == "check" else _same_problem(text)
        if message is not None:
            problem((*path, kind), message)
            continue
        rules.append(
            NodeRule(
                name,
                where((*path, kind), False),
                check=text if kind == "check" else "",
                same=text if kind == "same" else "",
                nodes=tuple(absolute(n) for n in nodes),
                description=description,
            )
        )
    return tuple(rules), problems


def _check_problem(check: str) -> str | None:
    """What is wrong with a check before any value is known: its syntax, its references."""
    if WILDCARD_REFERENCE.search(check):
        return "a rule reads nodes named in full: no wildcards (write each node)"
    found = references(check)
    if not found:
        return "a check reads parameters of nodes, written /ns/node.parameter"
    for node, _ in found:
        bad = node_pattern_problem(node)
        if bad is not None:
            return f"{node}: invalid node name: {bad}"
    try:
        ast.parse(_translated(check).strip(), mode="eval")
    except SyntaxError as exc:
        return f"invalid expression: {exc.msg}"
    return None


def _same_problem(parameter: str) -> str | None:
    # Any node's parameters: a schema's names, or rcl's tokens (`_private` too).
    if is_ros_name(parameter) or all(NODE_TOKEN.fullmatch(t) for t in parameter.split(".")):
        return None
    return f"same: takes one parameter name, such as use_sim_time, not {parameter!r}"


@dataclass(frozen=True)
class RuleResults:
    problems: tuple[SchemaProblem, ...]  # a rule the values break, or cannot be read for
    notes: tuple[SchemaProblem, ...]  # a rule left unchecked: a node it reads is not here


def check_rules(rules: Sequence[NodeRule], values: NodeValues) -> RuleResults:
    """Every rule over the nodes of ``values``."""
    problems: list[SchemaProblem] = []
    notes: list[SchemaProblem] = []
    for rule in rules:
        if rule.same:
            problem, note = _check_same(rule, values)
        else:
            problem, note = _check_expression(rule, values)
        if problem is not None:
            problems.append(SchemaProblem(rule.location, rule.name, problem))
        if note is not None:
            notes.append(SchemaProblem(rule.location, rule.name, note))
    return RuleResults(tuple(problems), tuple(notes))


def _check_same(rule: NodeRule, values: NodeValues) -> tuple[str | None, str | None]:
    covered = sorted(n for n in values if any(node_matches(p, n) for p in rule.nodes))
    holding = {n: values[n][rule.same] for n in covered if rule.same in values[n]}
    if len(holding) < 2:
        return None, f"not checked: fewer than two nodes hold {rule.same}"
    groups: list[tuple[Any, list[str]]] = []
    for node, held in holding.items():
        for value, nodes in groups:
            if equal_values(value, held.value):
                nodes.append(node)
                break
        else:
            groups.append((held.value, [node]))
    if len(groups) == 1:
        return None, None
    parts = "; ".join(
        f"{_text(value)} on " + ", ".join(_at(n, holding[n]) for n in nodes)
        for value, nodes in groups
    )
    return f"broken: {rule.same} differs across nodes: {parts}", None


def _check_expression(rule: NodeRule, values: NodeValues) -> tuple[str | None, str | None]:
    found = references(rule.check)
    absent = sorted({node for node, _ in found if node not in values})
    if absent:
        return None, f"not checked: {', '.join(absent)} not in this deployment"
    held = {(n, p): held_name(values[n], p) for n, p in found}
    unset = [f"{n}.{p}" for (n, p), name in held.items() if name is None]
    if unset:
        return f"cannot be checked: {', '.join(unset)} not set", None
    read = {spelled(n, p): values[n][name] for (n, p), name in held.items() if name is not None}
    types = {name: type_name(held.value) for name, held in read.items()}
    try:
        compiled = compile_rule(rule.name, _translated(rule.check), rule.description, types)
    except RuleError as exc:
        return shown(str(exc)), None
    failure = compiled.failure({name: held.value for name, held in read.items()}, shown)
    if failure is None:
        return None, None
    places = ", ".join(_at(shown(name), held) for name, held in read.items() if held.place)
    return f"broken: {shown(failure)}" + (f" ({places})" if places else ""), None


def held_name(node_values: Mapping[str, NodeValue], parameter: str) -> str | None:
    """The name a node holds that a check's ``parameter`` reads: the name itself, else the
    one name whose attribute spelling it is (``axes.twist_linear_x`` reads
    ``axes.twist-linear-x``, ``input_shape_height`` reads ``input_shape/height``), as a
    schema's rules read names; None when the node holds neither, or several such names."""
    if parameter in node_values:
        return parameter
    spelled_so = [n for n in node_values if ".".join(attribute_parts(n)) == parameter]
    return spelled_so[0] if len(spelled_so) == 1 else None


def _at(name: str, held: NodeValue) -> str:
    return f"{name} from {held.place}" if held.place else name


def equal_values(one: Any, other: Any) -> bool:
    """Equal as ROS holds them: of one type (a ``true`` is not a ``1``), then the runtime's
    equality (NaN equals NaN)."""
    if type_name(one) != type_name(other):
        return False
    if isinstance(one, list | tuple):
        return len(one) == len(other) and all(map(equal_values, one, other))
    return bool(same_value(one, other))


def _text(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value)


def type_name(value: Any) -> str:
    """The schema type of a value as ROS holds it (a list's from its first item)."""
    if isinstance(value, bytes):
        return "byte_array"
    if isinstance(value, list | tuple):
        item = type_name(value[0]) if value else "double"
        return f"{item}_array" if item in ("bool", "int", "double", "string") else "string_array"
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int"
    if isinstance(value, float):
        return "double"
    return "string"
