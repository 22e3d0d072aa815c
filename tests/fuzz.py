"""Fuzz the schema front end: loader -> schema check -> model builder -> renderer.

The only exception any input may raise is SchemaError (with at least one
problem, each with a 1-based line and column); anything else is a bug. An
accepted schema must render to a module that compiles.

Three input families, each a Hypothesis strategy:
- ``yaml_soup``: random YAML-looking text (anchors, tags, flow and block
  syntax, tabs, keys of the schema format, odd numbers);
- ``edited_texts``: a valid schema's text with random edits (deleted or
  repeated spans, inserted YAML tokens);
- ``near_valid_documents``: a valid schema as data with a few values replaced,
  keys removed, added or misspelt, written back as YAML.

Long runs:  .venv/bin/python -m tests.fuzz --seconds 3600
"""

from __future__ import annotations

import argparse
import copy
import time
from collections.abc import Callable
from typing import Any

from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from genparams.api import load_schema
from genparams.outputs.render import render_module
from genparams.schema.errors import SchemaError
from tests.strategies import HOSTILE_TEXT, schemas
from tests.yaml_text import Flow, block

SCHEMA_WORDS = (
    "genparams", "name", "description", "parameters", "type", "default", "read_only", "unit",
    "range", "min", "max", "step", "choices", "validators", "additional_constraints",
    "deprecated", "rules", "check", "for_each", "aliases", "bool", "int", "double", "string",
    "byte_array", "bool_array", "int_array", "double_array", "string_array", "gt", "ge", "lt",
    "le", "bounds", "element_bounds", "one_of", "subset_of", "not_empty", "unique", "length",
    "exact", "pattern", "custom",
)  # fmt: skip
YAML_TOKENS = (
    ": ", "- ", "\n", "\n  ", "\n    ", "\t", "[", "]", "{", "}", ", ", "&a ", "*a", "&b ",
    "*b", "<<: *a", "!!str ", "!!int ", "!!float ", "!!binary ", "!!python/object:os.system ",
    "!!python/name:os.system", "!custom ", "? ", "|\n  ", ">-\n  ", "---\n", "\n...\n",
    "%YAML 1.1\n", "%TAG ! tag:x,2000:\n", "'", '"', "#", "~", "null", "true", "no", "on",
    ".inf", "-.nan", "0x1F", "0o17", "1e400", "1_000", "9223372036854775808",
    "-9223372036854775809", "1" * 400, "2001-12-14", "=", "\\u0000", "\\ud800", "\ufeff",
)  # fmt: skip
INTERESTING_VALUES: tuple[object, ...] = (
    None, True, False, 0, -1, 2**63 - 1, 2**63, -(2**63) - 1, 2**64, 10**400, -(10**400),
    0.0, -0.0, 1e308, 5e-324, float("inf"), float("-inf"), float("nan"), "", " ",
    "x" * 300, [], {}, [[]], [1, "a"], {"min": 5, "max": 1}, {"min": 0, "max": 10, "step": 0.0},
)  # fmt: skip

yaml_soup = st.lists(
    st.one_of(
        st.sampled_from(SCHEMA_WORDS),
        st.sampled_from(YAML_TOKENS),
        st.sampled_from(HOSTILE_TEXT),
        st.text(max_size=5),
        st.integers().map(str),
    ),
    max_size=60,
).map("".join)


@st.composite
def edited_texts(draw: st.DrawFn) -> str:
    text = draw(schemas()).text
    for _ in range(draw(st.integers(1, 4))):
        start = draw(st.integers(0, len(text)))
        end = draw(st.integers(start, min(len(text), start + 40)))
        edit = draw(st.sampled_from(["delete", "repeat", "insert", "replace"]))
        token = draw(st.sampled_from(YAML_TOKENS + SCHEMA_WORDS))
        if edit == "delete":
            text = text[:start] + text[end:]
        elif edit == "repeat":
            text = text[:end] + text[start:end] + text[end:]
        elif edit == "insert":
            text = text[:start] + token + text[start:]
        else:
            text = text[:start] + token + text[end:]
    return text


scalars = st.one_of(
    st.sampled_from(INTERESTING_VALUES),
    st.sampled_from(SCHEMA_WORDS),
    st.integers(),
    st.floats(),
    st.text(max_size=10),
)
anything = st.recursive(
    scalars,
    lambda children: st.one_of(
        st.lists(children, max_size=4),
        st.dictionaries(st.sampled_from(SCHEMA_WORDS) | st.text(max_size=6), children, max_size=4),
    ),
    max_leaves=8,
)


def _unwrap(value: Any) -> Any:
    if isinstance(value, Flow):
        value = value.mapping
    if isinstance(value, dict):
        return {k: _unwrap(v) for k, v in value.items()}
    return copy.copy(value)


def _mappings(tree: Any, out: list[dict[str, Any]]) -> list[dict[str, Any]]:
    if isinstance(tree, dict):
        out.append(tree)
        for value in tree.values():
            _mappings(value, out)
    elif isinstance(tree, list):
        for value in tree:
            _mappings(value, out)
    return out


@st.composite
def near_valid_documents(draw: st.DrawFn) -> str:
    document = _unwrap(draw(schemas()).document)
    for _ in range(draw(st.integers(1, 3))):
        mapping = draw(st.sampled_from(_mappings(document, [])))
        keys = list(mapping)
        edit = draw(st.sampled_from(["replace", "delete", "add", "rename"]))
        if edit == "add" or not keys:
            mapping[draw(st.sampled_from(SCHEMA_WORDS) | st.text(max_size=8))] = draw(anything)
            continue
        key = draw(st.sampled_from(keys))
        if edit == "replace":
            mapping[key] = draw(anything)
        elif edit == "delete":
            del mapping[key]
        else:
            mapping[key[:-1] or "x"] = mapping.pop(key)
    return block(document, quote_keys=True)


def check(text: str) -> None:
    """The fuzz target: SchemaError, or a module that compiles."""
    try:
        schema = load_schema("fuzz.yaml", text)
    except SchemaError as exc:
        assert exc.problems, "SchemaError without problems"
        for problem in exc.problems:
            assert problem.location.line >= 1 and problem.location.column >= 1, problem
        assert str(exc)
        return
    compile(render_module(schema), "fuzz_params.py", "exec")


TARGETS: dict[str, st.SearchStrategy[str]] = {
    "yaml_soup": yaml_soup,
    "edited_texts": edited_texts(),
    "near_valid_documents": near_valid_documents(),
}


def run_for(strategy: st.SearchStrategy[str], seconds: float, chunk: int = 25) -> int:
    """Run ``check`` over fresh examples until ``seconds`` pass; returns how many ran.

    A failing input is reported as found, not shrunk: shrinking a text can take
    longer than the whole budget (minutes), and the input is printed in full.
    """
    deadline = time.monotonic() + seconds
    count = 0

    @settings(
        max_examples=chunk,
        deadline=None,
        database=None,
        phases=(Phase.explicit, Phase.generate),
        suppress_health_check=list(HealthCheck),
    )
    @given(text=strategy)
    def fuzz(text: str) -> None:
        nonlocal count
        count += 1
        check(text)

    runner: Callable[[], None] = fuzz
    while time.monotonic() < deadline:
        runner()
    return count


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=600.0, help="per target")
    parser.add_argument("--target", choices=sorted(TARGETS), action="append")
    args = parser.parse_args()
    for name in args.target or sorted(TARGETS):
        started = time.monotonic()
        count = run_for(TARGETS[name], args.seconds)
        print(f"{name}: {count} inputs in {time.monotonic() - started:.0f} s, no crash")


if __name__ == "__main__":
    main()
