"""Check params files for one node (or several), against one or more schemas.

A node gets the sections rcl applies to it (node_sections), in rcl's order;
sections for other nodes are skipped, never errors. Each schema declared on
the node (with its prefix) checks the entries under that prefix
(section_checker). An entry is unknown, so silently ignored by ROS, only when
no schema owns it, rclpy does not declare it on every node, and it is not
declared known (a framework's parameters, such as ros2_control's ``type``).
"""

from __future__ import annotations

import dataclasses
import fnmatch
from collections.abc import Sequence
from dataclasses import dataclass

from genparams.paramsfile.node_sections import rcl_order, sections_for
from genparams.paramsfile.params_reader import ParamEntry, ParamsDocument, Section
from genparams.paramsfile.ros_yaml import ros_type_name
from genparams.paramsfile.section_checker import SectionChecker
from genparams.runtime.core.naming import join_prefix
from genparams.runtime.core.suggest import closest_name, did_you_mean_name
from genparams.schema.errors import Location, SchemaProblem
from genparams.schema.model import Schema

# Parameters rclpy declares on every node, by type; and a namespace it owns.
BUILTIN_PARAMETERS = {"use_sim_time": "bool", "start_type_description_service": "bool"}
BUILTIN_PREFIXES = ("qos_overrides.",)
ALL_NODES = "/**"  # the section every node takes


@dataclass(frozen=True)
class Bound:
    """One schema's class declared on the node, under ``prefix`` ("" for the root)."""

    schema: Schema
    prefix: str = ""


@dataclass(frozen=True)
class Report:
    problems: tuple[SchemaProblem, ...]  # what makes the file wrong: exit 1
    warnings: tuple[SchemaProblem, ...]  # worth knowing, not wrong (deprecation, unchecked rules)
    skipped: tuple[SchemaProblem, ...] = ()  # sections for other nodes, with the reason


def check_params(
    schema: Schema,
    document: ParamsDocument,
    nodes: Sequence[str] = (),
    *,
    also: Sequence[Bound] = (),
    known: Sequence[str] = (),
) -> Report:
    """Check the sections of ``document`` that reach one of ``nodes``.

    Without ``nodes``, every section is taken to be for this schema's node.
    """
    return check_files([Bound(schema), *also], [document], nodes, known)


def check_files(
    bounds: Sequence[Bound],
    documents: Sequence[ParamsDocument],
    nodes: Sequence[str] = (),
    known: Sequence[str] = (),
    *,
    near_misses: bool = True,
    sections_needed: bool = True,
) -> Report:
    """Check params files given in this order (as rcl gets them) for ``nodes``.

    A skipped section that looks meant for one of ``nodes`` (a typo in its name
    or namespace) is a warning, unless ``near_misses`` is False (the caller
    reports unclaimed sections itself). A node that no section reaches is a
    problem, unless ``sections_needed`` is False: a check of nothing would pass.
    """
    problems: list[SchemaProblem] = [p for d in documents for p in d.problems]
    files = [d.sections for d in documents]
    applied, per_node, skipped, warnings = _node_sections(files, nodes)
    if not near_misses:
        warnings = []
    if sections_needed and nodes and not any(d.problems and not d.sections for d in documents):
        unnamed = _unnamed(documents, per_node)
        problems.extend(_unreached(documents, unnamed))
    if any(d.problems and not d.sections for d in documents):
        per_node = []  # nothing could be read: a list of every required parameter adds only noise
    file = documents[0].file if documents else "-"
    checkers = []
    for bound in bounds:
        checker = SectionChecker(bound.schema, file)
        checker.run(
            own_sections(applied, bound.prefix),
            [(n, own_sections(s, bound.prefix)) for n, s in per_node],
        )
        problems.extend(_prefixed(p, bound.prefix) for p in checker.problems)
        warnings.extend(_prefixed(p, bound.prefix) for p in checker.warnings)
        checkers.append((bound.prefix, checker))
    owned = [join_prefix(prefix, name) for prefix, checker in checkers for name in checker.names()]
    unclaimed = [(prefix, _unknown_keys(checker)) for prefix, checker in checkers]
    for entry in (e for section in applied for e in section.entries):
        if not any(_claims(prefix, unknown, entry) for prefix, unknown in unclaimed):
            problem = _unowned(entry, owned, known)
            if problem is not None:
                problems.append(problem)
    return Report(tuple(sorted(set(problems))), tuple(sorted(set(warnings))), tuple(skipped))


