"""The launch actions a ``.launch.py`` puts in its description, followed as launch would
perform them: nodes, composable nodes, groups, namespace pushes, includes, ``SetParameter``."""

from __future__ import annotations

import ast
from pathlib import Path

from genparams.launch.model import Unknown
from genparams.launch.nodes import add_node, parameter_value
from genparams.launch.scope import Scope, Value, text
from genparams.schema.errors import Location

NODE_KINDS = {"Node": "node", "LifecycleNode": "lifecycle_node"}
NAMESPACE_PUSHES = ("PushRosNamespace", "PushROSNamespace")


class Action:
    """A launch action the reader follows when it is returned in the description."""

    def __init__(self, kind: str, call: ast.Call, values: dict[str, Value]) -> None:
        self.kind = kind
        self.call = call
        self.values = values


def where_of(node: ast.AST, scope: Scope) -> Location:
    return scope.at(getattr(node, "lineno", 1), getattr(node, "col_offset", 0) + 1)


def perform(action: Value, scope: Scope) -> Scope:
    """Follow one action of the description; a namespace push changes what follows."""
    if not isinstance(action, Action):
        if not isinstance(action, Unknown):
            scope.unknown("an entity of the description", scope.at(1, 1))
        return scope
    values, where = action.values, where_of(action.call, scope)
    positional = values.get("__args__", [])
    condition = values.get("condition", True)
    if isinstance(condition, Unknown):
        return scope  # reported where the condition was read
    if condition is False:
        return scope
    kind = action.kind
    if kind in NAMESPACE_PUSHES:
        pushed = values.get("namespace", positional[0] if positional else "")
        return scope.pushed(text(pushed), where)
    if kind == "SetLaunchConfiguration":
        key = text(values.get("name", positional[0] if positional else ""))
        if isinstance(key, str):
            scope.arguments[key] = values.get("value", positional[1] if len(positional) > 1 else "")
        return scope
    if kind == "SetParameter":
        name = text(values.get("name", positional[0] if positional else ""))
        value = parameter_value(values.get("value", positional[1] if len(positional) > 1 else ""))
        if isinstance(name, Unknown) or isinstance(value, Unknown):
            scope.unknown("a SetParameter", where)
            return scope
        return scope.with_parameter(name, value, where)
    if kind == "OpaqueFunction":
        scope.unknown("what an OpaqueFunction starts", where)
        return scope
    if kind == "DeclareLaunchArgument":
        return scope
    if kind in NODE_KINDS:
        add_node(
            scope, NODE_KINDS[kind], _fields(values), flat(values.get("parameters", [])), where
        )
        return scope
    if kind == "ComposableNodeContainer":
        container = add_node(
            scope, "container", _fields(values), flat(values.get("parameters", [])), where
        )
        composables(
            values.get("composable_node_descriptions", []),
            scope,
            container.full_name if container else "",
        )
        return scope
    if kind == "LoadComposableNodes":
        target = text(values.get("target_container", ""))
        composables(
            values.get("composable_node_descriptions", []),
            scope,
            target if isinstance(target, str) else "",
        )
        return scope
    if kind == "GroupAction":
        inner = scope.pushed("", where)  # a group scopes the namespaces pushed inside it
        for item in flat(values.get("actions", positional[0] if positional else [])):
            inner = perform(item, inner)
        return scope
    if kind == "IncludeLaunchDescription":
        source = text(values.get("launch_description_source", positional[0] if positional else ""))
        if isinstance(source, Unknown):
            scope.unknown("the launch file an include reads", where)
            return scope
        arguments = dict(scope.arguments)
        for pair in _flat_pairs(values.get("launch_arguments", [])):
            arguments[str(text(pair[0]))] = pair[1]
        scope.include(Path(source), arguments, scope, where)
        return scope
    return scope


def composables(descriptions: Value, scope: Scope, container: str) -> None:
    for item in flat(descriptions):
        if isinstance(item, Action) and item.kind == "ComposableNode":
            fields = _fields(item.values)
            fields["executable"] = item.values.get("plugin", "")
            add_node(scope, "composable_node", fields, flat(item.values.get("parameters", [])),
                     where_of(item.call, scope), container)  # fmt: skip
        elif not isinstance(item, Unknown):
            scope.unknown("a composable node", scope.at(1, 1))


def flat(value: Value) -> list[Value]:
    if isinstance(value, list | tuple):
        return [item for part in value for item in flat(part)]
    return [value]


def _flat_pairs(value: Value) -> list[tuple[Value, Value]]:
    if isinstance(value, dict):
        return list(value.items())
    if isinstance(value, list | tuple):
        return [tuple(p) for p in value if isinstance(p, list | tuple) and len(p) == 2]
    return []


def _fields(values: dict[str, Value]) -> dict[str, Value]:
    return {key: values.get(key, "") for key in ("package", "executable", "name", "namespace")}
