"""Work on a schema message is bounded by its size.

- A pattern whose counted repeats multiply (``(?:x{400}){400}``: 160,000 nodes once
  compiled; ``(?:x{2000}){2000}`` took a gigabyte) makes the message a problem, told before
  anything compiles it.
- Mapped groups chained inside each other's entries (``g``, ``g.*.g``, ...): reading the
  message, mapping its places and auditing the node grow with the message's size (its
  characters), not with a power of the depth. The work is counted in Python lines run, so the
  test does not depend on the machine's speed.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Callable
from types import FrameType
from typing import Any

from genparams.audit.schema_checks import check_node
from genparams.runtime.core.schema_message import SchemaProblem, read_schema_message
from genparams.tune.places import entry_places

NODE = "/chain"


def field(name: str, validators: list[list[str]] | None = None) -> dict[str, Any]:
    return {
        "name": name,
        "type": "string" if validators else "double",
        "required": False,
        "default": "x" if validators else 1.0,
        "description": "",
        "unit": None,
        "read_only": False,
        "constraints": [],
        "aliases": [],
        "choices": None,
        "range": None,
        "validators": validators or [],
    }


def message(parameters: list[dict[str, Any]], maps: list[dict[str, Any]]) -> str:
    described = {"class": "C", "prefix": "", "hash": "h", "parameters": parameters}
    described |= {"maps": maps, "rules": []}
    body = {"format": 1, "node": NODE, "genparams": "1", "hash": "h", "classes": [described]}
    return json.dumps(body)


def test_a_pattern_that_multiplies_is_a_problem_before_it_is_compiled() -> None:
    costly = message([field("label", [["pattern", "(?:x{400}){400}"]])], [])
    read = read_schema_message(costly, NODE)
    assert isinstance(read, SchemaProblem)
    assert "expands to more than" in read.detail and "(?:x{400}){400}" in read.detail
    fine = message([field("label", [["pattern", r"^\d{1,3}(\.\d{1,3}){3}$"]])], [])
    assert not isinstance(read_schema_message(fine, NODE), SchemaProblem)


def chain(depth: int) -> tuple[str, dict[str, Any]]:
    """A message of ``depth`` open groups, each in the entry of the one before, and a node's
    values: one entry ``k`` in each."""
    maps, path = [], "g"
    for _ in range(depth):
        maps.append({"path": path, "for_each": "(overrides)", "fields": [field("v")]})
        path += ".*.g"
    values, name = {}, "g"
    for _ in range(depth):
        values[f"{name}.k.v"] = 1.0
        name += ".k.g"
    return message([], maps), values


def lines_run(work: Callable[[], object]) -> int:
    count = [0]

    def tracer(frame: FrameType, event: str, arg: Any) -> Any:
        if event == "line":
            count[0] += 1
        return tracer

    sys.settrace(tracer)
    try:
        work()
    finally:
        sys.settrace(None)
    return count[0]


def work(depth: int) -> tuple[int, int]:
    """(lines run to read, place and audit a chain of ``depth`` groups; the size of what the
    node gives: the message's characters and its names')."""
    text, values = chain(depth)

    def everything() -> None:
        schema = read_schema_message(text, NODE)
        assert isinstance(schema, dict)
        parameters = [{"name": n, "type": "double", "value": v} for n, v in values.items()]
        assert len(entry_places(schema, parameters)) == depth
        assert check_node(NODE, schema, values) == []

    return lines_run(everything), len(text) + sum(map(len, values))


def test_chained_groups_cost_work_in_proportion_to_the_message() -> None:
    small_lines, small_size = work(40)
    large_lines, large_size = work(160)
    # What the node gives grows about 10-fold (paths and names grow with depth); the work may
    # grow as much, with room to spare, not as a power of the depth would make it.
    assert large_lines / small_lines < 1.5 * large_size / small_size, (
        small_lines,
        large_lines,
        small_size,
        large_size,
    )
