"""Locate the shipped schemas/ and templates/ folders (inside the wheel, or the checkout)."""

from __future__ import annotations

from pathlib import Path

_PACKAGE = Path(__file__).resolve().parent.parent


def resource_dir(name: str) -> Path:
    """``schemas`` or ``templates``: packaged copy first, then the repository's top level."""
    for candidate in (_PACKAGE / name, _PACKAGE.parent / name):
        if candidate.is_dir():
            return candidate
    raise FileNotFoundError(f"genparams resource folder {name!r} is missing from the install")
