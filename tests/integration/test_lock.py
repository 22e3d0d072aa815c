"""requirements/dev.txt, the hashed lock `make venv` installs, covers pyproject.toml.

Every requirement of the package, of every extra and of the build group is pinned there,
at a version its range admits, with hashes: editing pyproject.toml without `make lock`
fails here, offline.
"""

from __future__ import annotations

import re
import tomllib

from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

from tests.support import ROOT

LOCK = ROOT / "requirements" / "dev.txt"
PIN = re.compile(r"^([A-Za-z0-9][A-Za-z0-9._-]*)==(\S+?)(?:\s*;[^\\]*)?\s*\\?$", re.MULTILINE)


def pyproject_requirements() -> list[Requirement]:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())
    listed = list(project["project"]["dependencies"])
    for extra in project["project"]["optional-dependencies"].values():
        listed += extra
    listed += project["dependency-groups"]["build"]
    own = canonicalize_name(project["project"]["name"])
    return [r for r in map(Requirement, listed) if canonicalize_name(r.name) != own]


def locked_versions() -> dict[str, list[str]]:
    pins: dict[str, list[str]] = {}
    for name, version in PIN.findall(LOCK.read_text()):
        pins.setdefault(canonicalize_name(name), []).append(version)
    return pins


def test_every_requirement_is_pinned_in_range() -> None:
    pins = locked_versions()
    unpinned = [
        str(requirement)
        for requirement in pyproject_requirements()
        if not any(
            requirement.specifier.contains(version, prereleases=True)
            for version in pins.get(canonicalize_name(requirement.name), [])
        )
    ]
    assert unpinned == []


def test_every_pin_carries_hashes() -> None:
    entries = re.split(r"\n(?=[A-Za-z0-9])", LOCK.read_text())
    pinned = [entry for entry in entries if "==" in entry.split("\n", 1)[0]]
    assert len(pinned) > 100
    assert [entry.split()[0] for entry in pinned if "--hash=sha256:" not in entry] == []
