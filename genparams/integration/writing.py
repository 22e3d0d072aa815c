"""Writing generated text: all outputs computed first, then each replaced atomically."""

from __future__ import annotations

import difflib
import os
import stat
import tempfile
from collections.abc import Mapping
from pathlib import Path


def write_all(outputs: Mapping[Path, str]) -> None:
    """Write every output, or none: each is written in full to a temporary file beside its
    path first, and only when all are written does each replace its path (atomically)."""
    staged: list[tuple[str, Path]] = []
    try:
        for path, text in outputs.items():
            path.parent.mkdir(parents=True, exist_ok=True)
            fd, temp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
            staged.append((temp, path))
            with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as handle:
                handle.write(text)
            # mkstemp makes the file private (0600); installs copy that mode along.
            os.chmod(temp, _file_mode(path))
        for temp, path in staged:
            os.replace(temp, path)
    finally:  # a temporary file left is one that never replaced its path
        for temp, _ in staged:
            Path(temp).unlink(missing_ok=True)


def _file_mode(path: Path) -> int:
    """The mode a rewritten file keeps, or what a plain ``open`` would give a new one."""
    try:
        return stat.S_IMODE(path.stat().st_mode)
    except FileNotFoundError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


def stale_diffs(outputs: Mapping[Path, str]) -> list[str]:
    """A unified diff per output whose file on disk differs (or is missing)."""
    diffs = []
    for path, text in outputs.items():
        try:
            current = path.read_text(encoding="utf-8")
        except FileNotFoundError:
            diffs.append(f"{path}: missing (run genparams generate)\n")
            continue
        if current != text:
            diffs.append(
                "".join(
                    difflib.unified_diff(
                        current.splitlines(keepends=True),
                        text.splitlines(keepends=True),
                        fromfile=f"{path} (on disk)",
                        tofile=f"{path} (generated)",
                    )
                )
            )
    return diffs
