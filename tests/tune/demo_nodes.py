"""Real nodes for the tuning and audit tests, in a process of their own.

``python -m tests.tune.demo_nodes NAME:KIND ...`` starts one node per argument
(KIND: camera, arm, motion, nonfinite, open, names, plain, loose, hostile, edges, checks, or
wideN with N parameters) and prints "ready" once every node is declared. ROS arguments for
every node follow ``--``.
"""

from __future__ import annotations

import json
import sys
import tempfile
from pathlib import Path
from typing import Any

import rclpy
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor
from rclpy.node import Node

import genparams
from tests.edge_values import SCHEMA as EDGES_SCHEMA
from tests.node_process import serve
from tests.support import ROOT, import_file

SCHEMAS = {
    "camera": ROOT / "examples/camera_node/camera_driver.yaml",
    "arm": ROOT / "examples/arm/arm.yaml",
    "motion": ROOT / "examples/motion/motion.yaml",
    "nonfinite": ROOT / "tests/tune/nonfinite.yaml",
    "open": ROOT / "tests/cases/open_groups/schema.yaml",  # its keys come from a params file
    "names": ROOT / "tests/cases/ros_names/schema.yaml",  # names with '-', '/' and type
}


def wide_schema(count: int) -> str:
    """A schema of ``count`` ranged doubles in namespaces of 50, for the benchmark."""
    lines = ["genparams: 1", "name: wide", "parameters:"]
    for group in range(count // 50):
        lines.append(f"  group_{group}:")
        for index in range(50):
            lines.append(
                f"    p_{index}: {{type: double, default: 1.0, unit: m,"
                f" range: {{min: 0.0, max: 10.0, step: 0.5}}, description: Value {index}.}}"
            )
    return "\n".join(lines) + "\n"


# Markup and script in every text a schema lets a node publish: the page shows it as text.
HOSTILE_TEXT = '<img src=x onerror="window.pwned=1"><script>window.pwned=2</script>'


def hostile_schema() -> str:
    text = json.dumps(HOSTILE_TEXT)  # a JSON string is a double-quoted YAML scalar
    return (
        f"genparams: 1\nname: hostile\ndescription: {text}\nparameters:\n"
        f"  mode: {{type: string, default: ok, description: {text}, unit: {text},"
        f" choices: [ok, {text}]}}\n"
        f"  gain: {{type: double, default: 1.0, description: {text}, unit: {text}}}\n"
    )


# What the page's checks are tested on: a pattern, double edges and a step, a rule, a custom
# validator the tuning machine can import and one only the node can.
CHECKS_SCHEMA = r"""genparams: 1
name: checks
parameters:
  label: {type: string, default: abc, validators: [{pattern: '^\w+$'}]}
  share: {type: double, default: 0.5, range: {min: 0.0, max: 1.0}}
  fine: {type: double, default: 0.2, range: {min: 0.0, max: 1.0, step: 0.1}}
  even: {type: int, default: 2, validators: [{custom: 'tests.custom_checks:is_even'}]}
  short: {type: string, default: ab, validators: [{custom: 'node_only_checks:is_short'}]}
  low: {type: int, default: 1}
  high: {type: int, default: 5}
rules:
  - {name: low_below_high, check: 'low < high', description: Low stays below high.}
"""

NODE_ONLY_CHECKS = """def is_short(value):
    return None if len(value) <= 3 else f"{value!r} is longer than 3"
"""


# Integers past 2^53, doubles that hold whole numbers, and a rule: as the page must show them.
VALUES_SCHEMA = """\
genparams: 1
name: values
parameters:
  big: {type: int, default: 9007199254740993}
  ids: {type: int_array, default: [9007199254740993, -9223372036854775808]}
  ratio: {type: double, default: 30.0}
  weights: {type: double_array, default: [1.0, 2.5]}
  ranged: {type: double, default: 2.0, range: {min: 0.0, max: 10.0}}
  low: {type: double, default: 1.0}
rules:
  - name: low_below_ranged
    check: low <= ranged
    description: low stays at or below ranged.
"""


def schema_text(kind: str, workdir: Path) -> tuple[Path, str] | None:
    """The schema of a kind written in code, or None for an example's file."""
    if kind == "values":
        return workdir / "values.yaml", VALUES_SCHEMA
    if kind.startswith("wide"):
        return workdir / "wide.yaml", wide_schema(int(kind[4:] or 1000))
    if kind == "hostile":
        return workdir / "hostile.yaml", hostile_schema()
    if kind == "edges":
        return workdir / "edges.yaml", EDGES_SCHEMA
    if kind == "checks":
        # A module of the node's own: the tuning machine cannot import it.
        (workdir / "node_only_checks.py").write_text(NODE_ONLY_CHECKS, encoding="utf-8")
        if str(workdir) not in sys.path:
            sys.path.insert(0, str(workdir))
        return workdir / "checks.yaml", CHECKS_SCHEMA
    return None


def params_class(kind: str, workdir: Path) -> type[Any]:
    written = schema_text(kind, workdir)
    if written is not None:
        text = genparams.generate(*written)
    else:
        text = genparams.generate(SCHEMAS[kind])
    path = workdir / f"{kind}_params.py"
    path.write_text(text, encoding="utf-8")
    module = import_file(path)
    return next(
        value
        for name, value in vars(module).items()
        if name.endswith("Params") and isinstance(value, type) and hasattr(value, "_SPEC")
    )


def plain_node(name: str, args: list[str]) -> Node:
    node = Node(name, cli_args=["--ros-args", *args] if args else None)
    node.declare_parameter(
        "gain",
        2.0,
        ParameterDescriptor(
            description="Loop gain.",
            floating_point_range=[FloatingPointRange(from_value=0.0, to_value=10.0, step=0.5)],
        ),
    )
    node.declare_parameter(
        "retries",
        3,
        ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=10, step=1)]),
    )
    node.declare_parameter("frame", "map", ParameterDescriptor(description="Frame id."))
    node.declare_parameter("enabled", True)
    node.declare_parameter("hardware_id", 7, ParameterDescriptor(read_only=True))
    return node


def loose_node(name: str, workdir: Path) -> Node:
    """Describes itself with the motion schema but declares plain, unchecked parameters.

    What a node in another language, or an older build, may do: the audit, not
    the node, has to catch the values its schema forbids.
    """
    from genparams.runtime.core.spec import compile_schema
    from genparams.runtime.node.schema_topic import publish_schema

    spec = params_class("motion", workdir)._SPEC
    node = Node(name)
    for param in spec.parameters:
        node.declare_parameter(param.name, param.default)
    publish_schema(node, compile_schema(spec), "")
    return node


def main(argv: list[str]) -> int:
    specs, ros_args = argv, []
    if "--" in argv:
        specs, ros_args = argv[: argv.index("--")], argv[argv.index("--") + 1 :]
    rclpy.init()
    workdir = Path(tempfile.mkdtemp(prefix="genparams-demo-"))
    nodes, keep = [], []
    for spec in specs:
        name, _, kind = spec.partition(":")
        if kind == "plain":
            node = plain_node(name, ros_args)
        elif kind == "loose":
            node = loose_node(name, workdir)
        else:
            # The camera's serial has no default: it must come from an override.
            own = ["-p", "serial:=CAM12345"] if kind == "camera" else []
            node = Node(name, cli_args=["--ros-args", *own, *ros_args])
            keep.append(params_class(kind, workdir).declare(node))
        nodes.append(node)
    return serve(nodes)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
