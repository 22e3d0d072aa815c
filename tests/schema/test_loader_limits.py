"""Each size and depth limit of the YAML loader is reachable: each refuses some input."""

from __future__ import annotations

import pytest
import yaml

from genparams.paramsfile.params_reader import read_params_file
from genparams.schema import loader
from genparams.schema.errors import SchemaError
from genparams.schema.loader import MAX_DEPTH, MAX_NODES, compose_yaml


def _refusal(text: str) -> str:
    with pytest.raises(SchemaError) as raised:
        compose_yaml(text, "f.yaml")
    return str(raised.value)


def test_deep_text_is_refused_before_composing() -> None:
    depth = MAX_DEPTH + 1
    assert f"nested deeper than {MAX_DEPTH} levels" in _refusal("[" * depth + "]" * depth)


def test_an_alias_placed_deep_is_refused_while_building() -> None:
    # Each part of the text nests 55 deep at most; the alias expands it to 105.
    half = 50
    text = f"k: [[[[[&a {'[' * half}1{']' * half}]]]]]\nj: {'[' * half}*a{']' * half}\n"
    assert f": nested deeper than {MAX_DEPTH}" in _refusal(text)


def test_an_alias_bomb_is_refused_before_building() -> None:
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x, x]"]
    for level in range(1, 8):
        below = f"*a{level - 1}"
        lines.append(f"a{level}: &a{level} [{', '.join([below] * 10)}]")
    assert f"more than {MAX_NODES} values" in _refusal("\n".join(lines))


# Each too deep at the place given (line, column): flow brackets far past any parser's own
# limit, block mappings and sequences by indentation, and both mixed.
DEEP = {
    "flow sequences": ("x: " + "[" * 100_000 + "]" * 100_000, (1, 67)),
    "flow mappings": ("x: " + "{a: " * 100_000 + "1" + "}" * 100_000, (1, 256)),
    "block mappings": (
        "".join(" " * i + "a:\n" for i in range(1_000)) + " " * 1_000 + "a: 1",
        (65, 65),
    ),
    "block sequences": ("- " * 100_000 + "x", (1, 129)),
    "block then flow": (
        "".join(" " * i + "a:\n" for i in range(60)) + " " * 60 + "b: " + "[" * 10_000,
        (61, 67),
    ),
}
# What cannot open a collection, however many brackets it holds.
BRACKETS = "[{" * 100
FLAT = {
    "quoted": f"a: '{BRACKETS}'\nb: \"{BRACKETS}\"\n",
    "plain": f"a: x{BRACKETS}\n  and on {BRACKETS}\nb: [it's, a#b, c:d]\n",
    "block scalars": f"a: |\n  {BRACKETS}\n\n  {BRACKETS}\nb: >-\n    {BRACKETS}\n",
    "comments": f"a: 1 # {BRACKETS}\n# {BRACKETS}\nb: [1, # {BRACKETS}\n  2]\n",
}
LOADERS = [yaml.SafeLoader] + ([yaml.CSafeLoader] if hasattr(yaml, "CSafeLoader") else [])


@pytest.mark.parametrize("base", LOADERS, ids=lambda base: base.__name__)
@pytest.mark.parametrize(("text", "place"), DEEP.values(), ids=list(DEEP))
def test_depth_is_refused_the_same_under_every_yaml_parser(
    text: str, place: tuple[int, int], base: type[yaml.SafeLoader], monkeypatch: pytest.MonkeyPatch
) -> None:
    """genparams reads the depth from the text: neither the message nor the place depends on
    the parser (the pure-Python one, or libyaml with or without a depth limit of its own)."""
    monkeypatch.setattr(loader, "_SafeLoader", base)
    line, column = place
    expected = f"f.yaml:{line}:{column}: nested deeper than {MAX_DEPTH} levels"
    assert _refusal(text) == expected


@pytest.mark.parametrize("text", FLAT.values(), ids=list(FLAT))
def test_brackets_inside_scalars_and_comments_are_not_depth(text: str) -> None:
    document, problems = compose_yaml(text, "f.yaml")
    assert problems == []
    assert document.data == yaml.safe_load(text)


def test_a_deep_params_file_is_one_located_problem() -> None:
    text = "/**:\n  ros__parameters:\n    x: " + "[" * 100_000 + "\n"
    problems = read_params_file(text, "p.yaml").problems
    assert [str(p) for p in problems] == [f"p.yaml:3:69: nested deeper than {MAX_DEPTH} levels"]
