"""Shared by the live-graph tests: misbehaving nodes in their own process."""

from __future__ import annotations

import subprocess
from contextlib import AbstractContextManager

from tests.node_process import node_process


def hostile_nodes(*specs: str) -> AbstractContextManager[subprocess.Popen[str]]:
    """The nodes of tests.live.hostile_nodes (NAME:KIND[:ARG]...) until the block ends."""
    return node_process("tests.live.hostile_nodes", *specs)
