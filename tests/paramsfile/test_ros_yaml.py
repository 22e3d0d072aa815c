"""paramsfile.ros_yaml against ROS itself: each spelling and node pattern is fed to a real node."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import yaml

from genparams.paramsfile.ros_yaml import NoValue, node_matches, node_pattern_problem, ros_scalar
from tests.support import RosHarness

SPELLINGS = [
    "30",
    "30.0",
    "-7",
    "+5",
    "0x1F",
    "-0x10",
    "010",
    "08",
    "0",
    "-0",
    "1_000",
    "0o10",
    "0b1",
    "1e3",
    "1.0e-05",
    "1e",
    "5.",
    ".5",
    "1e400",
    "1e-400",
    "9223372036854775807",
    "9223372036854775808",
    "-9223372036854775808",
    "0x1p3",
    "nan",
    "NaN",
    "inf",
    "-Infinity",
    ".inf",
    "-.inf",
    ".nan",
    ".NaN",
    "+.inf",
    "true",
    "True",
    "TRUE",
    "yes",
    "Y",
    "n",
    "on",
    "OFF",
    "tRue",
    "null",
    "~",
    "rgb8",
    "/sensor/data",
    "1.2.3",
    "'30'",
    '"true"',
    "''",
    "'yes'",
    "a b",
    "|-\n      5",
    ">-\n      7.5",
]


def _overrides(ros: RosHarness, tmp_path: Path, text: str, name: str, namespace: str) -> Any:
    path = tmp_path / f"{name}_{abs(hash((text, namespace)))}.yaml"
    path.write_text(text, encoding="utf-8")
    node = ros.node(name, namespace=namespace, args=["--params-file", str(path)])
    return {key: p.value for key, p in node._parameter_overrides.items()}


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    return type(a) is type(b) and a == b


def test_scalars_are_typed_as_ros_types_them(ros: RosHarness, tmp_path: Path) -> None:
    lines = [f"    p{index}: {text}" for index, text in enumerate(SPELLINGS)]
    text = "/**:\n  ros__parameters:\n" + "\n".join(lines) + "\n"
    seen = _overrides(ros, tmp_path, text, "scalars", "/")
    nodes = yaml.compose(text)
    assert nodes is not None
    params = nodes.value[0][1].value[0][1].value
    for index, (_key, value_node) in enumerate(params):
        ours = ros_scalar(value_node.value, value_node.style)
        assert _same(ours, seen[f"p{index}"]), (SPELLINGS[index], ours, seen[f"p{index}"])


def test_empty_value_is_no_value() -> None:
    assert isinstance(ros_scalar("", None), NoValue)
    assert ros_scalar("", '"') == ""


PATTERNS = [
    "/**",
    "/*",
    "/ns/*",
    "/ns/**",
    "/**/n",
    "/**/*",
    "/*/n",
    "/a/**/n",
    "/ns/**/n",
    "/*/*",
    "ns/n",
    "/ns/n/**",
    "/**/ns/n",
    "n",
    "/n",
    "/**/**",
]
NODES = [("n", "/"), ("n", "/ns"), ("n", "/a/b/ns"), ("n", "/a/ns"), ("m", "/ns")]


def test_node_patterns_match_as_ros_matches_them(ros: RosHarness, tmp_path: Path) -> None:
    # One section per pattern, each setting its own parameter: a node sees hit<i> when
    # ROS applied pattern i to it.
    text = "".join(
        f"{pattern}:\n  ros__parameters:\n    hit{index}: true\n"
        for index, pattern in enumerate(PATTERNS)
    )
    for name, namespace in NODES:
        seen = _overrides(ros, tmp_path, text, name, namespace)
        fqn = f"{namespace.rstrip('/')}/{name}"
        for index, pattern in enumerate(PATTERNS):
            assert node_pattern_problem(pattern) is None
            assert node_matches(pattern, fqn) == (f"hit{index}" in seen), (pattern, fqn)


def test_invalid_node_patterns_are_named() -> None:
    assert node_pattern_problem("/ns/camera-1") == (
        "node name 'camera-1' may hold only letters, digits and '_'"
    )
    assert node_pattern_problem("/1ns/n") == "namespace must not start with a number: '1ns'"
    assert node_pattern_problem("/ns//n") == "contains repeated forward slash"
    assert node_pattern_problem("/ns/") == "node name must not be empty"
    assert node_pattern_problem("/n*") == "node name 'n*' may hold only letters, digits and '_'"
