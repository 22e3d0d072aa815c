"""Shared by the live-graph tests: misbehaving nodes in their own process, commands run."""

from __future__ import annotations

import subprocess
import sys
from contextlib import AbstractContextManager

from tests.node_process import node_process
from tests.patience import WAIT_S, run_patiently
from tests.support import ROOT


def hostile_nodes(*specs: str) -> AbstractContextManager[subprocess.Popen[str]]:
    """The nodes of tests.live.hostile_nodes (NAME:KIND[:ARG]...) until the block ends."""
    return node_process("tests.live.hostile_nodes", *specs)


def genparams(*args: str) -> subprocess.CompletedProcess[str]:
    """``genparams ARGS`` run to its end, however loaded the machine."""
    return run_patiently([sys.executable, "-m", "genparams", *args], budget_s=2 * WAIT_S, cwd=ROOT)


def audit(*args: str, settle: float = 3.0) -> subprocess.CompletedProcess[str]:
    """``genparams audit`` on named nodes: it waits for each to appear (up to WAIT_S), then
    ``settle`` seconds for schema topics of those that publish none."""
    return genparams("audit", "--settle", f"{settle:g}", "--timeout", f"{WAIT_S:g}", *args)
