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
import operator
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

from genparams.errors import GenparamsError

# rclpy's Parameter.Type members (and rcl_interfaces' ParameterType constants) -> schema types.
ROS_TYPES = {
    "BOOL": "bool",
    "INTEGER": "int",
    "DOUBLE": "double",
    "STRING": "string",
    "BYTE_ARRAY": "byte_array",
    "BOOL_ARRAY": "bool_array",
    "INTEGER_ARRAY": "int_array",
    "DOUBLE_ARRAY": "double_array",
    "STRING_ARRAY": "string_array",
    "NOT_SET": "not_set",
}
DESCRIPTOR_FIELDS = (
    "name",
    "type",
    "description",
    "additional_constraints",
    "read_only",
    "dynamic_typing",
    "floating_point_range",
    "integer_range",
)
_RANGE_FIELDS = ("from_value", "to_value", "step")
_BINARY: dict[type[ast.operator], Callable[[Any, Any], Any]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv,
    ast.Mod: operator.mod,
    ast.Pow: operator.pow,
}
_MATH = {"pi": math.pi, "e": math.e, "tau": math.tau, "inf": math.inf, "nan": math.nan}
# rclpy's QoS policy enums, often a parameter's default (an IntEnum: rclpy declares an int).
RCLPY_ENUMS = {
    **{f"QoSReliabilityPolicy.{k}": v for k, v in
       {"SYSTEM_DEFAULT": 0, "RELIABLE": 1, "BEST_EFFORT": 2, "BEST_AVAILABLE": 4}.items()},
    **{f"QoSDurabilityPolicy.{k}": v for k, v in
       {"SYSTEM_DEFAULT": 0, "TRANSIENT_LOCAL": 1, "VOLATILE": 2, "BEST_AVAILABLE": 4}.items()},
    **{f"QoSHistoryPolicy.{k}": v for k, v in
       {"SYSTEM_DEFAULT": 0, "KEEP_LAST": 1, "KEEP_ALL": 2}.items()},
    **{f"QoSLivelinessPolicy.{k}": v for k, v in
       {"SYSTEM_DEFAULT": 0, "AUTOMATIC": 1, "MANUAL_BY_TOPIC": 3, "BEST_AVAILABLE": 5}.items()},
}  # fmt: skip
_MAX_DEPTH = 32  # constants defined through constants, never in a loop


class UntranslatableError(GenparamsError):
    """A construct the import cannot turn into a value; ``what`` names it for a warning."""

    def __init__(self, node: ast.AST, what: str) -> None:
        super().__init__(what)
        self.node = node
        self.what = what


@dataclass(frozen=True)
class TypeMarker:
    """``Parameter.Type.DOUBLE``: a type given instead of a value."""

    schema_type: str


@dataclass(frozen=True)
class RangeValue:
    integer: bool
    from_value: float
    to_value: float
    step: float


@dataclass
class DescriptorValue:
    """A ParameterDescriptor(...) as the source builds it: fields read, and fields that
    could not be read with the reason."""

    fields: dict[str, Any] = field(default_factory=dict)
    failed: dict[str, UntranslatableError] = field(default_factory=dict)


@dataclass
class Scope:
    """Where names resolve: loop variables, the function's own variables, the class's
    constants, the module's constants."""

    loop: Mapping[str, Any] = field(default_factory=dict)
    local: Mapping[str, list[ast.stmt]] = field(default_factory=dict)  # assignments
    class_name: str | None = None
    class_constants: Mapping[str, ast.expr] = field(default_factory=dict)
    module_constants: Mapping[str, ast.expr] = field(default_factory=dict)
    # Helpers that build a value (``def ranged(lo, hi): return ParameterDescriptor(...)``):
    # the module's functions, the class's methods (as "self.name") and nested functions.
    functions: Mapping[str, ast.FunctionDef] = field(default_factory=dict)

    def with_loop(self, bindings: Mapping[str, Any]) -> Scope:
        return replace(self, loop={**self.loop, **bindings})


def unparsed(node: ast.AST, limit: int = 60) -> str:
    text = ast.unparse(node)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def dotted_name(node: ast.AST) -> str | None:
    """``a.b.c`` for a chain of attributes on a name, else None."""
    parts: list[str] = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name):
        parts.append(node.id)
        return ".".join(reversed(parts))
    return None