def _node_sections(
    files: Sequence[Sequence[Section]], nodes: Sequence[str]
) -> tuple[
    list[Section], list[tuple[str, list[Section]]], list[SchemaProblem], list[SchemaProblem]
]:
    """Sections that reach any of ``nodes``; each node's own; the skipped ones; near misses."""
    if not nodes:
        every = rcl_order(files)
        return every, [("", every)], [], []
    per_node = []
    reasons: dict[int, tuple[str, str]] = {}  # section -> (node it near-misses or "", reason)
    for node in nodes:
        applied, skipped = sections_for(files, node)
        per_node.append((node, applied))
        for skip in skipped:
            if skip.near_miss or id(skip.section) not in reasons:
                reasons[id(skip.section)] = (node if skip.near_miss else "", skip.reason)
    reached = {id(s) for _, applied in per_node for s in applied}
    ordered = rcl_order(files)
    union = [s for s in ordered if id(s) in reached]
    skipped_lines, near = [], []
    for section in (s for s in ordered if id(s) not in reached):
        node, reason = reasons[id(section)]
        if node:
            message = f"warning: ROS applies this section to another node, not {node}: {reason}"
            near.append(SchemaProblem(section.node_location, section.node, message))
        else:
            skipped_lines.append(
                SchemaProblem(section.node_location, section.node, f"skipped: {reason}")
            )
    return union, per_node, skipped_lines, near


def _unnamed(
    documents: Sequence[ParamsDocument], per_node: Sequence[tuple[str, Sequence[Section]]]
) -> list[str]:
    """The nodes no section names, in files that name nodes: only ``/**`` (or nothing)
    reaches them, so the sections meant for them, if any, went elsewhere."""
    if all(s.node == ALL_NODES for d in documents for s in d.sections):
        return [node for node, applied in per_node if not applied]
    return [node for node, applied in per_node if all(s.node == ALL_NODES for s in applied)]


def _unreached(documents: Sequence[ParamsDocument], nodes: Sequence[str]) -> list[SchemaProblem]:
    """A problem at the top of the first file for each node that no section names."""
    seen = list(dict.fromkeys(s.node for d in documents for s in d.sections))
    where = Location(documents[0].file if documents else "-", 1, 1)
    listed = ", ".join(seen) if seen else "none"
    return [
        SchemaProblem(
            where,
            node,
            f"no section of the file names this node, so nothing checks it; sections seen: "
            f"{listed}{_closest_section(node, [s for s in seen if s != ALL_NODES])}",
        )
        for node in nodes
    ]


def _closest_section(node: str, sections: Sequence[str]) -> str:
    """`` (did you mean /robot/cam?)``: the section with the node's own name in another
    namespace when there is one such section, else the closest name, else ""."""
    found = closest_name(node, sections, separator="/", by_leaf=False)
    return f" (did you mean {found}?)" if found is not None else ""


def own_sections(sections: Sequence[Section], prefix: str) -> list[Section]:
    """The sections as a class under ``prefix`` sees them: its entries, names relative."""
    if not prefix:
        return list(sections)
    head = prefix + "."
    return [
        dataclasses.replace(
            section,
            entries=tuple(
                dataclasses.replace(e, name=e.name[len(head) :])
                for e in section.entries
                if e.name.startswith(head)
            ),
        )
        for section in sections
    ]


def _unknown_keys(checker: SectionChecker) -> set[tuple[Location, str]]:
    """Where and under which name each entry the checker does not own was written."""
    return {(u.key_location, u.name) for u in checker.unknown_entries}


def _claims(prefix: str, unknown: set[tuple[Location, str]], entry: ParamEntry) -> bool:
    """Whether the class under ``prefix`` owns ``entry`` (a set lookup: linear in the file)."""
    head = prefix + "." if prefix else ""
    if not entry.name.startswith(head):
        return False
    return (entry.key_location, entry.name[len(head) :]) not in unknown


def _prefixed(problem: SchemaProblem, prefix: str) -> SchemaProblem:
    if not prefix or not problem.key:
        return problem
    return dataclasses.replace(problem, key=join_prefix(prefix, problem.key))


def _unowned(entry: ParamEntry, owned: list[str], known: Sequence[str]) -> SchemaProblem | None:
    """The problem with an entry no schema owns, or None when rclpy or a framework owns it."""
    builtin = BUILTIN_PARAMETERS.get(entry.name)
    if builtin is not None:
        if isinstance(entry.value, bool):
            return None
        got = "nothing" if entry.value is None else _shown(entry.value)
        return SchemaProblem(
            entry.value_location, entry.name, f"wrong type: expected {builtin}, got {got}"
        )
    if entry.name.startswith(BUILTIN_PREFIXES) or is_known(entry.name, known):
        return None
    hint = suggestion(entry.name, [*owned, *BUILTIN_PARAMETERS])
    return SchemaProblem(
        entry.key_location, entry.name, f"unknown parameter{hint}: ROS would ignore it"
    )


def is_known(name: str, known: Sequence[str]) -> bool:
    """Whether ``name`` is one of ``known``: names or globs (``*.type``) owned by other code."""
    return any(fnmatch.fnmatchcase(name, pattern) for pattern in known)


def _shown(value: object) -> str:
    if isinstance(value, (bool, int, float, str)):
        return f"{ros_type_name(value)} {value!r}"
    return f"a list {value!r}"


def suggestion(name: str, candidates: Sequence[str]) -> str:
    """`` (did you mean 'camera.fps'?)`` for a misspelt or misplaced name, else ""."""
    return did_you_mean_name(name, candidates)
