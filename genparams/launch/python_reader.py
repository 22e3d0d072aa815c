"""A ``.launch.py`` read from its syntax tree, never run.

``generate_launch_description()`` is followed statement by statement: assignments,
``LaunchDescription([...])``, ``ld.add_action(...)``, ``list.append``/``extend`` and the
return. The launch actions and substitutions of launch and launch_ros are known by name
(``Node``, ``LifecycleNode``, ``ComposableNodeContainer``, ``LoadComposableNodes``,
``ComposableNode``, ``GroupAction``, ``PushRosNamespace``, ``IncludeLaunchDescription``,
``DeclareLaunchArgument``, ``LaunchConfiguration``, ``IfCondition``, ``UnlessCondition``,
``PathJoinSubstitution``, ``FindPackageShare``, ``get_package_share_directory``,
``os.path.join``, ``EnvironmentVariable``, ``TextSubstitution``, ``ParameterFile``);
literals and the module's constants go to the static evaluator of import-rclpy. Anything
else (an ``OpaqueFunction``, a call of another function, a loop) is reported as set at
launch time, with its place.
"""

from __future__ import annotations

import ast
from dataclasses import replace
from typing import Any

from genparams.launch.model import LaunchResult, Unknown
from genparams.launch.nodes import Substituted, add_node, parameter_value
from genparams.launch.scope import (
    Scope,
    Value,
    condition_holds,
    environment,
    package_share,
    path_join,
    text,
)
from genparams.rclpy_import.values import Evaluator, UntranslatableError
from genparams.rclpy_import.values import Scope as ValueScope
from genparams.schema.errors import Location

ENTRY = "generate_launch_description"
NODE_KINDS = {"Node": "node", "LifecycleNode": "lifecycle_node"}
NAMESPACE_PUSHES = ("PushRosNamespace", "PushROSNamespace")


class _Action:
    """A launch action the reader follows when it is returned in the description."""

    def __init__(self, kind: str, call: ast.Call, values: dict[str, Value]) -> None:
        self.kind = kind
        self.call = call
        self.values = values


def read_python_launch(source: str, scope: Scope) -> None:
    try:
        tree = ast.parse(source, filename=str(scope.file))
    except SyntaxError as exc:
        scope.unknown(f"the launch file (not Python: {exc.msg})", scope.at(exc.lineno or 1, 1))
        return
    function = next(
        (n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == ENTRY), None
    )
    if function is None:
        scope.unknown(f"the launch file (no {ENTRY}())", scope.at(1, 1))
        return
    constants = {
        t.id: n.value
        for n in tree.body
        if isinstance(n, ast.Assign)
        for t in n.targets
        if isinstance(t, ast.Name)
    }
    # Arguments first: launch resolves configurations when it runs, after the description
    # is built, so a default may use a variable assigned anywhere in the function. A dry
    # run (its findings dropped) gives the variables; the real run then sees every default.
    dry = _Reader(replace(scope, result=LaunchResult(), arguments=dict(scope.arguments)), constants)
    dry.run(function.body)
    reader = _Reader(scope, constants)
    reader.variables = dry.variables
    reader.declare_arguments(function)
    reader.variables = {}
    for action in reader.run(function.body):
        reader.perform(action, scope)


