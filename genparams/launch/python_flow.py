"""The statements of a ``.launch.py`` followed as Python would run them, without running them.

Assignments (unpacking too), ``+=``, ``list.append``/``extend``, ``ld.add_action``, ``for``
loops over values Python holds before launch runs (lists, tuples, dicts, module constants,
``range``, ``zip``, ``enumerate``, ``.items()``), ``if``/``elif``/``else`` on such values,
``break``/``continue``/``return``, list comprehensions, and calls of the launch file's own
functions (module level or nested, positional, keyword and default arguments, a bounded
depth). A loop or a test on anything else is reported as set at launch time: what it adds is
not guessed, the variables it sets become unknown.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass

from genparams.errors import GenparamsError
from genparams.launch.model import Unknown
from genparams.launch.python_actions import flat
from genparams.launch.python_operators import NotPlainError, binary, items
from genparams.launch.python_syntax import bodies, leaves, names, targets, walk
from genparams.launch.python_values import NOT_OWN, ValueReader
from genparams.launch.scope import Scope, Value

MAX_CALL_DEPTH = 16  # calls within calls: a function calling itself stops here
MAX_STEPS = 50_000  # statements followed in one launch file, loops and calls included


@dataclass(frozen=True)
class Function:
    definition: ast.FunctionDef
    outer: tuple[dict[str, Value], ...]  # the frames a nested function sees


class _ReturnError(GenparamsError):
    def __init__(self, value: Value) -> None:
        self.value = value


class _BreakError(GenparamsError):
    pass


class _ContinueError(GenparamsError):
    pass


class _UndecidedError(GenparamsError):
    """A ``return``, ``break`` or ``continue`` under a test or loop the reader cannot decide:
    the rest of its function is not known."""

    def __init__(self, unknown: Unknown) -> None:
        self.unknown = unknown


class _TooLongError(GenparamsError):
    pass


class FlowReader(ValueReader):
    def __init__(
        self, scope: Scope, constants: dict[str, ast.expr], functions: dict[str, ast.FunctionDef]
    ) -> None:
        super().__init__(scope, constants)
        self.functions = functions
        self.loose: list[Value] = []  # add_action on what is not a known list: the description
        self.depth = 0
        self.steps = 0

    def run_entry(self, function: ast.FunctionDef) -> list[Value]:
        """The actions ``generate_launch_description`` puts in the description, in order."""
        try:
            self.block(function.body)
        except _ReturnError as returned:
            self.loose.extend(flat(returned.value))
        except _UndecidedError:
            self.scope.unknown(
                f"what {function.name}() returns (it may return under a test or loop only "
                "launch decides)",
                self.where(function),
            )
        except _TooLongError:
            self.scope.unknown(
                f"the rest of {function.name}() (over {MAX_STEPS} statements to follow)",
                self.where(function),
            )
        return self.loose

    # ---- statements -----------------------------------------------------------------

    def block(self, body: list[ast.stmt]) -> None:
        for statement in body:
            self.steps += 1
            if self.steps > MAX_STEPS:
                raise _TooLongError
            self.statement(statement)

    def statement(self, statement: ast.stmt) -> None:
        if isinstance(statement, ast.Assign):
            found = self.value(statement.value)
            for target in statement.targets:
                self.bind(target, found, statement)
        elif isinstance(statement, ast.AnnAssign) and statement.value is not None:
            self.bind(statement.target, self.value(statement.value), statement)
        elif isinstance(statement, ast.AugAssign) and isinstance(statement.target, ast.Name):
            self.augment(statement, statement.target)
        elif isinstance(statement, ast.Return):
            raise _ReturnError(None if statement.value is None else self.value(statement.value))
        elif isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Call):
            self.method_call(statement.value)
        elif isinstance(statement, ast.For):
            self.loop(statement)
        elif isinstance(statement, ast.If):
            holds = self.truth(statement.test)
            if isinstance(holds, Unknown):
                header = f"if {ast.unparse(statement.test)}:"
                self.undecided(statement, f"what {header[:60]!r} adds (its test is not known)")
            else:
                self.block(statement.body if holds else statement.orelse)
        elif isinstance(statement, ast.FunctionDef):
            self.variables[statement.name] = Function(statement, (self.variables, *self.outer))
        elif isinstance(statement, ast.Break):
            raise _BreakError
        elif isinstance(statement, ast.Continue):
            raise _ContinueError
        elif not isinstance(statement, ast.Import | ast.ImportFrom | ast.Pass | ast.Expr):
            first = ast.unparse(statement).splitlines()[0]
            self.undecided(statement, f"what the statement {first[:50]!r} adds")

    def bind(self, target: ast.expr, found: Value, statement: ast.AST) -> None:
        if isinstance(target, ast.Name):
            self.variables[target.id] = found
            return
        if isinstance(target, ast.Tuple | ast.List):
            if isinstance(found, list | tuple) and len(found) == len(target.elts):
                for element, item in zip(target.elts, found, strict=True):
                    self.bind(element, item, statement)
                return
            if not isinstance(found, Unknown):
                found = self.scope.unknown(
                    f"the unpacking {ast.unparse(target)[:50]!r}", self.where(target)
                )
            for name in names(target):
                self.variables[name] = found
            return
        if isinstance(target, ast.Subscript) and isinstance(target.value, ast.Name):
            known, container = self.lookup(target.value.id)
            index = self.value(target.slice)
            if known and isinstance(container, dict) and not isinstance(index, Unknown):
                try:
                    container[index] = found  # params["rate"] = 5.0
                except TypeError:
                    pass  # a key Python cannot hash: reported below
                else:
                    return
        self.scope.unknown(f"what {ast.unparse(statement)[:50]!r} sets", self.where(statement))

    def augment(self, statement: ast.AugAssign, target: ast.Name) -> None:
        """``nodes += [...]`` extends the list itself; ``n += 1`` binds a new value."""
        known, current = self.lookup(target.id)
        added = self.value(statement.value)
        if known and isinstance(current, list) and isinstance(statement.op, ast.Add):
            if isinstance(added, list | tuple):
                current.extend(added)
            elif not isinstance(added, Unknown):
                self.scope.unknown(
                    f"what {ast.unparse(statement)[:50]!r} adds", self.where(statement)
                )
            return
        if not known or isinstance(current, Unknown) or isinstance(added, Unknown):
            self.variables[target.id] = added if isinstance(added, Unknown) else self.value(target)
            return
        try:
            self.variables[target.id] = binary(statement.op, current, added)
        except NotPlainError:
            self.variables[target.id] = self.scope.unknown(
                f"the value of {ast.unparse(statement)[:50]!r}", self.where(statement)
            )

    def method_call(self, call: ast.Call) -> None:
        func = call.func
        if isinstance(func, ast.Attribute) and func.attr in ("add_action", "append", "extend"):
            owner = func.value
            added = [self.value(a) for a in call.args]
            if func.attr == "extend":
                added = [i for item in added for i in flat(item)]
            known, found = self.lookup(owner.id) if isinstance(owner, ast.Name) else (False, None)
            if known and isinstance(found, list):
                found.extend(added)
            elif known and isinstance(found, Unknown):
                self.scope.unknown(f"what {ast.unparse(call)[:50]!r} adds", self.where(call))
            else:
                self.loose.extend(added)  # ld.add_action(...): the description itself
            return
        if self.own_call(call) is NOT_OWN:
            self.scope.unknown(f"what {ast.unparse(call)[:50]!r} does", self.where(call))

    def loop(self, statement: ast.For) -> None:
        header = f"for {ast.unparse(statement.target)} in {ast.unparse(statement.iter)}:"
        try:
            found = items(self.value(statement.iter))
        except NotPlainError:
            self.undecided(statement, f"what {header[:60]!r} adds (its items are not known)")
            return
        for item in found:
            self.bind(statement.target, item, statement)
            try:
                self.block(statement.body)
            except _BreakError:
                return
            except _ContinueError:
                continue
        self.block(statement.orelse)

    def undecided(self, statement: ast.stmt, what: str) -> None:
        """A test, loop or statement only launch decides: its body is not followed, the
        variables it sets are unknown from here, and a ``return`` under it leaves its
        function unknown."""
        unknown = self.scope.unknown(what, self.where(statement))
        inner = [s for part in bodies(statement) for s in part]
        for node in [statement, *walk(inner)]:
            for target in targets(node):
                for name in names(target):
                    if not isinstance(self.lookup(name)[1], list):
                        self.variables[name] = unknown
                if isinstance(target, ast.Subscript) and isinstance(target.value, ast.Name):
                    self.variables[target.value.id] = unknown
        if leaves(inner, loop=isinstance(statement, ast.For | ast.While)):
            raise _UndecidedError(unknown)

    # ---- the launch file's own functions --------------------------------------------

    def own_call(self, node: ast.Call) -> Value:
        if not isinstance(node.func, ast.Name):
            return NOT_OWN
        known, found = self.lookup(node.func.id)
        if known and isinstance(found, Function):
            function = found
        elif not known and node.func.id in self.functions:
            function = Function(self.functions[node.func.id], ())
        else:
            return NOT_OWN
        if function.definition.decorator_list:
            return NOT_OWN
        where, written = self.where(node), ast.unparse(node)[:60]
        if self.depth >= MAX_CALL_DEPTH:
            return self.scope.unknown(
                f"the value of {written!r} (calls within calls deeper than {MAX_CALL_DEPTH})",
                where,
            )
        frame = self.arguments(function, node)
        if frame is None:
            signature = f"{function.definition.name}({ast.unparse(function.definition.args)})"
            return self.scope.unknown(
                f"the value of {written!r} (its arguments do not fit {signature})", where
            )
        saved = self.variables, self.outer
        self.variables, self.outer = frame, function.outer
        self.depth += 1
        try:
            self.block(function.definition.body)
        except _ReturnError as returned:
            return returned.value
        except _UndecidedError as undecided:
            return undecided.unknown
        except (_BreakError, _ContinueError):
            pass
        finally:
            self.depth -= 1
            self.variables, self.outer = saved
        return None

    def arguments(self, function: Function, node: ast.Call) -> dict[str, Value] | None:
        """The frame a call gives its function, as Python binds it; None when it does not fit."""
        spec = function.definition.args
        positional = [a.arg for a in (*spec.posonlyargs, *spec.args)]
        keyword_only = [a.arg for a in spec.kwonlyargs]
        given: list[Value] = []
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                try:
                    given.extend(items(self.value(arg.value)))
                except NotPlainError:
                    return None
            else:
                given.append(self.value(arg))
        named: dict[str, Value] = {}
        for keyword in node.keywords:
            found = self.value(keyword.value)
            if keyword.arg is not None:
                named[keyword.arg] = found
            elif isinstance(found, dict):
                named.update({str(k): v for k, v in found.items()})
            else:
                return None
        frame: dict[str, Value] = dict(zip(positional, given, strict=False))
        extra = given[len(positional) :]
        if extra and spec.vararg is None:
            return None
        if spec.vararg is not None:
            frame[spec.vararg.arg] = extra
        rest: dict[str, Value] = {}
        for key, found in named.items():
            if key in frame:
                return None
            if key in positional or key in keyword_only:
                frame[key] = found
            elif spec.kwarg is not None:
                rest[key] = found
            else:
                return None
        if spec.kwarg is not None:
            frame[spec.kwarg.arg] = rest
        defaults: dict[str, ast.expr] = dict(
            zip(positional[len(positional) - len(spec.defaults) :], spec.defaults, strict=True)
        )
        for name, default in zip(keyword_only, spec.kw_defaults, strict=True):
            if default is not None:
                defaults[name] = default
        missing = [n for n in (*positional, *keyword_only) if n not in frame]
        if any(name not in defaults for name in missing):
            return None
        saved = self.variables, self.outer
        if function.outer:
            self.variables, self.outer = function.outer[0], function.outer[1:]
        else:
            self.variables, self.outer = {}, ()
        try:  # defaults are read where the function is defined
            frame.update({name: self.value(defaults[name]) for name in missing})
        finally:
            self.variables, self.outer = saved
        return frame

    # ---- list comprehensions --------------------------------------------------------

    def comprehension(self, node: ast.ListComp | ast.GeneratorExp) -> Value:
        built: list[Value] = []
        saved = self.variables
        self.variables = dict(saved)  # its variables stay inside it
        try:
            unknown = self.generate(node, 0, built)
        finally:
            self.variables = saved
        return built if unknown is None else unknown

    def generate(
        self, node: ast.ListComp | ast.GeneratorExp, index: int, built: list[Value]
    ) -> Unknown | None:
        if index == len(node.generators):
            built.append(self.value(node.elt))
            return None
        generator = node.generators[index]
        try:
            found = items(self.value(generator.iter))
        except NotPlainError:
            return self.scope.unknown(
                f"the items of {ast.unparse(generator.iter)[:60]!r} in a list comprehension",
                self.where(generator.iter),
            )
        for item in found:
            self.steps += 1
            if self.steps > MAX_STEPS:
                raise _TooLongError
            self.bind(generator.target, item, generator.iter)
            taken = True
            for test in generator.ifs:
                holds = self.truth(test)
                if isinstance(holds, Unknown):
                    return holds
                if not holds:
                    taken = False
                    break
            if taken:
                unknown = self.generate(node, index + 1, built)
                if unknown is not None:
                    return unknown
        return None
