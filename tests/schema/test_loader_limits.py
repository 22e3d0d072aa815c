"""Each size and depth limit of the YAML loader is reachable: each refuses some input."""

from __future__ import annotations

import pytest

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
