"""How close a misspelt name must be to be offered: 0.6 of difflib's ratio for a whole
name, a stricter 0.75 for a leaf alone (short words match by chance)."""

from __future__ import annotations

import pytest

from genparams.runtime.core.suggest import closest, did_you_mean_name

NAMES = ["control.gain", "camera.fps"]


@pytest.mark.parametrize(
    ("name", "hint"),
    [
        ("deep.ns.gian", " (did you mean 'control.gain'?)"),  # leaf ratio 0.75: offered
        ("deep.ns.gn", ""),  # leaf ratio 0.67: below the leaf cutoff
        ("deep.ns.fp", " (did you mean 'camera.fps'?)"),  # leaf ratio 0.8
    ],
)
def test_a_leaf_alone_must_be_closer(name: str, hint: str) -> None:
    assert did_you_mean_name(name, NAMES) == hint


def test_the_cutoff_is_the_one_given() -> None:
    assert closest("gn", ["gain"]) == "gain"  # 0.67 passes the default 0.6
    assert closest("gn", ["gain"], cutoff=0.75) is None
    assert closest("gn", ["gain"], cutoff=0.6) == "gain"
