"""Which sections of params files reach one node, in the order rcl applies them.

rcl parses every ``--params-file`` and ``-p`` rule, in command-line order, into
one table keyed by the section's node name: a name seen again (in a later
file) reuses its first slot, and its values overwrite the earlier ones there.
A node then takes every slot whose name matches it, in slot order, later slots
overriding earlier ones. So order is by the first appearance of a node name,
not by file: a ``/**`` section first written before ``/robot/cam`` is applied
before it, even when a later file repeats it. ``*`` matches one name token,
``**`` any number; nested keys (``/**: {controller_manager: ...}``) join with
``/``. These rules were checked against rclpy on Jazzy (tests/paramsfile).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from genparams.paramsfile.params_reader import ParamEntry, Section
from genparams.paramsfile.ros_yaml import absolute, node_matches
from genparams.runtime.core.naming import WILDCARD_ANY, WILDCARD_ONE
from genparams.runtime.core.suggest import close_names, edit_distance, numbered_copies

__all__ = [
    "Skipped",
    "edit_distance",
    "entries_in_force",
    "near_miss",
    "rcl_order",
    "sections_for",
]


@dataclass(frozen=True)
class Skipped:
    section: Section
    reason: str
    near_miss: bool  # the name is close to the node's: likely a typo


def rcl_order(files: Sequence[Sequence[Section]]) -> list[Section]:
    """Every section of ``files`` (in command-line order) in the order rcl applies them."""
    slots: dict[str, list[Section]] = {}
    for sections in files:
        for section in sections:
            slots.setdefault(section.node, []).append(section)
    return [section for group in slots.values() for section in group]


def sections_for(
    files: Sequence[Sequence[Section]], node: str
) -> tuple[list[Section], list[Skipped]]:
    """The sections that reach ``node``, in rcl's order, and the others with the reason."""
    applied: list[Section] = []
    skipped: list[Skipped] = []
    for section in rcl_order(files):
        if node_matches(section.node, node):
            applied.append(section)
            continue
        near = near_miss(section.node, node)
        reason = f"for another node (not {node})" if near is None else near
        skipped.append(Skipped(section, reason, near is not None))
    return applied, skipped


def entries_in_force(applied: Sequence[Section]) -> dict[str, tuple[Section, ParamEntry]]:
    """The entry that gives each name its value, and its section: of the sections
    :func:`sections_for` applies, in that order, the last to write the name."""
    return {entry.name: (section, entry) for section in applied for entry in section.entries}


def near_miss(pattern: str, node: str) -> str | None:
    """Why a section named ``pattern`` looks meant for ``node`` but misses it, or None.

    ``node`` may be a pattern itself (a manifest's ``/*/camera``).
    """
    pattern, node = absolute(pattern), absolute(node)
    tokens, wanted = pattern[1:].split("/"), node[1:].split("/")
    if WILDCARD_ANY in tokens or WILDCARD_ONE in tokens[-1:]:
        return None  # a pattern for many nodes: missing one is its purpose
    name, node_name = tokens[-1], wanted[-1]
    namespace, node_namespace = "/" + "/".join(tokens[:-1]), "/" + "/".join(wanted[:-1])
    same_namespace = node_matches(node_namespace, namespace) or node_matches(
        namespace, node_namespace
    )
    if name == node_name and not same_namespace:
        if namespace == "/" or _typo(namespace, node_namespace):
            return f"same node name in namespace {namespace}, but {node} runs in {node_namespace}"
        return None
    if name != node_name and same_namespace and _typo(name, node_name):
        return f"node name {name!r} is close to {node_name!r}: a typo?"
    return None


def _typo(written: str, meant: str) -> bool:
    """Close, and not numbered copies (robot_1 and robot_2, joint1 and joint2 are both real)."""
    return close_names(written, meant) and not numbered_copies(written, meant)
