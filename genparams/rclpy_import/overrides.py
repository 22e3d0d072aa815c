"""The keys a node finds under a prefix in its overrides, as hand-written nodes compute them.

A node that takes its sensors from the params file (``sensors.front.topic``,
``sensors.rear.topic``) finds the names ``front`` and ``rear`` in one of two ways:

- from its overrides, which rclpy keeps by full name:
  ``{n.split(".")[1] for n in self._parameter_overrides if n.startswith("sensors.")}``
- from the parameters declared under the prefix (every override is, on a node built with
  ``automatically_declare_parameters_from_overrides=True``), which rclpy gives relative to
  it: ``{k.split(".")[0] for k in self.get_parameters_by_prefix("sensors")}``

either as a set, list or generator comprehension, maybe in ``sorted()``, ``set()``,
``list()`` or ``tuple()``, maybe through a variable assigned once before its use.
``keys_under`` recognises these and gives the prefix, so that declarations and reads of
``sensors.<key>.<field>`` in a loop over them become an open group
(``sensors: {for_each: overrides, ...}``).
"""

from __future__ import annotations

import ast
from dataclasses import dataclass

from genparams.rclpy_import.values import (
    Evaluator,
    Scope,
    UntranslatableError,
    assigned_once_before,
)

BY_PREFIX = "get_parameters_by_prefix"
OVERRIDES = "_parameter_overrides"
_WRAPPERS = ("sorted", "set", "list", "tuple", "frozenset")
_MAX_HOPS = 4  # variables assigned from variables


@dataclass(frozen=True)
class KeysUnder:
    """Keys found under ``prefix`` in the overrides; ``source`` is the by-prefix call or
    the ``_parameter_overrides`` attribute they are read from."""

    prefix: str
    source: ast.AST


def keys_under(node: ast.AST, scope: Scope, depth: int = 0) -> KeysUnder | None:
    """The prefix whose keys ``node`` computes from the overrides, or None."""
    if depth > _MAX_HOPS:
        return None
    if (
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Name)
        and node.func.id in _WRAPPERS
        and len(node.args) == 1
        and not node.keywords
    ):
        return keys_under(node.args[0], scope, depth + 1)
    if isinstance(node, (ast.SetComp, ast.ListComp, ast.GeneratorExp)):
        return _comprehension(node, scope)
    statement = assigned_once_before(node, scope)
    if statement is None:
        return None
    return keys_under(statement.value, scope, depth + 1)


_OWN = ("_parameters", OVERRIDES)  # rclpy's tables of a node's parameters, by full name


def over_own_parameters(node: ast.AST) -> bool:
    """``self._parameters`` or ``self._parameter_overrides`` (maybe ``.keys()``, maybe in
    ``sorted()`` and the like): the names of the node's own parameters."""
    while isinstance(node, ast.Call) and not node.keywords:
        func = node.func
        if isinstance(func, ast.Name) and func.id in _WRAPPERS and len(node.args) == 1:
            node = node.args[0]
        elif isinstance(func, ast.Attribute) and func.attr == "keys" and not node.args:
            node = func.value
        else:
            return False
    return isinstance(node, ast.Attribute) and node.attr in _OWN


_PURE = ("split", "partition", "startswith", "keys", BY_PREFIX)


def reads_overrides(node: ast.AST) -> bool:
    """Whether ``node`` reads the overrides (``_parameter_overrides``, a by-prefix call) and
    calls nothing but the string methods and wrappers keys are computed with: a variable
    holding it can go with its last use."""
    reads = False
    for child in ast.walk(node):
        if isinstance(child, ast.Attribute) and child.attr == OVERRIDES:
            reads = True
        elif isinstance(child, ast.Call):
            func = child.func
            if isinstance(func, ast.Attribute) and func.attr in _PURE:
                reads = reads or func.attr == BY_PREFIX
            elif not (isinstance(func, ast.Name) and func.id in _WRAPPERS):
                return False
    return reads


