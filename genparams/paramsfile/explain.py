"""A node's effective configuration: every parameter's value and where it came from.

The inputs are what rcl gets: params files and ``-p`` rules, in command-line
order. Sections reach the node in rcl's order (node_sections); each value
shadows what an earlier section, file or the schema default gave. What ROS
would silently ignore is listed beside: unknown keys, values of the wrong
type, and sections meant for this node that miss it by a typo.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import yaml

from genparams.errors import GenparamsError
from genparams.paramsfile.check_params import (
    BUILTIN_PARAMETERS,
    BUILTIN_PREFIXES,
    Bound,
    Report,
    check_files,
    is_known,
    own_sections,
)
from genparams.paramsfile.node_sections import Skipped, sections_for
from genparams.paramsfile.params_reader import ParamEntry, ParamsDocument, Section
from genparams.paramsfile.ros_yaml import NoValue, absolute, ros_scalar
from genparams.paramsfile.section_checker import SectionChecker
from genparams.runtime.core.naming import COMMAND_LINE_NAME, NODE_TOKEN, join_prefix
from genparams.runtime.core.spec import CompiledParam
from genparams.runtime.core.types import ValueTypeError
from genparams.schema.errors import Location, SchemaError
from genparams.schema.nesting import check_nesting

OVERRIDE_FILE = "-p"  # the file name of -p rules' locations: line = the rule's place among them


@dataclass(frozen=True)
class Source:
    """Where a value came from: the schema default, a params-file section, or a -p rule."""

    text: str  # "default", "robot.yaml:12:7 (/robot/camera)", "-p fps:=5.0"
    value: Any


@dataclass
class Row:
    name: str
    value: Any  # typed as the node holds it; None when not set
    type_name: str  # the schema's type, "" when no schema owns the parameter
    source: Source | None  # None: required and not set
    shadowed: list[Source] = field(default_factory=list)
    owner: str = "schema"  # or "rclpy", "known" (other code), "nobody" (ignored), "unchecked"
    optional: bool = False  # declared by type only: no value unless an override gives one


@dataclass(frozen=True)
class Explanation:
    node: str
    rows: tuple[Row, ...]
    report: Report  # problems: what ROS ignores or refuses
    near_misses: tuple[Skipped, ...]
    sections: int


def overrides_document(rules: Sequence[str], start: int = 1) -> ParamsDocument:
    """``-p`` rules as rcl reads them: ``name:=value`` for every node, ``node:name:=value``.

    Raises RuleError for a rule rcl refuses. ``start`` numbers the first rule.
    """
    slots: dict[str, list[ParamEntry]] = {}
    for index, rule in enumerate(rules, start=start):
        target, value_text = _split_rule(rule)
        node, _, name = target.rpartition(":")
        where = Location(OVERRIDE_FILE, index, 1)
        value = _rule_value(value_text, rule)
        slots.setdefault(absolute(node) if node else "/**", []).append(
            ParamEntry(name, value, where, where, written_empty=value is None)
        )
    sections = tuple(
        Section(
            node, Location(OVERRIDE_FILE, e[0].key_location.line, 1), e[0].key_location, tuple(e)
        )
        for node, e in slots.items()
    )
    return ParamsDocument(OVERRIDE_FILE, sections, ())


class RuleError(GenparamsError, ValueError):
    """A -p rule rcl would refuse."""


def _split_rule(rule: str) -> tuple[str, str]:
    target, sep, value = rule.partition(":=")
    node = target.rpartition(":")[0]
    if not sep or not target.rpartition(":")[2]:
        raise RuleError(f"-p {rule!r}: expected NAME:=VALUE or NODE:NAME:=VALUE")
    if node and NODE_TOKEN.fullmatch(node) is None:
        # rcl takes one plain node name here: no namespace, no wildcard.
        raise RuleError(f"-p {rule!r}: the node is one name, without namespace or wildcard")
    if COMMAND_LINE_NAME.fullmatch(target.rpartition(":")[2]) is None:
        raise RuleError(
            f"-p {rule!r}: rcl reads a name of letters, digits and '_' between '.' and '/' "
            "here (no digit first); give other names in a params file"
        )
    return target, value


def _rule_value(text: str, rule: str) -> Any:
    """rcl reads a -p value with its params-file rules: a scalar, or a flat list."""
    try:
        check_nesting(text, "-p")  # before composing, which recurses
        node = yaml.compose(text, Loader=yaml.SafeLoader)
    except SchemaError as exc:
        raise RuleError(f"-p {rule!r}: {exc.problems[0].message}") from exc
    except yaml.YAMLError as exc:
        raise RuleError(f"-p {rule!r}: not a YAML value ({exc.__class__.__name__})") from exc
    if isinstance(node, yaml.ScalarNode):
        value = ros_scalar(node.value, node.style)
        if isinstance(value, NoValue):
            raise RuleError(f"-p {rule!r}: no value")
        return value
    if isinstance(node, yaml.SequenceNode) and all(
        isinstance(item, yaml.ScalarNode) for item in node.value
    ):
        items = [ros_scalar(item.value, item.style) for item in node.value]
        return items or None
    raise RuleError(f"-p {rule!r}: a value is a scalar or a flat list")


def explain(
    bounds: Sequence[Bound],
    documents: Sequence[ParamsDocument],
    node: str,
    known: Sequence[str] = (),
) -> Explanation:
    """The configuration ``node`` starts with, given these files and -p rules in order."""
    files = [d.sections for d in documents]
    applied, skipped = sections_for(files, node)
    owned = _owned(bounds, applied)
    rows: dict[str, Row] = {}
    for name, (param, current) in owned.items():
        if name != current:
            continue  # an old name
        if param.spec.required:
            rows[name] = Row(name, None, param.type.name, None)
        elif param.spec.optional:
            rows[name] = Row(name, None, param.type.name, None, optional=True)
        else:
            value = param.type.coerce_default(param.spec.default)
            rows[name] = Row(name, value, param.type.name, Source("default", value))
    for section in applied:
        for entry in section.entries:
            _apply(rows, owned, section, entry)
    for row in rows.values():
        if row.name not in owned or row.type_name == "":
            row.owner = _owner(row.name, known) if bounds else "unchecked"
    if not bounds:
        known = ["*"]  # no schema: nothing to call unknown, only what rcl refuses
    report = check_files(bounds, documents, [node], known, near_misses=False, sections_needed=False)
    return Explanation(
        node,
        tuple(rows.values()),
        report,
        tuple(s for s in skipped if s.near_miss),
        len(applied),
    )


def _owned(
    bounds: Sequence[Bound], applied: Sequence[Section]
) -> dict[str, tuple[CompiledParam, str]]:
    """Full name -> (parameter, its current full name), for every parameter and old name.

    Mapped entries are expanded from the items the sections give.
    """
    owned: dict[str, tuple[CompiledParam, str]] = {}
    for bound in bounds:
        checker = SectionChecker(bound.schema, "")
        checker.run(own_sections(applied, bound.prefix), [])
        for name, param in checker.params.items():
            full = join_prefix(bound.prefix, name)
            owned[full] = (param, full)
        # An old name (a renamed parameter) gives the current one its value.
        for old, current in checker.compiled.aliases.items():
            owned[join_prefix(bound.prefix, old)] = owned[join_prefix(bound.prefix, current)]
    return owned


def _owner(name: str, known: Sequence[str]) -> str:
    if name in BUILTIN_PARAMETERS or name.startswith(BUILTIN_PREFIXES):
        return "rclpy"
    return "known" if is_known(name, known) else "nobody"


def _apply(
    rows: dict[str, Row],
    owned: dict[str, tuple[CompiledParam, str]],
    section: Section,
    entry: ParamEntry,
) -> None:
    where = entry.key_location
    if where.file == OVERRIDE_FILE:
        text = f"-p (rule {where.line}, for {section.node})"
    else:
        text = f"{where.file}:{where.line}:{where.column} ({section.node})"
    value = entry.value
    name = entry.name
    if name in owned:
        param, name = owned[name]  # the current name of a renamed parameter
        try:
            value = param.type.from_ros(entry.value)
        except ValueTypeError:
            return  # the node refuses it: listed with the problems, the earlier value stays
    row = rows.get(name)
    if row is None:
        row = rows[name] = Row(name, value, "", None)
    elif row.source is not None:
        row.shadowed.append(row.source)
    row.value, row.source = value, Source(text, value)
