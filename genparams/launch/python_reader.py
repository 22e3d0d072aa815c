"""A ``.launch.py`` read from its syntax tree, never run.

``generate_launch_description()`` is followed as Python would run it (python_flow): its
statements, loops and tests on values Python holds, and the file's own functions. The
launch actions and substitutions of launch and launch_ros are known by name (``Node``,
``LifecycleNode``, ``ComposableNodeContainer``, ``LoadComposableNodes``, ``ComposableNode``,
``GroupAction``, ``PushRosNamespace``, ``IncludeLaunchDescription``, ``DeclareLaunchArgument``,
``LaunchConfiguration``, ``IfCondition``, ``UnlessCondition``, ``PathJoinSubstitution``,
``FindPackageShare``, ``get_package_share_directory``, ``os.path.join``,
``EnvironmentVariable``, ``TextSubstitution``, ``ParameterFile``: python_values); the
description's actions are then performed in order (python_actions). Anything else (an
``OpaqueFunction``, a function of another module, a loop over what only launch knows) is
reported as set at launch time, with its place.
"""

from __future__ import annotations

import ast
from dataclasses import replace

from genparams.launch.model import LaunchResult, Unknown
from genparams.launch.python_actions import perform
from genparams.launch.python_flow import FlowReader
from genparams.launch.python_values import call_argument, called_name
from genparams.launch.scope import Scope

ENTRY = "generate_launch_description"


def read_python_launch(source: str, scope: Scope) -> None:
    try:
        tree = ast.parse(source, filename=str(scope.file))
    except SyntaxError as exc:
        scope.unknown(f"the launch file (not Python: {exc.msg})", scope.at(exc.lineno or 1, 1))
        return
    functions = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
    function = functions.get(ENTRY)
    if function is None:
        scope.unknown(f"the launch file (no {ENTRY}())", scope.at(1, 1))
        return
    constants: dict[str, ast.expr] = {}
    for statement in tree.body:
        if isinstance(statement, ast.Assign):
            for target in statement.targets:
                if isinstance(target, ast.Name):
                    constants[target.id] = statement.value
        elif isinstance(statement, ast.AnnAssign) and statement.value is not None:
            if isinstance(statement.target, ast.Name):  # ROBOTS: list[str] = [...]
                constants[statement.target.id] = statement.value
    try:
        _follow(scope, function, constants, functions)
    except RecursionError:  # values nested in themselves (a list appended to itself)
        scope.unknown("the launch file (its values nest too deep to follow)", scope.at(1, 1))


def _follow(
    scope: Scope,
    function: ast.FunctionDef,
    constants: dict[str, ast.expr],
    functions: dict[str, ast.FunctionDef],
) -> None:
    # Arguments first: launch resolves configurations when it runs, after the description
    # is built, so a default may use a variable assigned anywhere in the function. A dry
    # run (its findings dropped) gives the variables and the arguments declared in loops
    # and functions; the real run then sees every default.
    dry_scope = replace(scope, result=LaunchResult(), arguments=dict(scope.arguments))
    dry = FlowReader(dry_scope, constants, functions)
    dry.run_entry(function)
    reader = FlowReader(scope, constants, functions)
    reader.variables = dry.variables
    declare_arguments(reader, function)
    for name, default in dry.declared.items():
        if name not in scope.arguments:
            scope.arguments[name] = default
    reader.variables = {}
    reader.module_values = {}
    for action in reader.run_entry(function):
        perform(action, scope)


def declare_arguments(reader: FlowReader, function: ast.FunctionDef) -> None:
    """Every ``DeclareLaunchArgument`` default, before any use: launch resolves
    configurations when it runs, after the description is built."""
    scope = reader.scope
    for node in ast.walk(function):
        if isinstance(node, ast.Call) and called_name(node) == "DeclareLaunchArgument":
            name = reader.literal(call_argument(node, 0, "name"))
            if not isinstance(name, str) or name in scope.arguments:
                continue
            default = call_argument(node, 1, "default_value")
            if default is not None:
                scope.arguments[name] = reader.value(default)
            else:
                scope.arguments[name] = Unknown(
                    f"launch argument {name} (no default, none given)", reader.where(node)
                )
