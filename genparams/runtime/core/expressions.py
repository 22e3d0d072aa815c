"""The expression language of cross-parameter rules: parsed, typed, compiled to closures.

A check is read with ``ast.parse(..., mode="eval")``, which only parses, and every
node of the tree is then checked against a whitelist and turned into a closure.
Schema text is never passed to ``eval``, ``exec`` or ``compile``-to-code: anything
outside the whitelist is refused, so an expression can only read parameters, never
run code.

The language: dotted parameter names (``camera.width``; a Python keyword is written
with a trailing underscore, as in the typed view), numbers, strings, ``true`` /
``false`` (or ``True`` / ``False``), tuple and list literals, ``+ - * / // %`` and
unary ``-`` / ``+``, comparisons (chained too, and ``in`` / ``not in``),
``and`` / ``or`` / ``not``, ``x if c else y``, and the functions ``abs``, ``min``,
``max`` and ``len``. Every expression is typed before it runs (numbers, strings,
bools, byte strings and arrays of them), so ``len(fps)`` or ``name < 3`` are errors
when the schema is checked, not surprises at run time.

Pure Python, shared by the code generator and the runtime.
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from genparams.runtime.core.errors import GenparamsError
from genparams.runtime.core.expression_words import (
    ARITHMETIC,
    ARRAYS,
    EQUALITY,
    FORBIDDEN,
    FUNCTIONS,
    KIND_OF_TYPE,
    MEMBERSHIP,
    ORDERING,
    kind_words,
)
from genparams.runtime.core.naming import attribute_parts
from genparams.runtime.core.suggest import did_you_mean

MAX_CHECK_LENGTH = 2000

Values = Mapping[str, Any]
Evaluator = Callable[[Values], Any]


class RuleError(GenparamsError, ValueError):
    """A rule's check is not a valid expression of the language; ``offset`` is 0-based."""

    def __init__(self, message: str, offset: int | None = None) -> None:
        self.offset = offset
        self.unknown_name: str | None = None  # a name that is no parameter, as spelled
        where = f" (at character {offset + 1})" if offset is not None else ""
        super().__init__(f"{message}{where}")


@dataclass(frozen=True)
class Expression:
    """A checked, compiled expression: call ``evaluate`` with values by ROS name."""

    text: str
    kind: str
    parameters: tuple[str, ...]  # ROS names, in order of first appearance
    evaluate: Evaluator


def compile_expression(text: str, parameter_types: Mapping[str, str]) -> Expression:
    if len(text) > MAX_CHECK_LENGTH:
        raise RuleError(f"a check is limited to {MAX_CHECK_LENGTH} characters")
    # Checks may span lines in YAML; one space per line break keeps every offset.
    flat = text.replace("\r", " ").replace("\n", " ")
    source = flat.lstrip()  # the parser takes leading blanks for an indent
    shift = len(flat) - len(source)
    if not source:
        raise RuleError("a check cannot be empty")
    try:
        tree = ast.parse(source, mode="eval")
    except SyntaxError as exc:
        offset = (exc.offset - 1 + shift) if exc.offset else None
        raise RuleError(f"invalid expression: {exc.msg}", offset) from None
    except (RecursionError, MemoryError, ValueError):
        raise RuleError("invalid expression: too deeply nested or malformed") from None
    compiler = _Compiler(source, shift, parameter_types)
    try:
        kind, evaluate = compiler.compile(tree.body)
    except RecursionError:
        raise RuleError("invalid expression: too deeply nested") from None
    return Expression(text, kind, tuple(compiler.used), evaluate)


