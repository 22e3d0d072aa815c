"""The runtime's view of a schema parameter, built from the model.

Generated modules hand the runtime a ``ParamSpec`` per parameter; the offline
tools (docs, check-params) build the very same spec from the model and compile
it with the runtime's ``compile_param``, so a value is judged, and a rule is
worded, exactly as it is on a robot.
"""

from __future__ import annotations

from genparams.model import Parameter
from genparams.runtime.spec import CompiledParam, ParamSpec, compile_param


def param_spec(parameter: Parameter) -> ParamSpec:
    """The ``ParamSpec`` a generated module holds for ``parameter``."""
    return ParamSpec(parameter.ros_name, parameter.type.name, **dict(parameter.spec_options))


def compiled_param(parameter: Parameter) -> CompiledParam:
    return compile_param(param_spec(parameter))
