"""Read every value of a declared class three ways: cfg, the node, the parameter service.

Values are compared exactly: same Python type, NaN equals NaN, -0.0 differs
from 0.0, arrays as tuples and byte arrays as bytes (the typed view's form).
"""

from __future__ import annotations

import math
import types
from typing import Any

from rclpy.node import Node

from genparams.runtime import Params
from genparams.runtime.core.naming import join_prefix
from genparams.runtime.core.spec import compile_schema
from genparams.runtime.core.tree import get_path
from genparams.runtime.core.types import TYPES, ParamType
from tests.support import RosHarness, ServiceClient


def params_class(module: types.ModuleType) -> type[Params]:
    """The generated top-level class of a module."""
    (cls,) = (
        value
        for value in vars(module).values()
        if isinstance(value, type) and issubclass(value, Params) and value is not Params
    )
    return cls


def same(a: Any, b: Any) -> bool:
    """Exact equality of typed-view values (see the module docstring)."""
    if type(a) is not type(b):
        return False
    if isinstance(a, float):
        if math.isnan(a) or math.isnan(b):
            return math.isnan(a) and math.isnan(b)
        return a == b and math.copysign(1.0, a) == math.copysign(1.0, b)
    if isinstance(a, tuple):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b, strict=True))
    return bool(a == b)


def read_back(
    ros: RosHarness,
    node: Node,
    cfg: Params,
    prefix: str = "",
    client: ServiceClient | None = None,
) -> dict[str, tuple[Any, Any, Any]]:
    """Relative name -> (through cfg, through node.get_parameter, through the service).

    Entries of mapped groups are read too: the declared class knows which it declared.
    """
    binding = getattr(cfg, "_binding", None)
    if binding is not None:
        parameters = {param.name: param for param in binding.owned.values()}
    else:
        parameters = dict(compile_schema(type(cfg)._SPEC).parameters)
    names = list(parameters)
    full = [join_prefix(prefix, name) for name in names]
    client = client or ros.client(node)
    served = client.get(*full) if full else []
    if len(served) != len(full):
        # The service answers nothing when any name is not set (an optional parameter):
        # ask name by name, an empty answer meaning "not set".
        served = [next(iter(client.get(name)), None) for name in full]
    out = {}
    for name, full_name, service_value in zip(names, full, served, strict=True):
        param = parameters[name]
        param_type = TYPES[param.spec.type]

        def typed(value: Any, param_type: ParamType = param_type, param: Any = param) -> Any:
            return None if param.spec.optional and value is None else param_type.from_ros(value)

        out[name] = (
            get_path(cfg, param.attribute_path),
            typed(node.get_parameter_or(full_name).value),
            typed(service_value),
        )
    return out


def mismatches(
    seen: dict[str, tuple[Any, Any, Any]], expected: dict[str, Any]
) -> dict[str, tuple[Any, ...]]:
    """Names whose three readings are not all exactly ``expected[name]``."""
    return {
        name: (expected.get(name, "<missing>"), *values)
        for name, values in seen.items()
        if not all(same(value, expected.get(name)) for value in values)
    } | {name: (expected[name], "<not declared>") for name in set(expected) - set(seen)}