def assigned_once_before(node: ast.AST, scope: Scope) -> ast.Assign | None:
    """The one assignment of the variable ``node`` (``v`` or ``self.v``) in the function,
    when it ends before this use."""
    key = dotted_name(node)
    if key is None or key.count(".") > 1 or ("." in key and not key.startswith("self.")):
        return None
    assigned = scope.local.get(key, [])
    if len(assigned) != 1:
        return None
    statement = assigned[0]
    end = (statement.end_lineno or statement.lineno, statement.end_col_offset or 0)
    if end > (getattr(node, "lineno", 0), getattr(node, "col_offset", 0)):
        return None
    if not isinstance(statement, ast.Assign) or len(statement.targets) != 1:
        return None
    return statement


class Evaluator:
    def __init__(self, scope: Scope) -> None:
        self.scope = scope
        self.depth = 0

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
        if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
            left, right = self.value(node.left), self.value(node.right)
            if _same_kind(left, right) and not _too_large(node.op, left, right):
                try:
                    return _BINARY[type(node.op)](left, right)
                except (ArithmeticError, TypeError, ValueError):
                    pass
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
        parts = []
        for part in node.values:
            if isinstance(part, ast.Constant):
                parts.append(str(part.value))
            elif isinstance(part, ast.FormattedValue):
                if part.format_spec is not None or part.conversion != -1:
                    raise UntranslatableError(part, f"the formatted value {unparsed(node)!r}")
                parts.append(str(self.value(part.value)))
        return "".join(parts)

    def _name(self, node: ast.Name) -> Any:
        scope = self.scope
        if node.id in scope.loop:
            return scope.loop[node.id]
        assigned = _last_before(scope.local.get(node.id, []), node)
        if assigned is not None:
            return self._assigned(assigned, node)
        if node.id in scope.module_constants:
            return self.value(scope.module_constants[node.id])
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
            if not _before(statement, use):
                continue
            assert isinstance(statement, ast.Assign)
            target = statement.targets[0]
            assert isinstance(target, ast.Attribute)
            self._descriptor_field(descriptor, target.attr, statement.value)

    def _attribute(self, node: ast.Attribute) -> Any:
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
            if head == "math" and rest in _MATH:
                return _MATH[rest]
            if head in ("os", "environ") and "environ" in name:
                raise UntranslatableError(node, "a value read from the environment")
            if head in ("self", self.scope.class_name) and rest in self.scope.class_constants:
                return self.value(self.scope.class_constants[rest])
            if head == "self" and "." not in rest:  # self.rate = 10.0 earlier in the method
                assigned = _last_before(self.scope.local.get(name, []), node)
                if isinstance(assigned, ast.Assign) and len(assigned.targets) == 1:
                    return self.value(assigned.value)
            if head == "self":
                raise UntranslatableError(node, f"the attribute {name!r}")
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
        if function in ("float", "int", "str", "bool") and len(node.args) == 1:
            argument = self.value(node.args[0])
            try:
                return {"float": float, "int": int, "str": str, "bool": bool}[function](argument)
            except (TypeError, ValueError):
                pass
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
            assert keyword.arg is not None
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
        values: dict[str, Any] = dict.fromkeys(_RANGE_FIELDS, 0)
        if len(node.args) > len(_RANGE_FIELDS):
            raise UntranslatableError(node, f"the range {unparsed(node)!r}")
        for name, argument in zip(_RANGE_FIELDS, node.args, strict=False):
            values[name] = self.value(argument)
        for keyword in node.keywords:
            if keyword.arg not in _RANGE_FIELDS:
                raise UntranslatableError(node, f"the range {unparsed(node)!r}")
            values[keyword.arg] = self.value(keyword.value)
        if not all(_is_number(v) for v in values.values()):
            raise UntranslatableError(node, f"the range {unparsed(node)!r}")
        return RangeValue(integer, values["from_value"], values["to_value"], values["step"])


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _same_kind(left: Any, right: Any) -> bool:
    if _is_number(left) and _is_number(right):
        return True
    if isinstance(left, str) and isinstance(right, str):
        return True
    return isinstance(left, list) and isinstance(right, list)


def _too_large(op: ast.operator, left: Any, right: Any) -> bool:
    """A power whose result could exhaust memory or time (``10 ** 10 ** 9``) is not computed."""
    return isinstance(op, ast.Pow) and _is_number(right) and abs(right) > 64


def _before(statement: ast.stmt, use: ast.AST) -> bool:
    """Whether ``statement`` ends before ``use`` starts (``x = f(x)`` does not precede its
    own ``x``)."""
    end = (
        getattr(statement, "end_lineno", None) or statement.lineno,
        getattr(statement, "end_col_offset", None) or statement.col_offset,
    )
    return end <= (getattr(use, "lineno", 0), getattr(use, "col_offset", 0))


def _last_before(statements: list[ast.stmt], use: ast.AST) -> ast.stmt | None:
    earlier = [s for s in statements if _before(s, use)]
    return earlier[-1] if earlier else None