def _comprehension(
    node: ast.SetComp | ast.ListComp | ast.GeneratorExp, scope: Scope
) -> KeysUnder | None:
    if len(node.generators) != 1:
        return None
    generator = node.generators[0]
    if generator.is_async or not isinstance(generator.target, ast.Name):
        return None
    variable = generator.target.id
    index = _segment(node.elt, variable)
    if index is None:
        return None
    by_prefix = _by_prefix(generator.iter, scope)
    if by_prefix is not None:
        prefix, call = by_prefix
        if index != 0 or not prefix or generator.ifs:
            return None
        return KeysUnder(prefix, call)
    source = _without_keys(generator.iter)
    if not (isinstance(source, ast.Attribute) and source.attr == OVERRIDES):
        return None
    if len(generator.ifs) != 1:
        return None
    under = _starts_with(generator.ifs[0], variable, scope)
    if under is None or index != len(under.split(".")):
        return None
    return KeysUnder(under, source)


def _segment(node: ast.AST, variable: str) -> int | None:
    """``v.split(".")[i]`` (``v.split(".", n)[i]``, ``v.partition(".")[0]``): i."""
    if not isinstance(node, ast.Subscript):
        return None
    index = node.slice
    if not (isinstance(index, ast.Constant) and type(index.value) is int and index.value >= 0):
        return None
    call = node.value
    if not (
        isinstance(call, ast.Call)
        and isinstance(call.func, ast.Attribute)
        and isinstance(call.func.value, ast.Name)
        and call.func.value.id == variable
        and not call.keywords
        and call.args
        and isinstance(call.args[0], ast.Constant)
        and call.args[0].value == "."
    ):
        return None
    method, count = call.func.attr, index.value
    if method == "partition" and len(call.args) == 1:
        return 0 if count == 0 else None
    if method != "split" or len(call.args) > 2:
        return None
    if len(call.args) == 2:
        limit = call.args[1]
        if not (isinstance(limit, ast.Constant) and type(limit.value) is int):
            return None
        if not 0 <= count < limit.value:  # the last piece holds the rest of the name
            return None
    return count


def _without_keys(node: ast.AST) -> ast.AST:
    """``x.keys()`` -> ``x``."""
    if (
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and node.func.attr == "keys"
        and not node.args
        and not node.keywords
    ):
        return node.func.value
    return node


def _by_prefix(node: ast.AST, scope: Scope, depth: int = 0) -> tuple[str, ast.Call] | None:
    """``x.get_parameters_by_prefix("sensors")`` (or ``.keys()`` of it, or a variable
    assigned from it): the prefix and the call."""
    node = _without_keys(node)
    if isinstance(node, ast.Call):
        if not (
            isinstance(node.func, ast.Attribute)
            and node.func.attr == BY_PREFIX
            and len(node.args) == 1
            and not node.keywords
        ):
            return None
        try:
            prefix = Evaluator(scope).value(node.args[0])
        except UntranslatableError:
            return None
        return (prefix, node) if isinstance(prefix, str) else None
    statement = assigned_once_before(node, scope)
    if statement is None or depth >= _MAX_HOPS:
        return None
    return _by_prefix(statement.value, scope, depth + 1)


def _starts_with(test: ast.AST, variable: str, scope: Scope) -> str | None:
    """``v.startswith("sensors.")``: ``sensors``."""
    if not (
        isinstance(test, ast.Call)
        and isinstance(test.func, ast.Attribute)
        and test.func.attr == "startswith"
        and isinstance(test.func.value, ast.Name)
        and test.func.value.id == variable
        and len(test.args) == 1
        and not test.keywords
    ):
        return None
    try:
        text = Evaluator(scope).value(test.args[0])
    except UntranslatableError:
        return None
    if not isinstance(text, str) or not text.endswith(".") or len(text) < 2:
        return None
    return text[:-1]
