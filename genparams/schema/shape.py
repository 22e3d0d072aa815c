"""Which mappings of a schema's ``parameters:`` tree are parameters, and which namespaces.

A mapping whose ``type:`` holds a type name (or any other value that is not a
mapping) is a parameter. Any other mapping is a namespace, so a ``type:`` key
holding a mapping is a parameter or namespace named ``type``:
``walk: {type: {type: string}}`` is the namespace ``walk`` holding the string
parameter ``type``.
"""

from __future__ import annotations

from typing import Any

TYPE_KEY = "type"


def is_parameter(value: Any) -> bool:
    """Whether ``value``, a node of the ``parameters:`` tree, states one parameter."""
    return isinstance(value, dict) and TYPE_KEY in value and not isinstance(value[TYPE_KEY], dict)


def is_namespace(value: Any) -> bool:
    """Whether ``value``, a node of the ``parameters:`` tree, is a namespace (or open one)."""
    return isinstance(value, dict) and not is_parameter(value)
