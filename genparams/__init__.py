"""genparams: typed, validated ROS 2 parameters from a YAML schema.

This package root stays import-light: generated modules import
``genparams.runtime``, which must not pull in the code generator's
dependencies (jinja2, jsonschema, yaml). The names below load on first use.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from genparams._version import __version__

if TYPE_CHECKING:
    from genparams.api import generate, load_schema
    from genparams.errors import (
        CommandError,
        GenparamsError,
        ParameterProblem,
        Problem,
        render_problem,
    )
    from genparams.runtime.core.errors import (
        ParameterDeclarationError,
        RemoteParameterError,
        RemoteSetError,
    )
    from genparams.schema.errors import SchemaError, SchemaProblem

_API = ("generate", "load_schema")
_ERRORS = ("CommandError", "GenparamsError", "ParameterProblem", "Problem", "render_problem")
_RUNTIME_ERRORS = ("ParameterDeclarationError", "RemoteParameterError", "RemoteSetError")
_SCHEMA_ERRORS = ("SchemaError", "SchemaProblem")

__all__ = [
    "CommandError",
    "GenparamsError",
    "ParameterDeclarationError",
    "ParameterProblem",
    "Problem",
    "RemoteParameterError",
    "RemoteSetError",
    "SchemaError",
    "SchemaProblem",
    "__version__",
    "generate",
    "load_schema",
    "render_problem",
]


def __getattr__(name: str) -> Any:
    if name in _API:
        from genparams import api

        return getattr(api, name)
    if name in _ERRORS:
        from genparams import errors

        return getattr(errors, name)
    if name in _RUNTIME_ERRORS:
        from genparams.runtime.core import errors as runtime_errors

        return getattr(runtime_errors, name)
    if name in _SCHEMA_ERRORS:
        from genparams.schema import errors as schema_errors

        return getattr(schema_errors, name)
    raise AttributeError(name)
