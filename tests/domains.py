"""A ROS domain for each test run on this machine that no other run shares.

Test nodes are named per process (``served_1``, ``node_3``): two runs in one domain would
answer each other's service calls. A run holds a lock file for its domain until it exits.
"""

from __future__ import annotations

import fcntl
import os
import random
import tempfile

# Test runs take 1-100; people's own scripts use 101-199 and mutation workers 200-231.
TEST_DOMAINS = range(1, 101)
_held: list[int] = []  # the lock's descriptor, open for as long as the process runs


def hold_free_domain(domains: range = TEST_DOMAINS) -> int:
    """The first domain (from a random start) that no other process holds; now held here.
    With every domain held, a random one."""
    start = random.SystemRandom().randrange(len(domains))
    for offset in range(len(domains)):
        domain = domains[(start + offset) % len(domains)]
        path = os.path.join(tempfile.gettempdir(), f"genparams-test-domain-{domain}.lock")
        try:
            descriptor = os.open(path, os.O_CREAT | os.O_RDWR, 0o666)
        except OSError:  # another user's lock file
            continue
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(descriptor)
            continue
        _held.append(descriptor)
        return domain
    return domains[start]
