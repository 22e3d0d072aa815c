"""Benchmark schemas: N parameters of mixed types and validators, spread over nested namespaces.

Parameters come in groups of ten, one of each kind below. Groups are leaves
of a namespace tree with at most ten children per level, so the tree grows in
depth with N the way large real schemas do (``a3.b7.gain``), and no level is
wider than ten.

The same parameters are also written as hand-written rclpy would declare
them: a literal ``node.declare_parameters`` call with the same names, values
and ``ParameterDescriptor`` fields, plus a trivial on-set callback that
accepts everything.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

FANOUT = 10
LEVEL_LETTERS = "abcdefgh"


@dataclass(frozen=True)
class Kind:
    """One kind of parameter: its schema leaf and a second valid value to set it to."""

    name: str
    leaf: dict[str, Any]
    other: Any  # a valid value different from the default, in ROS form

    @property
    def default(self) -> Any:
        return self.leaf["default"]


KINDS: tuple[Kind, ...] = (
    Kind(
        "speed",
        {
            "type": "double",
            "default": 1.5,
            "unit": "m/s",
            "description": "Cruise speed.",
            "range": {"min": 0.0, "max": 100.0},
        },
        2.5,
    ),
    Kind(
        "count",
        {"type": "int", "default": 10, "range": {"min": 0, "max": 1000, "step": 2}},
        12,
    ),
    Kind(
        "mode",
        {"type": "string", "default": "fast", "choices": ["fast", "slow", "off"]},
        "slow",
    ),
    Kind("enabled", {"type": "bool", "default": True, "description": "Switch."}, False),
    Kind(
        "gain",
        {"type": "double", "default": 1.0, "validators": [{"gt": 0.0}], "description": "Gain."},
        2.0,
    ),
    Kind(
        "topics",
        {"type": "string_array", "default": ["/a", "/b"], "validators": ["not_empty", "unique"]},
        ["/a", "/c"],
    ),
    Kind(
        "ids",
        {"type": "int_array", "default": [1, 2, 3], "validators": [{"element_bounds": [0, 10]}]},
        [4, 5, 6],
    ),
    Kind(
        "weights",
        {
            "type": "double_array",
            "default": [0.5, 0.5],
            "validators": [{"length": {"min": 1, "max": 8}}],
        },
        [0.25, 0.75],
    ),
    Kind(
        "frame",
        {"type": "string", "default": "base_link", "validators": [{"pattern": "^[a-z_]+$"}]},
        "odom",
    ),
    Kind(
        "offset",
        {"type": "int", "default": 0, "validators": [{"bounds": [-5, 5]}], "unit": "mm"},
        3,
    ),
)


@dataclass(frozen=True)
class BenchParameter:
    name: str  # dotted ROS name
    kind: Kind


@dataclass(frozen=True)
class BenchSchema:
    """The parameters of one benchmark size; what every scenario reads and sets."""

    size: int
    parameters: tuple[BenchParameter, ...]

    @property
    def name(self) -> str:
        return f"bench_{self.size}"

    @property
    def module_name(self) -> str:
        return f"{self.name}_params"

    @property
    def class_name(self) -> str:
        return f"Bench{self.size}Params"

    @property
    def plain_module_name(self) -> str:
        return f"{self.name}_plain"

    @property
    def probe(self) -> BenchParameter:
        """The parameter the read and single-set scenarios use: a ``gain`` at full depth."""
        return next(p for p in self.parameters if p.kind.name == "gain")

    @property
    def depth(self) -> int:
        """Attribute hops from the root to a parameter (``cfg.a0.b0.gain`` is 3)."""
        return self.probe.name.count(".") + 1

    def document(self) -> dict[str, Any]:
        tree: dict[str, Any] = {}
        for parameter in self.parameters:
            *namespaces, leaf = parameter.name.split(".")
            level = tree
            for namespace in namespaces:
                level = level.setdefault(namespace, {})
            level[leaf] = parameter.kind.leaf
        return {
            "genparams": 1,
            "name": self.name,
            "description": f"Benchmark schema with {self.size} parameters.",
            "parameters": tree,
        }

    def yaml_text(self) -> str:
        return yaml.dump(
            self.document(), Dumper=_Dumper, sort_keys=False, width=100, default_flow_style=None
        )

    def values(self, *, other: bool = False) -> dict[str, Any]:
        """Every parameter's default (or its other valid value), by ROS name."""
        return {p.name: p.kind.other if other else p.kind.default for p in self.parameters}


