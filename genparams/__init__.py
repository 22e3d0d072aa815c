"""genparams: typed, validated ROS 2 parameters generated from a YAML schema.

This package root stays import-light: generated modules import
``genparams.runtime``, which must not pull in the code generator's
dependencies (jinja2, jsonschema, yaml).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

if TYPE_CHECKING:
    from genparams.api import generate, load_schema

__all__ = ["__version__", "generate", "load_schema"]


def __getattr__(name: str) -> Any:
    if name in ("generate", "load_schema"):
        from genparams import api

        return getattr(api, name)
    raise AttributeError(name)
