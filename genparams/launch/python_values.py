"""The values of a ``.launch.py``'s expressions, read from its syntax tree, never run.

Launch's actions and substitutions are known by name; the file's variables, its module
constants (read when first used), Python's operators, comparisons, ``not``/``and``/``or``,
``x if c else y``, indexing and a few builtins are computed on values Python holds while the
description is built. A substitution's text is known to the reader but not to that Python:
a test on it is left to launch. Anything else is an ``Unknown`` naming it, with its place.
"""

from __future__ import annotations

import ast
from pathlib import Path
from typing import Any

from genparams.launch.model import Unknown
from genparams.launch.nodes import Substituted
from genparams.launch.python_actions import NAMESPACE_PUSHES, NODE_KINDS, Action, flat
from genparams.launch.python_operators import (
    BUILTINS,
    METHODS,
    LaunchText,
    NotPlainError,
    binary,
    builtin,
    compare,
    is_plain,
)
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

ACTIONS = (*NODE_KINDS, "ComposableNode", "ComposableNodeContainer", "LoadComposableNodes",
           "GroupAction", *NAMESPACE_PUSHES, "IncludeLaunchDescription", "DeclareLaunchArgument",
           "SetLaunchConfiguration", "OpaqueFunction", "SetParameter")  # fmt: skip
SOURCES = ("PythonLaunchDescriptionSource", "AnyLaunchDescriptionSource",
           "XMLLaunchDescriptionSource", "YAMLLaunchDescriptionSource",
           "FrontendLaunchDescriptionSource")  # fmt: skip
ENVIRON = ("os.environ", "environ")
NOT_OWN = object()  # a call of none of the launch file's own functions


