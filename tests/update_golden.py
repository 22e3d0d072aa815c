"""Rewrite every golden file after an intended change of output: python -m tests.update_golden"""

from __future__ import annotations

from tests.golden import update

if __name__ == "__main__":
    update()
