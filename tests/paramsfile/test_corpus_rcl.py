"""On every section of real params files, genparams and rcl agree on what a node gets.

The files are the params files of ros2_controllers, ros2_control,
ros2_control_demos and generate_parameter_library (the corpus's paramsfile
folder: tests/corpus.py, and SOURCES.md there). For every node a section names
(a wildcard section stands for a node it matches), the values genparams reads
for that node, in rcl's order, must be exactly the overrides a real node receives.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest

from genparams.paramsfile.node_sections import sections_for
from genparams.paramsfile.params_reader import read_params_file
from tests import corpus
from tests.paramsfile.rcl_load import RclRefusedError, file_args, overrides, plain

CORPUS = corpus.folder("paramsfile")
FILES = sorted(CORPUS.glob("*/*/params/*.yaml"))


def concrete(pattern: str) -> str:
    """A node a section named ``pattern`` applies to: ``/**/cm`` -> ``/robot/cm``."""
    tokens = ["robot" if t == "**" else "x" if t == "*" else t for t in pattern[1:].split("/")]
    return "/" + "/".join(tokens)


def genparams_values(path: Path, node: str) -> dict[str, Any]:
    document = read_params_file(path.read_text(encoding="utf-8"), str(path))
    assert not document.problems, document.problems
    applied, _skipped = sections_for([document.sections], node)
    values: dict[str, Any] = {}
    for section in applied:
        for entry in section.entries:
            values[entry.name] = plain(entry.value)
    return values


def same(one: Any, other: Any) -> bool:
    if isinstance(one, float) and isinstance(other, float) and math.isnan(one):
        return math.isnan(other)
    return type(one) is type(other) and one == other


def test_the_corpus_is_all_there() -> None:
    sections = 0
    for path in FILES:
        sections += len(read_params_file(path.read_text(encoding="utf-8"), str(path)).sections)
    assert len(FILES) == 86
    assert sections == 169


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(CORPUS)))
def test_every_node_of_a_real_file_gets_what_rcl_gives(path: Path) -> None:
    document = read_params_file(path.read_text(encoding="utf-8"), str(path))
    nodes = sorted({concrete(s.node) for s in document.sections})
    for node in nodes:
        try:
            real = overrides(node, file_args(path))
        except RclRefusedError as exc:
            pytest.fail(f"rcl refuses {path.name} for {node}: {exc}")
        ours = genparams_values(path, node)
        assert ours.keys() == real.keys(), node
        for name, value in real.items():
            # rclpy hands empty lists and not-set values over as None
            assert same(ours[name], value) or (ours[name] is None and value is None), (node, name)
