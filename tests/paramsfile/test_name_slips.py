"""How far apart two names are, and which sections that makes near misses of a node."""

from __future__ import annotations

import pytest

from genparams.paramsfile.node_sections import edit_distance, near_miss


@pytest.mark.parametrize(
    ("one", "other", "edits"),
    [
        ("", "", 0),
        ("", "abc", 3),  # three inserts
        ("abc", "", 3),  # three deletes
        ("abc", "abc", 0),
        ("ab", "a", 1),  # a delete at the end
        ("a", "ab", 1),  # an insert at the end
        ("abc", "abd", 1),  # a replace
        ("ab", "ba", 1),  # a swap of the first two letters
        ("camera", "cmaera", 1),  # a swap inside
        ("aaa", "a", 2),
        ("kitten", "sitting", 3),
        ("ca", "abc", 3),  # a swapped pair is not edited again
        ("odometry", "odmoetyr", 2),  # two swaps
    ],
)
def test_edit_distance_counts_inserts_deletes_replaces_and_swaps(
    one: str, other: str, edits: int
) -> None:
    assert edit_distance(one, other) == edits
    assert edit_distance(other, one) == edits


@pytest.mark.parametrize(
    ("section", "node", "reason"),
    [
        (
            "/camera",
            "/site/robot/camera",
            "same node name in namespace /, but /site/robot/camera runs in /site/robot",
        ),
        ("/robot/camera1", "/robot/cameras", "node name 'camera1' is close to 'cameras': a typo?"),
        # eight letters allow two slips
        (
            "/robot/odmoetyr",
            "/robot/odometry",
            "node name 'odmoetyr' is close to 'odometry': a typo?",
        ),
    ],
)
def test_near_miss_names_the_slip(section: str, node: str, reason: str) -> None:
    assert near_miss(section, node) == reason


@pytest.mark.parametrize(
    ("section", "node"),
    [
        ("/*", "/a"),  # a pattern for every node in / is not a slip of one name
        ("/robot/*", "/robot/a"),
        ("/lidar", "/robot/camera"),  # another name in another namespace
        ("/robot/odmoetyrx", "/robot/odometry"),  # three slips
        ("/robot/cmaeras", "/robot/camera"),  # two slips in a short name
    ],
)
def test_other_sections_are_not_near_misses(section: str, node: str) -> None:
    assert near_miss(section, node) is None
