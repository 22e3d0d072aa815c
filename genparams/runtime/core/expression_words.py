"""The words of the rule expression language: its kinds of values, its functions, its
operators and how each is applied, and the readable names of what it leaves out.

``expressions`` compiles checks with these tables; messages word kinds with
``kind_words``.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from typing import Any

# Typed-view kinds of the nine parameter types; "T[]" is an array of T.
KIND_OF_TYPE = {
    "bool": "bool",
    "int": "number",
    "double": "number",
    "string": "string",
    "byte_array": "bytes",
    "bool_array": "bool[]",
    "int_array": "number[]",
    "double_array": "number[]",
    "string_array": "string[]",
}
KIND_WORDS = {
    "bool": "true/false",
    "number": "a number",
    "string": "a string",
    "bytes": "a byte array",
}

FUNCTIONS = ("abs", "len", "max", "min")

ARITHMETIC: dict[type[ast.operator], tuple[str, Callable[[Any, Any], Any]]] = {
    ast.Add: ("+", lambda a, b: a + b),
    ast.Sub: ("-", lambda a, b: a - b),
    ast.Mult: ("*", lambda a, b: a * b),
    ast.Div: ("/", lambda a, b: a / b),
    ast.FloorDiv: ("//", lambda a, b: a // b),
    ast.Mod: ("%", lambda a, b: a % b),
}
ORDERING: dict[type[ast.cmpop], tuple[str, Callable[[Any, Any], bool]]] = {
    ast.Lt: ("<", lambda a, b: a < b),
    ast.LtE: ("<=", lambda a, b: a <= b),
    ast.Gt: (">", lambda a, b: a > b),
    ast.GtE: (">=", lambda a, b: a >= b),
}
EQUALITY: dict[type[ast.cmpop], tuple[str, Callable[[Any, Any], bool]]] = {
    ast.Eq: ("==", lambda a, b: a == b),
    ast.NotEq: ("!=", lambda a, b: a != b),
}
MEMBERSHIP: dict[type[ast.cmpop], tuple[str, Callable[[Any, Any], bool]]] = {
    ast.In: ("in", lambda a, b: a in b),
    ast.NotIn: ("not in", lambda a, b: a not in b),
}
# Readable names for constructs outside the language.
FORBIDDEN = {
    ast.Pow: "the operator **",
    ast.MatMult: "the operator @",
    ast.BitAnd: "the operator &",
    ast.BitOr: "the operator |",
    ast.BitXor: "the operator ^",
    ast.LShift: "the operator <<",
    ast.RShift: "the operator >>",
    ast.Invert: "the operator ~",
    ast.Is: "'is' (use ==)",
    ast.IsNot: "'is not' (use !=)",
    ast.Subscript: "indexing",
    ast.Lambda: "lambda",
    ast.NamedExpr: "':='",
    ast.JoinedStr: "f-strings",
    ast.Dict: "dict literals",
    ast.Set: "set literals",
    ast.ListComp: "comprehensions",
    ast.SetComp: "comprehensions",
    ast.DictComp: "comprehensions",
    ast.GeneratorExp: "comprehensions",
    ast.Starred: "'*' unpacking",
    ast.Await: "await",
    ast.Yield: "yield",
    ast.YieldFrom: "yield",
    ast.Slice: "slices",
}

ARRAYS = ("bool[]", "number[]", "string[]")


def kind_words(kind: str) -> str:
    if kind.endswith("[]"):
        return f"an array of {kind[:-2]}"
    return KIND_WORDS.get(kind, kind)
