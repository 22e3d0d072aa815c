"""Values of a node's source, read from its syntax tree and never run.

The evaluator knows literals, simple arithmetic on them, constants the module or
the class defines (``NAME = literal``), variables of the function bound before
their use, loop variables, ``Parameter.Type.X`` and the descriptor messages
(``ParameterDescriptor``, ``FloatingPointRange``, ``IntegerRange``). Anything
else raises ``UntranslatableError`` naming the construct.
"""

from __future__ import annotations

import ast
import math
import os.path
from collections.abc import Callable
from dataclasses import replace
from typing import Any

from genparams.rclpy_import.limits import computable
from genparams.rclpy_import.ros_names import (
    BINARY,
    DESCRIPTOR_FIELDS,
    MATH,
    RANGE_FIELDS,
    RCLPY_ENUMS,
    ROS_TYPES,
)
from genparams.rclpy_import.scope import (
    Binding,
    DescriptorValue,
    Elsewhere,
    NotReadError,
    RangeValue,
    Scope,
    SharePath,
    TypeMarker,
    UntranslatableError,
    assigned_once_before,
    before,
    constants,
    dotted_name,
    last_before,
    read_call,
    unparsed,
)

__all__ = [
    "RCLPY_ENUMS",
    "ROS_TYPES",
    "DescriptorValue",
    "Evaluator",
    "RangeValue",
    "Scope",
    "SharePath",
    "TypeMarker",
    "UntranslatableError",
    "assigned_once_before",
    "dotted_name",
    "evaluate_constant",
    "unparsed",
]

_MAX_DEPTH = 32  # constants defined through constants, never in a loop


_BUILTINS: dict[str, Any] = {"float": float, "int": int, "str": str, "bool": bool}
_NUMPY = ("np", "numpy")
_FUNCTIONS: dict[str, Callable[..., Any]] = {
    "math.radians": math.radians,
    "math.degrees": math.degrees,
    "math.sqrt": math.sqrt,
    "math.floor": math.floor,
    "math.ceil": math.ceil,
    "abs": abs,
    "min": min,
    "max": max,
    "round": round,
}
_SHARE = "get_package_share_directory"


def evaluate_constant(expression: ast.expr, module: ast.Module | None = None) -> Any:
    """The value of ``expression``, read statically with the constants ``module`` assigns
    once at its top level (``RATE = 10.0``): literals, arithmetic, ``math.pi``, f-strings,
    share-directory paths (a ``SharePath``). Raises ``UntranslatableError`` naming the
    construct for anything else; nothing is ever run."""
    bound: dict[str, Binding] = dict(constants(module.body)) if module is not None else {}
    return Evaluator(Scope(module_constants=bound)).value(expression)


