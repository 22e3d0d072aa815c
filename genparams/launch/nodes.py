"""A node found in any of the three formats, recorded the same way: its full name from the
namespace pushed around it, its parameters in the order launch passes them."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import Any

from genparams.launch.model import InlineParameters, LaunchNode, ParamsFileRef, Unknown
from genparams.launch.scope import Scope, Value, join_namespace, text
from genparams.paramsfile.ros_yaml import NoValue, ros_scalar
from genparams.schema.errors import Location


class Substituted(str):
    """Text a substitution made (``LaunchConfiguration``, ``$(var x)``): launch reads it as
    YAML before handing it to the node, so ``'true'`` becomes a bool, ``'2.0'`` a double."""

    __slots__ = ()


def add_node(
    scope: Scope,
    kind: str,
    fields: dict[str, Value],
    parameters: Sequence[Value],
    location: Location,
    container: str = "",
) -> LaunchNode | None:
    """Record a node; its name and namespace must be known, or it is reported instead."""
    values = {key: text(fields.get(key, "")) for key in ("package", "executable", "name")}
    namespace = text(fields.get("namespace", ""))
    for key, value in [*values.items(), ("namespace", namespace)]:
        if isinstance(value, Unknown):
            scope.unknown(f"the {key} of a {kind.replace('_', ' ')}", value.location)
            return None
    if scope.namespace.startswith("/<launch-time>"):
        scope.unknown(f"the namespace of node {values['name']}", location)
        return None
    sources: list[InlineParameters | ParamsFileRef] = []
    if scope.set_parameters:
        sources.append(InlineParameters(scope.set_parameters))
    for item in parameters:
        source = parameter_source(item, scope, location)
        if source is not None:
            sources.append(source)
    node = LaunchNode(
        kind,
        str(values["package"]),
        str(values["executable"]),
        str(values["name"]),
        join_namespace(scope.namespace, str(namespace)),
        tuple(sources),
        location,
        container,
    )
    if not node.name:
        scope.unknown(
            f"the name of the {kind.replace('_', ' ')} {node.package}/{node.executable} "
            "(the launch file does not name it: its code does)",
            location,
        )
    scope.add(node)
    return node


def parameter_source(
    item: Value, scope: Scope, location: Location
) -> InlineParameters | ParamsFileRef | None:
    if isinstance(item, InlineParameters):
        return item
    if isinstance(item, dict):
        return InlineParameters(tuple(flatten(item, location, scope)))
    path = text(item)
    if isinstance(path, Unknown):
        scope.unknown("a params file", path.location)
        return None
    return ParamsFileRef(str(path), location)


def flatten(
    values: dict[Any, Value], location: Location, scope: Scope, head: str = ""
) -> Iterator[tuple[str, Any, Location]]:
    """Nested dicts as dotted names (launch_ros's rule), each value as the node gets it."""
    for key, value in values.items():
        name = f"{head}{text(key)}"
        if isinstance(value, dict):
            yield from flatten(value, location, scope, name + ".")
            continue
        read = parameter_value(value)
        if isinstance(read, Unknown):
            scope.unknown(f"parameter {name}", read.location)
            continue
        yield name, read, location


def _scalar(written: str) -> Any:
    quoted = len(written) > 1 and written[0] == written[-1] and written[0] in "'\""
    read = ros_scalar(written[1:-1] if quoted else written, written[0] if quoted else None)
    return None if isinstance(read, NoValue) else read


def parameter_value(value: Value) -> Any:
    """What launch hands the node for one parameter value."""
    if isinstance(value, Unknown):
        return value
    if isinstance(value, Substituted):
        written = str(value).strip()
        if written.startswith("[") and written.endswith("]"):  # launch reads it as YAML
            items = [item.strip() for item in written[1:-1].split(",") if item.strip()]
            return [_scalar(item) for item in items] or None
        return _scalar(written)
    if isinstance(value, list | tuple):
        if any(isinstance(item, Unknown) for item in value):
            return next(item for item in value if isinstance(item, Unknown))
        if value and all(isinstance(item, Substituted) for item in value):
            return text(list(value))  # a list of substitutions is one text
        return [parameter_value(item) for item in value]
    return value
