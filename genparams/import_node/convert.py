"""What a running node reports of its parameters -> a genparams schema, as plain data.

Each parameter's current value becomes its default and every descriptor field is
kept: description, additional_constraints, read_only and the range with its step.
A parameter not set (declared by type only) is ``optional`` of its descriptor's type;
a dynamically typed one is ``type: any``.
Whatever a schema cannot state becomes a warning naming the parameter, and the
parameter is left out, never silently changed.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from genparams.errors import ParameterProblem
from genparams.importing import EXACT, LEFT_OUT, Imported, Outcome, attribute_clash, schema_name
from genparams.runtime.core.naming import NAME_RULE, NODE_PARAMETERS, is_ros_name
from genparams.runtime.core.types import TYPES_BY_ROS_TYPE

NOT_SET = 0  # rcl_interfaces ParameterType.PARAMETER_NOT_SET
BYTE_ARRAY = 5  # rcl_interfaces ParameterType.PARAMETER_BYTE_ARRAY


@dataclass(frozen=True)
class Reported:
    """One parameter as the node's services report it (list, get, describe)."""

    name: str
    type: int  # the value's rcl_interfaces ParameterType
    value: Any  # plain Python: bool, int, float, str, list
    description: str = ""
    additional_constraints: str = ""
    read_only: bool = False
    dynamic_typing: bool = False
    descriptor_type: int = NOT_SET  # the descriptor's type: a type-only declaration has one
    integer_range: tuple[int, int, int] | None = None  # from, to, step
    floating_point_range: tuple[float, float, float] | None = None


def import_node(node: str, reported: Sequence[Reported], name: str | None = None) -> Imported:
    """A schema declaring what ``node`` declares, with its current values as defaults.
    The parameters rclpy declares on every node are left out, each with a note."""
    schema = name or schema_name(node.rstrip("/").rpartition("/")[2], "node")
    tree: dict[str, Any] = {}
    names = {r.name for r in reported}
    kept: list[str] = []
    outcomes: list[Outcome] = []
    warnings: list[ParameterProblem] = []
    notes: list[ParameterProblem] = []
    for param in sorted(reported, key=lambda r: r.name):
        if param.name in NODE_PARAMETERS:
            notes.append(
                ParameterProblem(param.name, "note: declared by rclpy itself: left out", place=node)
            )
            continue
        problem = _problem(param, names) or attribute_clash(param.name, kept)
        if problem is not None:
            warnings.append(
                ParameterProblem(param.name, f"warning: {problem}: left out", place=node)
            )
            outcomes.append(Outcome(param.name, LEFT_OUT))
            continue
        *spaces, last = param.name.split(".")
        namespace = tree
        for part in spaces:
            namespace = namespace.setdefault(part, {})
        namespace[last] = _leaf(param)
        kept.append(param.name)
        outcomes.append(Outcome(param.name, EXACT, param.name))
    return Imported(
        name=schema,
        data={
            "genparams": 1,
            "name": schema,
            "description": f"Parameters of {node}, read from the running node.",
            "parameters": tree,
        },
        outcomes=tuple(outcomes),
        warnings=tuple(warnings),
        notes=tuple(notes),
    )


def _problem(param: Reported, names: set[str]) -> str | None:
    """Why a schema cannot state this parameter exactly, or None."""
    parts = param.name.split(".")
    if not is_ros_name(param.name):
        return f"its name is not made of names of {NAME_RULE}, joined by '.'"
    if any(".".join(parts[:n]) in names for n in range(1, len(parts))):
        return f"{'.'.join(parts[:-1])!r} is a parameter too, so it cannot be a namespace"
    if param.dynamic_typing:
        if param.integer_range or param.floating_point_range:
            return "a range on a dynamically typed parameter: a schema cannot state it"
        if param.type != NOT_SET and param.type not in TYPES_BY_ROS_TYPE:
            return f"unknown parameter type {param.type}"
        if param.type == BYTE_ARRAY:
            return "dynamically typed, holding a byte_array: a schema default cannot be one"
        return None
    kind = param.type if param.type != NOT_SET else param.descriptor_type
    if kind == NOT_SET:
        return "not set, and its descriptor gives no type"
    if kind not in TYPES_BY_ROS_TYPE:
        return f"unknown parameter type {kind}"
    is_array = TYPES_BY_ROS_TYPE[kind].name.endswith("_array")
    if is_array and (param.integer_range or param.floating_point_range):
        return "a range on an array: ROS applies it to no item, genparams to every item"
    for bounds in (param.integer_range, param.floating_point_range):
        if bounds is not None and bounds[0] > bounds[1]:
            return f"its range runs from {bounds[0]!r} down to {bounds[1]!r}"
        if bounds is not None and any(isinstance(b, float) and math.isnan(b) for b in bounds):
            return "its range has a NaN bound"
    return None


def _leaf(param: Reported) -> dict[str, Any]:
    """The parameter as a leaf: ``type: any`` for a dynamically typed one, ``optional``
    for one not set (declared by type only), else its type and current value."""
    if param.dynamic_typing:
        leaf: dict[str, Any] = {"type": "any"}
    else:
        kind = param.type if param.type != NOT_SET else param.descriptor_type
        leaf = {"type": TYPES_BY_ROS_TYPE[kind].name}
    if param.type == NOT_SET:
        leaf["optional"] = True
    else:
        leaf["default"] = param.value
    if param.description:
        leaf["description"] = param.description
    if param.read_only:
        leaf["read_only"] = True
    bounds = param.integer_range or param.floating_point_range
    if bounds is not None:
        low, high, step = bounds
        leaf["range"] = {"min": low, "max": high, **({"step": step} if step else {})}
    if param.additional_constraints:
        leaf["additional_constraints"] = param.additional_constraints
    return leaf