class Evaluator:
    def __init__(self, scope: Scope) -> None:
        self.scope = scope
        self.depth = 0
        self.parameters_read: list[str] = []  # parameters a value was computed from

    def value(self, node: ast.expr) -> Any:
        self.depth += 1
        try:
            if self.depth > _MAX_DEPTH:
                raise UntranslatableError(node, f"the expression {unparsed(node)!r}")
            return self._value(node)
        finally:
            self.depth -= 1

    def _value(self, node: ast.expr) -> Any:
        if isinstance(node, ast.Constant):
            if isinstance(node.value, (bool, int, float, str, bytes)) or node.value is None:
                return node.value
            raise UntranslatableError(node, f"the constant {unparsed(node)}")
        if isinstance(node, (ast.List, ast.Tuple)):
            items = [self.value(item) for item in node.elts]
            return items if isinstance(node, ast.List) else tuple(items)
        if isinstance(node, ast.Dict) and None not in node.keys:
            pairs = zip(node.keys, node.values, strict=True)
            return {self.value(k): self.value(v) for k, v in pairs if k is not None}
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd, ast.Not)):
            operand = self.value(node.operand)
            if isinstance(node.op, ast.Not):
                return not operand
            if isinstance(operand, (int, float)) and not isinstance(operand, bool):
                return -operand if isinstance(node.op, ast.USub) else operand
        if isinstance(node, ast.BinOp) and type(node.op) in BINARY:
            left, right = self.value(node.left), self.value(node.right)
            if _repeated(node.op, left, right):
                return left * right if isinstance(left, list) else right * left
            if _same_kind(left, right) and computable(node.op, left, right):
                try:
                    result = BINARY[type(node.op)](left, right)
                except (ArithmeticError, TypeError, ValueError):
                    pass
                else:
                    return SharePath(result) if isinstance(left, SharePath) else result
        if isinstance(node, ast.JoinedStr):
            return self._formatted(node)
        if isinstance(node, ast.Name):
            return self._name(node)
        if isinstance(node, ast.Attribute):
            return self._attribute(node)
        if isinstance(node, ast.Call):
            return self._call(node)
        if isinstance(node, ast.Subscript):
            container, index = self.value(node.value), self.value(node.slice)
            try:
                return container[index]
            except (IndexError, KeyError, TypeError):
                pass
        raise UntranslatableError(node, f"the expression {unparsed(node)!r}")

    def _formatted(self, node: ast.JoinedStr) -> str:
        parts: list[str] = []
        for part in node.values:
            if isinstance(part, ast.Constant):
                parts.append(str(part.value))
            elif isinstance(part, ast.FormattedValue):
                if part.format_spec is not None or part.conversion != -1:
                    raise UntranslatableError(part, f"the formatted value {unparsed(node)!r}")
                parts.append(self.value(part.value))
        text = "".join(str(p) for p in parts)
        return SharePath(text) if parts and isinstance(parts[0], SharePath) else text

    def _name(self, node: ast.Name) -> Any:
        scope = self.scope
        if node.id in scope.loop:
            return scope.loop[node.id]
        assigned = last_before(scope.local.get(node.id, []), node)
        if assigned is not None:
            return self._assigned(assigned, node)
        if node.id in scope.module_constants:
            return self.bound(scope.module_constants[node.id])
        if node.id in scope.outside:
            raise NotReadError(node, node.id, scope.outside[node.id])
        raise UntranslatableError(node, f"the variable {node.id!r}")

    def _assigned(self, statement: ast.stmt, use: ast.Name) -> Any:
        if isinstance(statement, (ast.Assign, ast.AnnAssign)) and statement.value is not None:
            value = self.value(statement.value)
            if isinstance(value, DescriptorValue):
                self._apply_attribute_sets(value, use)
            return value
        raise UntranslatableError(use, f"the variable {use.id!r}")

    def _apply_attribute_sets(self, descriptor: DescriptorValue, use: ast.Name) -> None:
        """``descriptor.read_only = True`` after the descriptor was made, before its use."""
        sets = self.scope.local.get(f"{use.id}.*", [])
        for statement in sets:
            if not isinstance(statement, ast.Assign) or not before(statement, use):
                continue
            target = statement.targets[0]
            if isinstance(target, ast.Attribute):
                self._descriptor_field(descriptor, target.attr, statement.value)

    def bound(self, binding: Binding) -> Any:
        """A constant's value, read where it is bound (another module's, in its scope)."""
        if isinstance(binding, Elsewhere):
            inner = Evaluator(binding.scope)
            inner.depth = self.depth
            return inner.value(binding.expression)
        return self.value(binding)

    def _attribute(self, node: ast.Attribute) -> Any:
        read = self._parameter_read(node)
        if read is not None:
            return read
        name = dotted_name(node)
        if name is not None:
            head, _, rest = name.partition(".")
            parts = name.split(".")
            if len(parts) >= 2 and parts[-2] == "Type" and parts[-1] in ROS_TYPES:
                return TypeMarker(ROS_TYPES[parts[-1]])
            if (
                len(parts) >= 2
                and parts[-2] == "ParameterType"
                and parts[-1].startswith("PARAMETER_")
            ):
                key = parts[-1].removeprefix("PARAMETER_")
                if key in ROS_TYPES:
                    return TypeMarker(ROS_TYPES[key])
            enum = ".".join(parts[-2:])
            if enum in RCLPY_ENUMS and (len(parts) == 2 or parts[-3] == "qos"):
                return RCLPY_ENUMS[enum]
            if head in ("math", *_NUMPY) and rest in MATH:
                return MATH[rest]
            if head in ("os", "environ") and "environ" in name:
                raise UntranslatableError(node, "a value read from the environment")
            if head in ("self", self.scope.class_name) and rest in self.scope.class_constants:
                return self.bound(self.scope.class_constants[rest])
            space, _, attribute = name.rpartition(".")
            if attribute in self.scope.namespaces.get(space, {}):
                return self.bound(self.scope.namespaces[space][attribute])
            if head == "self" and "." not in rest:  # self.rate = 10.0 earlier in the method
                assigned = last_before(self.scope.local.get(name, []), node)
                if isinstance(assigned, ast.Assign) and len(assigned.targets) == 1:
                    return self.value(assigned.value)
            if head == "self":
                raise UntranslatableError(node, f"the attribute {name!r}")
            if head in self.scope.outside:
                raise NotReadError(node, name, self.scope.outside[head])
        raise UntranslatableError(node, f"the expression {unparsed(node)!r}")

    def _call(self, node: ast.Call) -> Any:
        function = dotted_name(node.func) or ""
        last = function.rpartition(".")[2]
        helper = self.scope.functions.get(function)
        if helper is not None:
            return self._inlined(helper, node, method=function.startswith("self."))
        if last == "ParameterDescriptor":
            return self._descriptor(node)
        if last in ("FloatingPointRange", "IntegerRange"):
            return self._range(node, integer=last == "IntegerRange")
        if function in _BUILTINS and not node.keywords and len(node.args) <= 1:
            arguments = [self.value(a) for a in node.args]  # ``float()`` is 0.0
            try:
                return _BUILTINS[function](*arguments)
            except (TypeError, ValueError):
                pass
        if last == _SHARE and len(node.args) == 1 and not node.keywords:
            package = self.value(node.args[0])
            if isinstance(package, str):
                return SharePath(f"$(find-pkg-share {package})")
        if function in ("os.path.join", "path.join", "join") and node.args:
            parts = [self.value(a) for a in node.args]
            if all(isinstance(p, str) for p in parts) and not node.keywords:
                joined = os.path.join(*parts)
                return SharePath(joined) if isinstance(parts[0], SharePath) else joined
        if function == "len" and len(node.args) == 1:
            sized = self.value(node.args[0])
            if isinstance(sized, (list, tuple, str, dict)):
                return len(sized)
        computed = _FUNCTIONS.get(function.replace("numpy.", "math.").replace("np.", "math."))
        if computed is not None and node.args and not node.keywords:
            arguments = [self.value(a) for a in node.args]
            if all(_is_number(a) for a in arguments):
                try:
                    result = computed(*arguments)
                except (ArithmeticError, TypeError, ValueError):
                    pass
                else:  # numpy rounds to a float (np.floor(2.5) is 2.0), math to an int
                    numpy = function.startswith(("np.", "numpy.")) and last in ("floor", "ceil")
                    return float(result) if numpy else result
        if function in ("os.getenv", "getenv") or "environ" in function:
            raise UntranslatableError(node, "a value read from the environment")
        if last in ("get_parameter", "get_parameter_or", "get_parameters"):
            raise UntranslatableError(node, "a value read from another parameter")
        if isinstance(node.func, ast.Attribute) and node.func.attr in ("items", "keys", "values"):
            mapping = self.value(node.func.value)
            if isinstance(mapping, dict) and not node.args:
                return list(getattr(mapping, node.func.attr)())
        if function == "range" and node.args and not node.keywords:
            bounds = [self.value(a) for a in node.args]
            if all(isinstance(b, int) and not isinstance(b, bool) for b in bounds):
                return list(range(*bounds))
        raise UntranslatableError(node, f"a call of {unparsed(node.func)}()")

    def _inlined(self, helper: ast.FunctionDef, call: ast.Call, *, method: bool) -> Any:
        """The value a helper returns, when its body is one ``return`` (after a docstring)."""
        body = helper.body
        if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
            body = body[1:]
        spec = helper.args
        if (
            len(body) != 1
            or not isinstance(body[0], ast.Return)
            or body[0].value is None
            or spec.vararg
            or spec.kwarg
            or spec.posonlyargs
            or any(k.arg is None for k in call.keywords)
        ):
            raise UntranslatableError(call, f"a call of {unparsed(call.func)}()")
        names = [a.arg for a in spec.args][1 if method else 0 :]
        names += [a.arg for a in spec.kwonlyargs]
        defaults = dict(
            zip([a.arg for a in spec.args][-len(spec.defaults) :], spec.defaults, strict=False)
        )
        defaults.update(
            {
                a.arg: d
                for a, d in zip(spec.kwonlyargs, spec.kw_defaults, strict=False)
                if d is not None
            }
        )
        if len(call.args) > len(names) - len(spec.kwonlyargs):
            raise UntranslatableError(call, f"a call of {unparsed(call.func)}()")
        bound: dict[str, Any] = {}
        for name, argument in zip(names, call.args, strict=False):
            bound[name] = self.value(argument)
        for keyword in call.keywords:
            if keyword.arg is not None:  # ``**kwargs`` was refused above
                bound[keyword.arg] = self.value(keyword.value)
        outer = self.scope
        try:
            self.scope = replace(outer, loop={}, local={})
            for name in names:
                if name not in bound:
                    if name not in defaults:
                        raise UntranslatableError(call, f"a call of {unparsed(call.func)}()")
                    bound[name] = self.value(defaults[name])
            self.scope = replace(outer, loop=bound, local={})
            return self.value(body[0].value)
        finally:
            self.scope = outer

    def _descriptor(self, node: ast.Call) -> DescriptorValue:
        descriptor = DescriptorValue()
        if node.args:
            raise UntranslatableError(node, "a ParameterDescriptor with positional arguments")
        for keyword in node.keywords:
            if keyword.arg is None:
                raise UntranslatableError(node, "a ParameterDescriptor built from **arguments")
            self._descriptor_field(descriptor, keyword.arg, keyword.value)
        return descriptor

    def _descriptor_field(self, descriptor: DescriptorValue, name: str, node: ast.expr) -> None:
        if name not in DESCRIPTOR_FIELDS:
            descriptor.failed[name] = UntranslatableError(node, f"the descriptor field {name!r}")
            return
        try:
            descriptor.fields[name] = self.value(node)
            descriptor.failed.pop(name, None)
        except UntranslatableError as exc:
            descriptor.failed[name] = exc
            descriptor.fields.pop(name, None)

    def _range(self, node: ast.Call, *, integer: bool) -> RangeValue:
        values: dict[str, Any] = dict.fromkeys(RANGE_FIELDS, 0)
        if len(node.args) > len(RANGE_FIELDS):
            raise UntranslatableError(node, f"the range {unparsed(node)!r}")
        for name, argument in zip(RANGE_FIELDS, node.args, strict=False):
            values[name] = self.value(argument)
        for keyword in node.keywords:
            if keyword.arg not in RANGE_FIELDS:
                raise UntranslatableError(node, f"the range {unparsed(node)!r}")
            values[keyword.arg] = self.value(keyword.value)
        if not all(_is_number(v) for v in values.values()):
            raise UntranslatableError(node, f"the range {unparsed(node)!r}")
        return RangeValue(integer, values["from_value"], values["to_value"], values["step"])

    def _parameter_read(self, node: ast.Attribute) -> Any:
        """The value of a parameter declared before that ``node`` reads (``read_call``),
        when the scope offers them."""
        call = read_call(node, self.scope) if self.scope.parameters else None
        if call is None:
            return None
        name = self.value(call.args[0])
        if not isinstance(name, str) or name not in self.scope.parameters:
            return None
        self.parameters_read.append(name)
        value = self.scope.parameters[name]
        return list(value) if isinstance(value, list) else value


def _repeated(op: ast.operator, left: Any, right: Any) -> bool:
    """``[0.0] * n`` (or ``n * [0.0]``) of a bounded length."""
    if not isinstance(op, ast.Mult):
        return False
    items, count = (left, right) if isinstance(left, list) else (right, left)
    return (
        isinstance(items, list)
        and isinstance(count, int)
        and not isinstance(count, bool)
        and count >= 0
        and computable(op, items, count)
    )


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _same_kind(left: Any, right: Any) -> bool:
    if _is_number(left) and _is_number(right):
        return True
    if isinstance(left, str) and isinstance(right, str):
        return True
    return isinstance(left, list) and isinstance(right, list)