class _Compiler:
    def __init__(self, text: str, shift: int, parameter_types: Mapping[str, str]) -> None:
        self.encoded = text.encode("utf-8")
        self.shift = shift
        # Expression spelling (attribute names joined by dots) -> ROS name.
        self.spellings = {
            ".".join(attribute_parts(ros_name)): ros_name for ros_name in parameter_types
        }
        # A parameter of type ``any`` has no fixed kind: found, but refused where read.
        self.kinds = {name: KIND_OF_TYPE.get(t, "") for name, t in parameter_types.items()}
        self.used: dict[str, None] = {}  # ordered set
        self.handlers: dict[type[ast.expr], Callable[[Any], tuple[str, Evaluator]]] = {
            ast.Constant: self.constant,
            ast.Name: self.name,
            ast.Attribute: self.attribute,
            ast.Tuple: self.sequence,
            ast.List: self.sequence,
            ast.UnaryOp: self.unary,
            ast.BinOp: self.arithmetic,
            ast.BoolOp: self.boolean,
            ast.Compare: self.compare,
            ast.IfExp: self.conditional,
            ast.Call: self.call,
        }

    def error(self, node: ast.AST, message: str) -> RuleError:
        byte_offset = getattr(node, "col_offset", None)
        if byte_offset is None:
            return RuleError(message)
        characters = len(self.encoded[:byte_offset].decode("utf-8", "replace"))
        return RuleError(message, characters + self.shift)

    def compile(self, node: ast.expr) -> tuple[str, Evaluator]:
        """The kind of ``node`` and a closure computing it; anything unlisted is refused."""
        handler = self.handlers.get(type(node))
        if handler is None:
            what = FORBIDDEN.get(type(node), type(node).__name__)
            raise self.error(node, f"rules cannot use {what}")
        return handler(node)

    def constant(self, node: ast.Constant) -> tuple[str, Evaluator]:
        value = node.value
        if isinstance(value, bool):
            kind = "bool"
        elif isinstance(value, (int, float)):
            kind = "number"
        elif isinstance(value, str):
            kind = "string"
        else:
            raise self.error(node, f"rules cannot use the constant {value!r}")
        return kind, lambda values: value

    def name(self, node: ast.Name) -> tuple[str, Evaluator]:
        if node.id in ("true", "false"):  # YAML spelling, for readers of params files
            flag = node.id == "true"
            return "bool", lambda values: flag
        return self.parameter(node, node.id)

    def attribute(self, node: ast.Attribute) -> tuple[str, Evaluator]:
        parts = [node.attr]
        base: ast.expr = node.value
        while isinstance(base, ast.Attribute):
            parts.append(base.attr)
            base = base.value
        if not isinstance(base, ast.Name):
            raise self.error(
                node, "attribute access is not allowed: only dotted parameter names such as a.b"
            )
        parts.append(base.id)
        return self.parameter(node, ".".join(reversed(parts)))

    def parameter(self, node: ast.expr, spelling: str) -> tuple[str, Evaluator]:
        ros_name = self.spellings.get(spelling)
        if ros_name is None:
            error = self.error(node, self.unknown(spelling))
            error.unknown_name = spelling
            raise error
        if not self.kinds[ros_name]:
            raise self.error(
                node, f"{spelling!r} is of type any: its type is not fixed, so no rule can read it"
            )
        self.used[ros_name] = None
        return self.kinds[ros_name], lambda values: values[ros_name]

    def unknown(self, spelling: str) -> str:
        parts = spelling.split(".")
        for cut in range(len(parts) - 1, 0, -1):
            head = ".".join(parts[:cut])
            if head in self.spellings:
                return (
                    f"{spelling!r} is not a parameter: attribute access is not allowed "
                    f"({head!r} is a parameter)"
                )
        if spelling in FUNCTIONS:
            return f"{spelling!r} is a function: call it, as in {spelling}(...)"
        return f"unknown parameter {spelling!r}{did_you_mean(spelling, self.spellings)}"

    def sequence(self, node: ast.Tuple | ast.List) -> tuple[str, Evaluator]:
        items = [self.compile(item) for item in node.elts]
        kinds = {kind for kind, _ in items}
        if not items or len(kinds) != 1 or next(iter(kinds)) not in ("bool", "number", "string"):
            raise self.error(
                node, "a literal list needs at least one item, all numbers, strings or bools"
            )
        evaluators = [evaluate for _, evaluate in items]
        return f"{kinds.pop()}[]", lambda values: tuple(e(values) for e in evaluators)

    def unary(self, node: ast.UnaryOp) -> tuple[str, Evaluator]:
        kind, operand = self.compile(node.operand)
        if isinstance(node.op, ast.Not):
            self.expect(node.operand, kind, "bool", "'not'")
            return "bool", lambda values: not operand(values)
        if isinstance(node.op, (ast.USub, ast.UAdd)):
            self.expect(node.operand, kind, "number", "unary minus or plus")
            if isinstance(node.op, ast.USub):
                return "number", lambda values: -operand(values)
            return "number", operand
        raise self.error(node, f"rules cannot use {FORBIDDEN[type(node.op)]}")

    def arithmetic(self, node: ast.BinOp) -> tuple[str, Evaluator]:
        entry = ARITHMETIC.get(type(node.op))
        if entry is None:
            raise self.error(node, f"rules cannot use {FORBIDDEN[type(node.op)]}")
        symbol, apply = entry
        left_kind, left = self.compile(node.left)
        right_kind, right = self.compile(node.right)
        self.expect(node.left, left_kind, "number", f"the operator {symbol}")
        self.expect(node.right, right_kind, "number", f"the operator {symbol}")
        return "number", lambda values: apply(left(values), right(values))

    def boolean(self, node: ast.BoolOp) -> tuple[str, Evaluator]:
        word = "and" if isinstance(node.op, ast.And) else "or"
        operands = []
        for item in node.values:
            kind, evaluate = self.compile(item)
            self.expect(item, kind, "bool", f"'{word}'")
            operands.append(evaluate)
        if word == "and":
            return "bool", lambda values: all(o(values) for o in operands)
        return "bool", lambda values: any(o(values) for o in operands)

    def compare(self, node: ast.Compare) -> tuple[str, Evaluator]:
        operands = [self.compile(node.left), *(self.compile(c) for c in node.comparators)]
        nodes = [node.left, *node.comparators]
        steps: list[tuple[Callable[[Any, Any], bool], Evaluator, Evaluator]] = []
        for index, op in enumerate(node.ops):
            (left_kind, left), (right_kind, right) = operands[index], operands[index + 1]
            apply = self.comparison(nodes[index], op, left_kind, right_kind)
            steps.append((apply, left, right))
        if len(steps) == 1:
            ((apply, left, right),) = steps
            return "bool", lambda values: apply(left(values), right(values))

        def chained(values: Values) -> bool:
            # Like Python: each operand is evaluated once, and evaluation stops at the first false.
            current = steps[0][1](values)
            for apply, _, right in steps:
                following = right(values)
                if not apply(current, following):
                    return False
                current = following
            return True

        return "bool", chained

    def comparison(
        self, node: ast.expr, op: ast.cmpop, left: str, right: str
    ) -> Callable[[Any, Any], bool]:
        if type(op) in ORDERING:
            symbol, apply = ORDERING[type(op)]
            if left != right or left not in ("number", "string"):
                raise self.error(
                    node,
                    f"{symbol} compares two numbers or two strings, "
                    f"not {kind_words(left)} and {kind_words(right)}",
                )
            return apply
        if type(op) in EQUALITY:
            symbol, apply = EQUALITY[type(op)]
            if left != right:
                raise self.error(
                    node,
                    f"{symbol} compares values of one kind, "
                    f"not {kind_words(left)} and {kind_words(right)}",
                )
            return apply
        if type(op) in MEMBERSHIP:
            symbol, apply = MEMBERSHIP[type(op)]
            if right != f"{left}[]" and not (left == right == "string"):
                raise self.error(
                    node,
                    f"'{symbol}' needs an item and an array of its kind (or two strings), "
                    f"not {kind_words(left)} and {kind_words(right)}",
                )
            return apply
        raise self.error(node, f"rules cannot use {FORBIDDEN[type(op)]}")

    def conditional(self, node: ast.IfExp) -> tuple[str, Evaluator]:
        test_kind, test = self.compile(node.test)
        self.expect(node.test, test_kind, "bool", "the condition of 'if'")
        body_kind, body = self.compile(node.body)
        else_kind, orelse = self.compile(node.orelse)
        if body_kind != else_kind:
            raise self.error(
                node,
                f"both branches of 'if' must be of one kind, "
                f"not {kind_words(body_kind)} and {kind_words(else_kind)}",
            )
        return body_kind, lambda values: body(values) if test(values) else orelse(values)

    def call(self, node: ast.Call) -> tuple[str, Evaluator]:
        allowed = ", ".join(FUNCTIONS)
        if not isinstance(node.func, ast.Name):
            raise self.error(node, f"rules cannot call methods: the functions are {allowed}")
        function = node.func.id
        if function not in FUNCTIONS:
            raise self.error(node, f"rules cannot call {function!r}: the functions are {allowed}")
        if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
            raise self.error(node, f"{function}() takes plain positional arguments")
        arguments = [self.compile(a) for a in node.args]
        kinds = [kind for kind, _ in arguments]
        evaluators = [evaluate for _, evaluate in arguments]
        if function == "abs" and kinds == ["number"]:
            (value,) = evaluators
            return "number", lambda values: abs(value(values))
        if function == "len" and len(kinds) == 1 and kinds[0] in ("string", "bytes", *ARRAYS):
            (value,) = evaluators
            return "number", lambda values: len(value(values))
        if function in ("min", "max"):
            pick = min if function == "min" else max
            if kinds == ["number[]"]:
                (value,) = evaluators
                return "number", lambda values: pick(value(values))
            if len(kinds) >= 2 and all(kind == "number" for kind in kinds):
                return "number", lambda values: pick(e(values) for e in evaluators)
        expected = {
            "abs": "one number",
            "len": "one string or array",
            "min": "two or more numbers, or one array of numbers",
            "max": "two or more numbers, or one array of numbers",
        }[function]
        given = ", ".join(kind_words(kind) for kind in kinds) or "nothing"
        raise self.error(node, f"{function}() takes {expected}, not {given}")

    def expect(self, node: ast.expr, kind: str, wanted: str, used_by: str) -> None:
        if kind != wanted:
            raise self.error(node, f"{used_by} needs {kind_words(wanted)}, not {kind_words(kind)}")
