"""The runtime's view of a schema parameter, built from the model.

Generated modules hand the runtime a ``ParamSpec`` per parameter; the offline
tools (docs, check-params) build the very same spec from the model and compile
it with the runtime's ``compile_param``, so a value is judged, and a rule is
worded, exactly as it is on a robot.
"""

from __future__ import annotations

from genparams.runtime.core.param_spec import ParamSpec
from genparams.runtime.core.spec import (
    CompiledParam,
    CompiledSchema,
    RuleSpec,
    SchemaSpec,
    compile_schema,
)
from genparams.schema.model import Parameter, Schema


def param_spec(parameter: Parameter) -> ParamSpec:
    """The ``ParamSpec`` a generated module holds for ``parameter``."""
    return parameter.runtime_spec


def compiled_param(parameter: Parameter) -> CompiledParam:
    return parameter.compiled


def compiled_schema(schema: Schema) -> CompiledSchema:
    """What the runtime compiles from a generated module's spec: fixed parameters, the
    templates of mapped groups (with their maps), old names and rules. No classes: no values."""
    spec = SchemaSpec(
        schema.name,
        tuple(param_spec(p) for p in schema.parameters),
        groups={},
        maps=dict(schema.maps),
        rules=tuple(RuleSpec(r.name, r.check, **dict(r.spec_options)) for r in schema.rules),
    )
    return compile_schema(spec)


def compiled_params(schema: Schema) -> dict[str, CompiledParam]:
    """Every parameter and template by ROS name, with the checks a node runs on it (a
    for_each parameter's items must name entries, beyond its own validators)."""
    return {p.ros_name: p.compiled for p in schema.parameters}
