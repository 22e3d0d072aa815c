"""Shared fixtures. DDS stays on loopback, in a domain of its own per run."""

from __future__ import annotations

import os

from tests.domains import hold_free_domain

# Before rclpy is imported anywhere: discovery must never leave this machine, and no other
# test run on it shares the domain.
os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
if "ROS_DOMAIN_ID" not in os.environ:
    os.environ["ROS_DOMAIN_ID"] = str(hold_free_domain())

from collections.abc import Iterator

import pytest

from tests import budget  # noqa: F401  (registers and loads the Hypothesis profile)
from tests.support import RosHarness


@pytest.fixture(scope="session")
def ros_harness() -> Iterator[RosHarness]:
    harness = RosHarness()
    try:
        yield harness
    finally:
        harness.close()


@pytest.fixture
def ros(ros_harness: RosHarness) -> Iterator[RosHarness]:
    """Per-test access to rclpy: nodes made here are destroyed after the test."""
    try:
        yield ros_harness
    finally:
        ros_harness.destroy_test_nodes()
