"""Deprecated since 0.2.0, removed in 0.3.0: the runtime's errors moved to
``genparams.runtime.core.errors`` when the runtime was split into sub-packages.

Import them from ``genparams.runtime`` (or ``GenparamsError`` from ``genparams``), the
public paths (docs/public-api.md). Each name read from here still works and warns once
per place with a ``DeprecationWarning`` naming the path to use.
"""

from __future__ import annotations

import warnings
from typing import Any

from genparams.runtime.core import errors as _errors

_MOVED_TO = {
    "DetachedSnapshotError": "genparams.runtime",
    "GenparamsError": "genparams",
    "ParameterDeclarationError": "genparams.runtime",
    "RemoteParameterError": "genparams.runtime",
    "RemoteSetError": "genparams.runtime",
}

__all__ = sorted(_MOVED_TO)


def __getattr__(name: str) -> Any:
    if name not in _MOVED_TO:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    warnings.warn(
        f"genparams.runtime.errors is deprecated and goes in 0.3.0: "
        f"import {name} from {_MOVED_TO[name]}",
        DeprecationWarning,
        stacklevel=2,
    )
    return getattr(_errors, name)
