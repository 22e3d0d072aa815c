"""Where a package's share folder is: ``--package-path PKG=DIR`` first, then the ament
index of every prefix of ``AMENT_PREFIX_PATH``, as ``FindPackageShare`` looks it up."""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

INDEX = Path("share") / "ament_index" / "resource_index" / "packages"


@dataclass(frozen=True)
class Packages:
    given: Mapping[str, Path] = field(default_factory=dict)  # --package-path PKG=DIR
    prefixes: tuple[Path, ...] = ()

    @classmethod
    def from_environment(cls, given: Mapping[str, Path]) -> Packages:
        text = os.environ.get("AMENT_PREFIX_PATH", "")
        return cls(dict(given), tuple(Path(p) for p in text.split(os.pathsep) if p))

    def share(self, package: str) -> Path | None:
        """The package's share folder, or None when no index knows it."""
        if package in self.given:
            return self.given[package]
        for prefix in self.prefixes:
            if (prefix / INDEX / package).is_file():
                return prefix / "share" / package
        return None


def parse_package_path(text: str) -> tuple[str, Path]:
    """``PKG=DIR``; raises ValueError."""
    package, sep, folder = text.partition("=")
    if not sep or not package or not folder:
        raise ValueError(f"expected PKG=DIR, got {text!r}")
    return package, Path(folder)
