"""Cross-parameter rules: a named check over several parameters, and why values break it.

The code generator uses this module to check rules and the schema defaults
against them; the runtime to check every proposed change. The expression
language lives in genparams.runtime.core.expressions.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass

from genparams.runtime.core.expression_words import kind_words
from genparams.runtime.core.expressions import Expression, RuleError, Values, compile_expression

__all__ = ["CompiledRule", "RuleError", "compile_rule", "rules_by_parameter"]


@dataclass(frozen=True)
class CompiledRule:
    name: str
    check: str
    description: str
    expression: Expression

    @property
    def parameters(self) -> tuple[str, ...]:
        return self.expression.parameters

    def violation(self, values: Values, shown: Callable[[str], str] = str) -> str | None:
        """Why ``values`` break the rule, naming it and every value it read; None if they don't.

        ``shown`` turns a relative ROS name into the name to show (with the prefix).
        """
        failure = self.failure(values, shown)
        return None if failure is None else f"rule {self.name!r} broken: {failure}"

    def failure(self, values: Values, shown: Callable[[str], str] = str) -> str | None:
        if any(values[n] is None for n in self.parameters):
            return None  # it reads an optional parameter that is not set: nothing to check yet
        involved = ", ".join(f"{shown(n)}={values[n]!r}" for n in self.parameters)
        try:
            holds = self.expression.evaluate(values)
        except (ArithmeticError, ValueError, TypeError) as exc:
            return f"{self.check} cannot be evaluated for {involved}: {exc}"
        if holds is True:
            return None
        return f"{self.check} is false for {involved}"


def compile_rule(
    name: str, check: str, description: str, parameter_types: Mapping[str, str]
) -> CompiledRule:
    """Parse and type ``check`` against ``parameter_types`` (ROS name -> schema type name)."""
    expression = compile_expression(check, parameter_types)
    if expression.kind != "bool":
        raise RuleError(
            f"a check must be true or false (a comparison, say), not {kind_words(expression.kind)}"
        )
    return CompiledRule(name, check, description, expression)


def rules_by_parameter(rules: Iterable[CompiledRule]) -> dict[str, tuple[CompiledRule, ...]]:
    """Which rules read each parameter: a change needs only these checked again."""
    index: dict[str, list[CompiledRule]] = {}
    for rule in rules:
        for name in rule.parameters:
            index.setdefault(name, []).append(rule)
    return {name: tuple(found) for name, found in index.items()}
