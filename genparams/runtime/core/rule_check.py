"""Check cross-parameter rules against a proposed change merged into the committed values."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping
from typing import TYPE_CHECKING, Any

from genparams.runtime.core.problems import ParameterProblem
from genparams.runtime.core.spec import CompiledParam, compile_schema
from genparams.runtime.core.tree import get_path

if TYPE_CHECKING:
    from genparams.runtime.core.params_view import ParamsView
    from genparams.runtime.core.rules import CompiledRule

    # The type of ``broken_rules``, for those that hold it.
    RulesCheck = Callable[
        [ParamsView, Mapping[str, Any], Callable[[str], str]], list[ParameterProblem]
    ]


class MergedValues(Mapping[str, Any]):
    """Proposed values over the committed ones, by relative ROS name; read lazily."""

    def __init__(
        self,
        committed: ParamsView,
        proposed: Mapping[str, Any],
        parameters: Mapping[str, CompiledParam],
    ) -> None:
        self.committed = committed
        self.proposed = proposed
        self.parameters = parameters

    def __getitem__(self, name: str) -> Any:
        if name in self.proposed:
            return self.proposed[name]
        return get_path(self.committed, self.parameters[name].attribute_path)

    def __iter__(self) -> Iterator[str]:
        return iter(self.parameters)

    def __len__(self) -> int:
        return len(self.parameters)


def broken_rules(
    committed: ParamsView, proposed: Mapping[str, Any], shown: Callable[[str], str]
) -> list[ParameterProblem]:
    """A problem per rule that ``proposed`` (relative names, typed values) would break.

    Only rules that read a proposed parameter are evaluated: the committed values
    already satisfy every rule.
    """
    compiled = compile_schema(type(committed)._SPEC)
    rules = compiled.rules_reading(proposed)
    if not rules:
        return []
    return violations(rules, MergedValues(committed, proposed, compiled.parameters), shown)


def violations(
    rules: Iterable[CompiledRule], values: Mapping[str, Any], shown: Callable[[str], str]
) -> list[ParameterProblem]:
    """A problem per rule that ``values`` (relative ROS names, typed) break: no key, the
    message names the rule and every value it read."""
    problems = []
    for rule in rules:
        reason = rule.violation(values, shown)
        if reason is not None:
            problems.append(ParameterProblem("", reason))
    return problems