class _Reader:
    def __init__(self, scope: Scope, constants: dict[str, ast.expr]) -> None:
        self.scope = scope
        self.constants = constants
        self.variables: dict[str, Value] = {}

    def where(self, node: ast.AST) -> Location:
        return self.scope.at(getattr(node, "lineno", 1), getattr(node, "col_offset", 0) + 1)

    def declare_arguments(self, function: ast.FunctionDef) -> None:
        """Every ``DeclareLaunchArgument`` default, before any use: launch resolves
        configurations when it runs, after the description is built."""
        for node in ast.walk(function):
            if isinstance(node, ast.Call) and _called(node) == "DeclareLaunchArgument":
                name = self.literal(_argument(node, 0, "name"))
                if not isinstance(name, str) or name in self.scope.arguments:
                    continue
                default = _argument(node, 1, "default_value")
                if default is not None:
                    self.scope.arguments[name] = self.value(default)
                else:
                    self.scope.arguments[name] = Unknown(
                        f"launch argument {name} (no default, none given)", self.where(node)
                    )

    def run(self, body: list[ast.stmt]) -> list[Value]:
        """The actions the statements put in the description, in order."""
        actions: list[Value] = []
        for statement in body:
            if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
                target = statement.targets[0]
                if isinstance(target, ast.Name):
                    self.variables[target.id] = self.value(statement.value)
                continue
            if isinstance(statement, ast.Return) and statement.value is not None:
                actions.extend(_flat(self.value(statement.value)))
                continue
            if isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Call):
                self.method_call(statement.value, actions)
                continue
            if isinstance(statement, ast.Import | ast.ImportFrom | ast.Pass):
                continue
            self.scope.unknown(
                f"what the statement {ast.unparse(statement)[:50]!r} adds", self.where(statement)
            )
        return actions

    def method_call(self, call: ast.Call, actions: list[Value]) -> None:
        func = call.func
        if isinstance(func, ast.Attribute) and func.attr in ("add_action", "append", "extend"):
            owner = func.value
            items = [self.value(a) for a in call.args]
            if func.attr == "extend":
                items = [i for item in items for i in _flat(item)]
            if isinstance(owner, ast.Name) and isinstance(self.variables.get(owner.id), list):
                self.variables[owner.id].extend(items)
            else:
                actions.extend(items)  # ld.add_action(...): the description itself
            return
        self.scope.unknown(f"what {ast.unparse(call)[:50]!r} does", self.where(call))

    # ---- values ---------------------------------------------------------------------

    def literal(self, node: ast.expr | None) -> Any:
        if node is None:
            return None
        try:
            return Evaluator(ValueScope(module_constants=self.constants)).value(node)
        except UntranslatableError:
            return None

    def value(self, node: ast.expr) -> Value:
        if isinstance(node, ast.Name) and node.id in self.variables:
            return self.variables[node.id]
        if isinstance(node, ast.List | ast.Tuple):
            return [self.value(item) for item in node.elts]
        if isinstance(node, ast.Dict):
            return {
                self.value(k): self.value(v)
                for k, v in zip(node.keys, node.values, strict=True)
                if k is not None
            }
        if isinstance(node, ast.Call):
            return self.call(node)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            left, right = self.value(node.left), self.value(node.right)
            if isinstance(left, list) and isinstance(right, list):
                return left + right
            joined = text([left, right])
            return Substituted(joined) if isinstance(joined, str) else joined
        if isinstance(node, ast.JoinedStr):
            parts = [
                self.value(p.value) if isinstance(p, ast.FormattedValue) else self.value(p)
                for p in node.values
            ]
            joined = text(parts)
            return joined
        try:
            return Evaluator(ValueScope(module_constants=self.constants)).value(node)
        except UntranslatableError as exc:
            return self.scope.unknown(exc.what, self.where(node))

    def call(self, node: ast.Call) -> Value:
        name = _called(node)
        where = self.where(node)

        def argument(index: int, key: str) -> ast.expr | None:
            return _argument(node, index, key)

        if name == "LaunchConfiguration":
            key = self.literal(argument(0, "variable_name"))
            if not isinstance(key, str):
                return self.scope.unknown("a launch configuration's name", where)
            if key not in self.scope.arguments:
                default = argument(1, "default")
                if default is not None:
                    return self.value(default)
                return self.scope.unknown(f"launch configuration {key} (never declared)", where)
            found = self.scope.arguments[key]
            return found if isinstance(found, Unknown) else Substituted(text(found))
        if name in ("FindPackageShare", "FindPackagePrefix"):
            share = package_share(self.value(_required(node, 0, "package")), self.scope, where)
            if name == "FindPackagePrefix" and isinstance(share, str):
                return Substituted(str(_prefix_of(share)))
            return Substituted(share) if isinstance(share, str) else share
        if name == "get_package_share_directory":
            share = package_share(self.value(_required(node, 0, "package_name")), self.scope, where)
            return Substituted(share) if isinstance(share, str) else share
        if name in ("PathJoinSubstitution",):
            joined = path_join(_flat(self.value(_required(node, 0, "substitutions"))))
            return Substituted(joined) if isinstance(joined, str) else joined
        if name == "join" and ast.unparse(node.func) in ("os.path.join", "path.join"):
            joined = path_join([self.value(a) for a in node.args])
            return Substituted(joined) if isinstance(joined, str) else joined
        if name == "TextSubstitution":
            return Substituted(text(self.value(_required(node, 0, "text"))))
        if name == "EnvironmentVariable":
            key = text(self.value(_required(node, 0, "name")))
            default = argument(1, "default_value")
            if isinstance(key, Unknown):
                return key
            found = environment(
                key, None if default is None else self.value(default), self.scope, where
            )
            return found if isinstance(found, Unknown) else Substituted(text(found))
        if name in ("ParameterFile", "ParameterValue"):
            return self.value(
                _required(node, 0, "param_file" if name == "ParameterFile" else "value")
            )
        if name in ("PythonLaunchDescriptionSource", "AnyLaunchDescriptionSource",
                    "XMLLaunchDescriptionSource", "YAMLLaunchDescriptionSource",
                    "FrontendLaunchDescriptionSource"):  # fmt: skip
            return text(self.value(_required(node, 0, "launch_file_path")))
        if name in ("IfCondition", "UnlessCondition"):
            holds = condition_holds(
                self.value(_required(node, 0, "predicate_expression")),
                unless=name == "UnlessCondition",
            )
            if isinstance(holds, Unknown):
                return self.scope.unknown(f"the condition {ast.unparse(node)[:60]!r}", where)
            return holds
        if name == "LaunchDescription":
            first = argument(0, "initial_entities")
            return [] if first is None else _flat(self.value(first))
        if name == "OpaqueFunction":  # its function runs only at launch time
            return _Action(name, node, {})
        if name in (*NODE_KINDS, "ComposableNode", "ComposableNodeContainer",
                    "LoadComposableNodes", "GroupAction", *NAMESPACE_PUSHES,
                    "IncludeLaunchDescription", "DeclareLaunchArgument",
                    "SetLaunchConfiguration", "OpaqueFunction", "SetParameter"):  # fmt: skip
            values = {k.arg: self.value(k.value) for k in node.keywords if k.arg is not None}
            values["__args__"] = [self.value(a) for a in node.args]
            return _Action(name, node, values)
        if name in ("dict",) and not node.args:
            return {k.arg: self.value(k.value) for k in node.keywords if k.arg is not None}
        if name == "items" and isinstance(node.func, ast.Attribute):
            owner = self.value(node.func.value)
            return list(owner.items()) if isinstance(owner, dict) else owner
        return self.scope.unknown(f"the value of {ast.unparse(node)[:60]!r}", where)

    # ---- actions --------------------------------------------------------------------

    def perform(self, action: Value, scope: Scope) -> Scope:
        """Follow one action of the description; a namespace push changes what follows."""
        if not isinstance(action, _Action):
            if not isinstance(action, Unknown):
                scope.unknown("an entity of the description", scope.at(1, 1))
            return scope
        values, where = action.values, self.where(action.call)
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
                scope.arguments[key] = values.get(
                    "value", positional[1] if len(positional) > 1 else ""
                )
            return scope
        if kind == "SetParameter":
            name = text(values.get("name", positional[0] if positional else ""))
            value = parameter_value(
                values.get("value", positional[1] if len(positional) > 1 else "")
            )
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
                scope, NODE_KINDS[kind], _fields(values), _flat(values.get("parameters", [])), where
            )
            return scope
        if kind == "ComposableNodeContainer":
            container = add_node(
                scope, "container", _fields(values), _flat(values.get("parameters", [])), where
            )
            self.composables(
                values.get("composable_node_descriptions", []),
                scope,
                container.full_name if container else "",
            )
            return scope
        if kind == "LoadComposableNodes":
            target = text(values.get("target_container", ""))
            self.composables(
                values.get("composable_node_descriptions", []),
                scope,
                target if isinstance(target, str) else "",
            )
            return scope
        if kind == "GroupAction":
            inner = scope.pushed("", where)  # a group scopes the namespaces pushed inside it
            for item in _flat(values.get("actions", positional[0] if positional else [])):
                inner = self.perform(item, inner)
            return scope
        if kind == "IncludeLaunchDescription":
            source = text(
                values.get("launch_description_source", positional[0] if positional else "")
            )
            if isinstance(source, Unknown):
                scope.unknown("the launch file an include reads", where)
                return scope
            arguments = dict(scope.arguments)
            for pair in _flat_pairs(values.get("launch_arguments", [])):
                arguments[str(text(pair[0]))] = pair[1]
            scope.include(_path(source), arguments, scope, where)
            return scope
        return scope

    def composables(self, descriptions: Value, scope: Scope, container: str) -> None:
        for item in _flat(descriptions):
            if isinstance(item, _Action) and item.kind == "ComposableNode":
                fields = _fields(item.values)
                fields["executable"] = item.values.get("plugin", "")
                add_node(scope, "composable_node", fields, _flat(item.values.get("parameters", [])),
                         self.where(item.call), container)  # fmt: skip
            elif not isinstance(item, Unknown):
                scope.unknown("a composable node", scope.at(1, 1))


def _called(node: ast.Call) -> str:
    func = node.func
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute):
        return func.attr
    return ""


def _argument(node: ast.Call, index: int, key: str) -> ast.expr | None:
    for keyword in node.keywords:
        if keyword.arg == key:
            return keyword.value
    return node.args[index] if len(node.args) > index else None


def _required(node: ast.Call, index: int, key: str) -> ast.expr:
    found = _argument(node, index, key)
    return found if found is not None else ast.Constant("")


def _flat(value: Value) -> list[Value]:
    if isinstance(value, list | tuple):
        return [item for part in value for item in _flat(part)]
    return [value]


def _flat_pairs(value: Value) -> list[tuple[Value, Value]]:
    if isinstance(value, dict):
        return list(value.items())
    if isinstance(value, list | tuple):
        return [tuple(p) for p in value if isinstance(p, list | tuple) and len(p) == 2]
    return []


def _fields(values: dict[str, Value]) -> dict[str, Value]:
    return {key: values.get(key, "") for key in ("package", "executable", "name", "namespace")}


def _path(source: str) -> Any:
    from pathlib import Path

    return Path(source)


def _prefix_of(share: str) -> str:
    from pathlib import Path

    return str(Path(share).parent.parent)