class _Dumper(getattr(yaml, "CSafeDumper", yaml.SafeDumper)):  # type: ignore[misc]
    """Writes every leaf in full, as a person would, never as a YAML alias."""

    def ignore_aliases(self, data: Any) -> bool:
        return True


def group_paths(size: int) -> Iterator[str]:
    """Dotted namespaces of the ``ceil(size / 10)`` leaf groups, at equal depth."""
    groups = max(1, math.ceil(size / len(KINDS)))
    depth = max(1, math.ceil(math.log(groups, FANOUT) - 1e-9))
    for index in range(groups):
        digits = []
        for _ in range(depth):
            index, digit = divmod(index, FANOUT)
            digits.append(digit)
        yield ".".join(f"{LEVEL_LETTERS[level]}{d}" for level, d in enumerate(reversed(digits)))


def bench_schema(size: int) -> BenchSchema:
    parameters: list[BenchParameter] = []
    for path in group_paths(size):
        for kind in KINDS[: size - len(parameters)]:
            parameters.append(BenchParameter(f"{path}.{kind.name}", kind))
    return BenchSchema(size, tuple(parameters))


def write_schema(schema: BenchSchema, directory: Path) -> Path:
    path = directory / f"{schema.name}.yaml"
    path.write_text(schema.yaml_text(), encoding="utf-8")
    return path


_PLAIN_HEADER = '''\
"""{size} parameters declared the hand-written rclpy way (same names and descriptors)."""

from rcl_interfaces.msg import (
    FloatingPointRange,
    IntegerRange,
    ParameterDescriptor,
    SetParametersResult,
)
from rclpy.node import Node


def accept(parameters):
    return SetParametersResult(successful=True)


def declare(node: Node) -> None:
    node.declare_parameters(
        "",
        [
'''

_PLAIN_FOOTER = """\
        ],
    )
    node.add_on_set_parameters_callback(accept)
"""


def plain_module_source(schema: BenchSchema, descriptors: dict[str, Any]) -> str:
    """The hand-written declaration of ``schema``.

    ``descriptors`` (ROS name -> ParameterDescriptor, as genparams declares
    them) supplies the descriptor fields, so both sides describe every
    parameter identically; the text is then what a person would type.
    """
    lines = [_PLAIN_HEADER.format(size=schema.size)]
    for parameter in schema.parameters:
        descriptor = descriptors[parameter.name]
        lines.append(
            f"            ({parameter.name!r}, {parameter.kind.default!r}, "
            f"{_descriptor_literal(descriptor)}),\n"
        )
    lines.append(_PLAIN_FOOTER)
    return "".join(lines)


def _descriptor_literal(descriptor: Any) -> str:
    fields = []
    if descriptor.description:
        fields.append(f"description={descriptor.description!r}")
    if descriptor.additional_constraints:
        fields.append(f"additional_constraints={descriptor.additional_constraints!r}")
    if descriptor.read_only:
        fields.append("read_only=True")
    for ros_range in descriptor.integer_range:
        fields.append(
            "integer_range=[IntegerRange("
            f"from_value={ros_range.from_value!r}, to_value={ros_range.to_value!r}, "
            f"step={ros_range.step!r})]"
        )
    for ros_range in descriptor.floating_point_range:
        fields.append(
            "floating_point_range=[FloatingPointRange("
            f"from_value={ros_range.from_value!r}, to_value={ros_range.to_value!r}, "
            f"step={ros_range.step!r})]"
        )
    return f"ParameterDescriptor({', '.join(fields)})"
