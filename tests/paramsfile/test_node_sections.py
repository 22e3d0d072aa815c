"""Near misses: sections meant for a node that miss it, told from other nodes' sections."""

from __future__ import annotations

import pytest

from genparams.paramsfile.node_sections import near_miss


@pytest.mark.parametrize(
    ("section", "node", "why"),
    [
        ("/camera_driver", "/robot/camera_driver", "same node name in namespace /"),
        ("/robt_1/cm", "/robot_1/cm", "same node name in namespace /robt_1"),
        ("/robot/camera_drver", "/robot/camera_driver", "node name 'camera_drver' is close"),
        ("/robot/camera_drvier", "/robot/camera_driver", "node name 'camera_drvier' is close"),
        ("/robot_2/camera_drvier", "/*/camera_driver", "node name 'camera_drvier' is close"),
    ],
)
def test_a_typo_is_a_near_miss(section: str, node: str, why: str) -> None:
    reason = near_miss(section, node)
    assert reason is not None and reason.startswith(why)


@pytest.mark.parametrize(
    ("section", "node"),
    [
        ("/robot_2/cm", "/robot_1/cm"),  # the other robot's copy
        ("/joint2_controller", "/joint1_controller"),  # numbered siblings
        ("/**/lidar", "/robot/camera"),  # a pattern for other nodes
        ("/robot/lidar", "/robot/camera"),
    ],
)
def test_other_nodes_sections_are_not_near_misses(section: str, node: str) -> None:
    assert near_miss(section, node) is None