class ValueReader:
    def __init__(self, scope: Scope, constants: dict[str, ast.expr]) -> None:
        self.scope = scope
        self.constants = constants
        self.variables: dict[str, Value] = {}  # the frame being run
        self.outer: tuple[dict[str, Value], ...] = ()  # frames a nested function sees
        self.module_values: dict[str, Value] = {}
        self.reading: set[str] = set()  # module constants being read (a cycle stops)
        self.declared: dict[str, Value] = {}  # DeclareLaunchArgument defaults met

    def where(self, node: ast.AST) -> Location:
        return self.scope.at(getattr(node, "lineno", 1), getattr(node, "col_offset", 0) + 1)

    def own_call(self, node: ast.Call) -> Value:
        """The result of a call of the launch file's own function, else ``NOT_OWN``."""
        return NOT_OWN

    def literal(self, node: ast.expr | None) -> Any:
        if node is None:
            return None
        try:
            return Evaluator(ValueScope(module_constants=self.constants)).value(node)
        except UntranslatableError:
            return None

    def lookup(self, name: str) -> tuple[bool, Value]:
        for frame in (self.variables, *self.outer):
            if name in frame:
                return True, frame[name]
        if name in self.module_values:
            return True, self.module_values[name]
        if name in self.constants and name not in self.reading:
            saved = self.variables, self.outer
            self.variables, self.outer = {}, ()
            self.reading.add(name)
            try:
                found = self.value(self.constants[name])
            finally:
                self.reading.discard(name)
                self.variables, self.outer = saved
            self.module_values[name] = found
            return True, found
        return False, None

    def value(self, node: ast.expr) -> Value:
        if isinstance(node, ast.Name):
            known, found = self.lookup(node.id)
            if known:
                return found
        if isinstance(node, ast.List | ast.Tuple):
            return self.sequence(node)
        if isinstance(node, ast.Dict):
            return self.mapping(node)
        if isinstance(node, ast.Call):
            return self.call(node)
        if isinstance(node, ast.BinOp):
            return self.binary(node)
        if isinstance(node, ast.JoinedStr):
            parts = [
                self.value(p.value) if isinstance(p, ast.FormattedValue) else self.value(p)
                for p in node.values
            ]
            return text(parts)
        if isinstance(node, ast.Compare | ast.BoolOp | ast.UnaryOp | ast.IfExp | ast.Subscript):
            return self.python(node)
        if isinstance(node, ast.ListComp | ast.GeneratorExp):
            return self.comprehension(node)
        try:
            return Evaluator(ValueScope(module_constants=self.constants)).value(node)
        except UntranslatableError as exc:
            return self.scope.unknown(exc.what, self.where(node))

    def comprehension(self, node: ast.ListComp | ast.GeneratorExp) -> Value:
        return self.scope.unknown(f"the value of {ast.unparse(node)[:60]!r}", self.where(node))

    def sequence(self, node: ast.List | ast.Tuple) -> Value:
        """A list or tuple, ``*spread`` items included (``[*arguments, *nodes]``)."""
        found: list[Value] = []
        for item in node.elts:
            if not isinstance(item, ast.Starred):
                found.append(self.value(item))
                continue
            spread = self.value(item.value)
            if isinstance(spread, list | tuple | dict) and not isinstance(spread, LaunchText):
                found.extend(spread)
            else:
                found.append(
                    spread
                    if isinstance(spread, Unknown)
                    else self.scope.unknown(f"the items of {ast.unparse(item)!r}", self.where(item))
                )
        return found

    def mapping(self, node: ast.Dict) -> Value:
        """A dict, ``**spread`` ones included; a key Python cannot hash is unknown."""
        found: dict[Any, Value] = {}
        for key, item in zip(node.keys, node.values, strict=True):
            if key is None:
                spread = self.value(item)
                if isinstance(spread, dict):
                    found.update(spread)
                continue
            name, value = self.value(key), self.value(item)
            try:
                found[name] = value
            except TypeError:
                return self.scope.unknown(f"the key {ast.unparse(key)!r}", self.where(key))
        return found

    def binary(self, node: ast.BinOp) -> Value:
        left, right = self.value(node.left), self.value(node.right)
        for side in (left, right):
            if isinstance(side, Unknown):
                return side
        if isinstance(node.op, ast.Add) and not (is_plain(left) and is_plain(right)):
            if isinstance(left, list) and isinstance(right, list):
                return left + right
            joined = text([left, right])
            if isinstance(joined, Unknown):
                return joined
            launch_time = isinstance(left, LaunchText) or isinstance(right, LaunchText)
            return LaunchText(joined) if launch_time else Substituted(joined)
        try:
            found = binary(node.op, left, right)
        except NotPlainError:
            return self.scope.unknown(f"the value of {ast.unparse(node)[:60]!r}", self.where(node))
        substituted = isinstance(left, Substituted) or isinstance(right, Substituted)
        return Substituted(found) if isinstance(found, str) and substituted else found

    def python(self, node: ast.expr) -> Value:
        """A comparison, ``not``, ``and``/``or``, ``x if c else y``, ``x[i]``."""
        where, written = self.where(node), ast.unparse(node)[:60]
        if isinstance(node, ast.BoolOp):
            found: Value = None
            for operand in node.values:
                found = self.value(operand)
                if isinstance(found, Unknown):
                    return found
                if not is_plain(found):
                    return self.scope.unknown(
                        f"the test {written!r} (on a substitution, whose value only launch knows)",
                        where,
                    )
                if bool(found) == isinstance(node.op, ast.Or):
                    return found
            return found
        if isinstance(node, ast.IfExp):
            holds = self.truth(node.test)
            if isinstance(holds, Unknown):
                return holds
            return self.value(node.body if holds else node.orelse)
        if isinstance(node, ast.UnaryOp):
            operand = self.value(node.operand)
            if isinstance(operand, Unknown):
                return operand
            if isinstance(node.op, ast.Not) and is_plain(operand):
                return not operand
            if isinstance(node.op, ast.USub | ast.UAdd) and isinstance(operand, int | float):
                return -operand if isinstance(node.op, ast.USub) else operand
            return self.scope.unknown(f"the value of {written!r}", where)
        if isinstance(node, ast.Compare):
            values = [self.value(node.left), *(self.value(c) for c in node.comparators)]
            for value in values:
                if isinstance(value, Unknown):
                    return value
            try:
                return compare(node.ops, values)
            except NotPlainError:
                return self.scope.unknown(
                    f"the test {written!r} (on a substitution, whose value only launch knows)",
                    where,
                )
        if isinstance(node, ast.Subscript) and ast.unparse(node.value) in ENVIRON:
            key = self.value(node.slice)  # os.environ["X"]: set here, or only launch knows
            if isinstance(key, str) and not isinstance(key, LaunchText):
                return environment(key, None, self.scope, where)
        if isinstance(node, ast.Subscript):
            container, index = self.value(node.value), self.index(node.slice)
            if isinstance(index, Unknown):
                return index
            if isinstance(container, dict | list | tuple | str) and is_plain(index):
                try:
                    return container[index]
                except (IndexError, KeyError, TypeError):
                    pass
        return self.scope.unknown(f"the value of {written!r}", where)

    def index(self, node: ast.expr) -> Value:
        if not isinstance(node, ast.Slice):
            return self.value(node)
        bounds = [None if b is None else self.value(b) for b in (node.lower, node.upper, node.step)]
        if all(b is None or (isinstance(b, int) and not isinstance(b, bool)) for b in bounds):
            return slice(*bounds)
        return self.scope.unknown(f"the slice {ast.unparse(node)!r}", self.where(node))

    def truth(self, test: ast.expr) -> bool | Unknown:
        """Whether Python takes ``if test``: known only for values it holds before launch."""
        found = self.value(test)
        if isinstance(found, Unknown):
            return found
        if not is_plain(found):
            return self.scope.unknown(
                f"the test {ast.unparse(test)[:60]!r} (on a substitution or an action)",
                self.where(test),
            )
        return bool(found)

    def call(self, node: ast.Call) -> Value:
        own = self.own_call(node)
        if own is not NOT_OWN:
            return own
        name = called_name(node)
        where = self.where(node)

        def argument(index: int, key: str) -> ast.expr | None:
            return call_argument(node, index, key)

        if name == "LaunchConfiguration":
            key = self.value(argument(0, "variable_name") or ast.Constant(None))
            if not isinstance(key, str) or isinstance(key, LaunchText):
                return self.scope.unknown("a launch configuration's name", where)
            if key not in self.scope.arguments:
                default = argument(1, "default")
                if default is not None:
                    return self.value(default)
                return self.scope.unknown(f"launch configuration {key} (never declared)", where)
            found = self.scope.arguments[key]
            return found if isinstance(found, Unknown) else _launch_text(text(found))
        if name in ("FindPackageShare", "FindPackagePrefix"):
            share = package_share(self.value(_required(node, 0, "package")), self.scope, where)
            if name == "FindPackagePrefix" and isinstance(share, str):
                return LaunchText(str(Path(share).parent.parent))
            return _launch_text(share)
        if name == "get_package_share_directory":
            share = package_share(self.value(_required(node, 0, "package_name")), self.scope, where)
            return Substituted(share) if isinstance(share, str) else share
        if name in ("PathJoinSubstitution",):
            return _launch_text(path_join(flat(self.value(_required(node, 0, "substitutions")))))
        if name == "join" and ast.unparse(node.func) in ("os.path.join", "path.join"):
            parts = [self.value(a) for a in node.args]
            joined = path_join(parts)
            if any(isinstance(p, LaunchText) for p in parts):
                return _launch_text(joined)
            return Substituted(joined) if isinstance(joined, str) else joined
        if name == "TextSubstitution":
            return _launch_text(text(self.value(_required(node, 0, "text"))))
        if ast.unparse(node.func) in (*(f"{e}.get" for e in ENVIRON), "os.getenv", "getenv"):
            key = self.value(_required(node, 0, "key"))
            default = argument(1, "default")
            if not isinstance(key, str) or isinstance(key, LaunchText):
                return self.scope.unknown(f"the value of {ast.unparse(node)[:60]!r}", where)
            # Read while the description is built: this machine's environment, as for
            # EnvironmentVariable; unset and without a default, only launch knows it.
            return environment(
                key, None if default is None else self.value(default), self.scope, where
            )
        if name == "EnvironmentVariable":
            key = text(self.value(_required(node, 0, "name")))
            default = argument(1, "default_value")
            if isinstance(key, Unknown):
                return key
            found = environment(
                key, None if default is None else self.value(default), self.scope, where
            )
            return found if isinstance(found, Unknown) else _launch_text(text(found))
        if name in ("ParameterFile", "ParameterValue"):
            return self.value(
                _required(node, 0, "param_file" if name == "ParameterFile" else "value")
            )
        if name in SOURCES:
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
            return [] if first is None else flat(self.value(first))
        if name == "OpaqueFunction":  # its function runs only at launch time
            return Action(name, node, {})
        if name in ACTIONS:
            values: dict[str, Value] = {}
            for keyword in node.keywords:
                if keyword.arg is not None:
                    values[keyword.arg] = self.value(keyword.value)
                elif isinstance(splat := self.value(keyword.value), dict):
                    values.update({str(k): v for k, v in splat.items()})  # Node(**common)
            values["__args__"] = [self.value(a) for a in node.args]
            if name == "DeclareLaunchArgument":
                self.declare(values, where)
            return Action(name, node, values)
        if name in ("dict",) and not node.args:
            return {k.arg: self.value(k.value) for k in node.keywords if k.arg is not None}
        return self.python_call(node, name, where)

    def python_call(self, node: ast.Call, name: str, where: Location) -> Value:
        """A builtin (``range``, ``zip``, ``len`` ...) or a method that builds a value."""
        what = f"the value of {ast.unparse(node)[:60]!r}"
        method = isinstance(node.func, ast.Attribute) and name in METHODS
        builtin_name = isinstance(node.func, ast.Name) and name in BUILTINS
        if any(isinstance(a, ast.Starred) for a in node.args) or not (method or builtin_name):
            return self.scope.unknown(what, where)
        args = [self.value(a) for a in node.args]
        keywords = {k.arg: self.value(k.value) for k in node.keywords if k.arg is not None}
        function = BUILTINS[name] if builtin_name else METHODS[name]
        if isinstance(node.func, ast.Attribute):
            owner = self.value(node.func.value)
            if name in ("items", "keys", "values") and isinstance(owner, dict) and not args:
                return list(getattr(owner, name)())  # launch_arguments={...}.items()
            args = [owner, *args]
        for found in (*args, *keywords.values()):
            if isinstance(found, Unknown):
                return found
        try:
            return builtin(name, function, args, keywords)
        except NotPlainError as exc:
            return self.scope.unknown(f"{what} ({exc})" if str(exc) else what, where)

    def declare(self, values: dict[str, Value], where: Location) -> None:
        """A ``DeclareLaunchArgument`` met while reading: its default, by its name."""
        positional = values["__args__"]
        name = values.get("name", positional[0] if positional else None)
        default = values.get("default_value", positional[1] if len(positional) > 1 else None)
        if default is None:
            default = Unknown(f"launch argument {name} (no default, none given)", where)
        if isinstance(name, str) and name not in self.declared:
            self.declared[name] = default


def _launch_text(value: Value) -> Value:
    return LaunchText(value) if isinstance(value, str) else value


def called_name(node: ast.Call) -> str:
    func = node.func
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute):
        return func.attr
    return ""


def call_argument(node: ast.Call, index: int, key: str) -> ast.expr | None:
    for keyword in node.keywords:
        if keyword.arg == key:
            return keyword.value
    return node.args[index] if len(node.args) > index else None


def _required(node: ast.Call, index: int, key: str) -> ast.expr:
    found = call_argument(node, index, key)
    return found if found is not None else ast.Constant("")
