"""Shared by the tune and audit tests: demo nodes in their own processes, polling, a browser."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from tests.support import ROOT

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


def unique(stem: str) -> str:
    """Node names no other test run on this domain uses."""
    return f"{stem}_{os.getpid()}"


@contextmanager
def demo_nodes(
    *specs: str, ros_args: tuple[str, ...] = (), module: str = "tests.tune.demo_nodes"
) -> Iterator[subprocess.Popen[str]]:
    """``python -m MODULE NAME:KIND...`` until the block ends (MODULE prints "ready")."""
    command = [sys.executable, "-m", module, *specs]
    if ros_args:
        command += ["--", *ros_args]
    process = subprocess.Popen(
        command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    try:
        assert process.stdout is not None
        line = process.stdout.readline()  # blocks until the nodes are declared
        if line.strip() != "ready":
            process.kill()
            raise RuntimeError(f"demo nodes failed: {line}{process.communicate()[1]}")
        yield process
    finally:
        process.terminate()
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


def eventually(probe: Callable[[], Any], timeout: float = 10.0, interval: float = 0.05) -> Any:
    """Poll ``probe`` until it returns a true value; its last value on timeout fails."""
    deadline = time.monotonic() + timeout
    while True:
        value = probe()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"condition not met within {timeout} s (last: {value!r})")
        time.sleep(interval)
