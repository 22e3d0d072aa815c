"""Patterns: the ``regex`` engine loads only when a value from outside the schema is matched.

The generator matched every default against its patterns when it wrote the module, so
a node declaring a class with its defaults matches nothing and never imports the engine
(about 10 ms of a process). An override, a set or a schema read from a message is still
matched, refused when it does not match.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

import genparams
from genparams import GenparamsError
from genparams.runtime import ParameterDeclarationError
from genparams.runtime.core.validator_kinds import (
    ValidatorArgumentError,
    build_validator,
    checked_validator,
)
from genparams.runtime.core.validators import Pattern
from tests.patience import WAIT_S
from tests.support import RosHarness, load_generated

SCHEMA = """\
genparams: 1
name: framed
parameters:
  frame: {type: string, default: base_link, validators: [{pattern: '^[a-z_]+$'}]}
  topics: {type: string_array, default: [/a, /b], validators: [{pattern: '^/'}]}
"""

# `import regex` fails in this process (a None in sys.modules); rclpy's own parser then
# does without it. The class declares with its defaults and reads them back.
WITHOUT_ENGINE = """
import sys
sys.modules["regex"] = None
import importlib
import rclpy
from rclpy.context import Context
from rclpy.node import Node
sys.path.insert(0, sys.argv[1])
module = importlib.import_module("framed_params")
context = Context()
rclpy.init(context=context)
node = Node("pattern_engine_probe", context=context)
params = module.FramedParams.declare(node)
print(params.frame, *params.topics)
node.destroy_node()
rclpy.shutdown(context=context)
"""


@pytest.fixture
def framed(tmp_path: Path) -> Path:
    schema = tmp_path / "framed.yaml"
    schema.write_text(SCHEMA, encoding="utf-8")
    return schema


def test_a_declare_with_the_defaults_never_imports_the_pattern_engine(
    framed: Path, tmp_path: Path
) -> None:
    (tmp_path / "framed_params.py").write_text(genparams.generate(framed), encoding="utf-8")
    result = subprocess.run(
        [sys.executable, "-c", WITHOUT_ENGINE, str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=WAIT_S,
        env=dict(os.environ),
        check=False,
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ["base_link", "/a", "/b"]


def test_an_override_that_breaks_a_pattern_is_refused_at_start(
    ros: RosHarness, framed: Path, tmp_path: Path
) -> None:
    module = load_generated(framed, tmp_path)
    node = ros.node(args=["-p", "frame:=Base-Link", "-p", "topics:=[/a, b]"])
    with pytest.raises(ParameterDeclarationError) as caught:
        module.FramedParams.declare(node)
    assert tuple(map(str, caught.value.problems)) == (
        "frame: override rejected: must match '^[a-z_]+$' (pattern), got 'Base-Link'",
        "topics: override rejected: item 1 must match '^/' (pattern), got 'b'",
    )
    assert not node.has_parameter("frame")


def test_an_override_and_a_set_are_matched(ros: RosHarness, framed: Path, tmp_path: Path) -> None:
    module = load_generated(framed, tmp_path)
    node = ros.node(args=["-p", "frame:=odom"])
    params = module.FramedParams.declare(node)
    assert params.frame == "odom"
    (refused,) = node.set_parameters([Parameter("frame", value="Odom")])
    assert not refused.successful
    assert "must match '^[a-z_]+$' (pattern), got 'Odom'" in refused.reason
    assert params.frame == "odom"


# `re` reads these; the engine that matches refuses them.
ENGINE_REFUSES = ["{s3", "a{d>"]


@pytest.mark.parametrize("pattern", ENGINE_REFUSES)
def test_a_pattern_the_engine_refuses_is_a_schema_error(pattern: str) -> None:
    build_validator("pattern", pattern, "string")  # re's syntax: the engine is not asked
    with pytest.raises(ValidatorArgumentError, match=r"is not a valid regex: "):
        checked_validator("pattern", pattern, "string")


def test_the_generator_refuses_a_pattern_the_engine_refuses(tmp_path: Path) -> None:
    schema = tmp_path / "posix.yaml"
    schema.write_text(
        "genparams: 1\nname: posix\nparameters:\n"
        "  label: {type: string, validators: [{pattern: '{s3'}]}\n",
        encoding="utf-8",
    )
    with pytest.raises(GenparamsError, match=r"pattern '\{s3' is not a valid regex"):
        genparams.generate(schema)


@pytest.mark.parametrize("pattern", ENGINE_REFUSES)
def test_a_pattern_never_checked_refuses_every_value(pattern: str) -> None:
    """A pattern built at run time from a message the generator never saw."""
    reason = Pattern(pattern)("abc")
    assert reason is not None
    assert reason.startswith(f"cannot be matched against {pattern!r} (pattern): ")
