"""The CMake package of genparams: ``find_package(genparams)`` and ``genparams_generate_python``.

``python -m genparams.cmake`` (or ``genparams cmake-dir``) prints the folder to put in
``CMAKE_PREFIX_PATH`` or ``genparams_DIR``.
"""

from __future__ import annotations

from pathlib import Path


def cmake_dir() -> Path:
    """The folder holding genparamsConfig.cmake."""
    return Path(__file__).resolve().parent
