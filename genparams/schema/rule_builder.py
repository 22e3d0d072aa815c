"""Build the model of a schema's ``rules:`` and check them: names, expressions, defaults.

A check may read only parameters the schema declares, must be an expression of
genparams.runtime.core.rules, and the defaults must satisfy it (when every parameter it reads
has a default). Problems point at the rule's ``check`` value.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from genparams.runtime.core.naming import ENTRY_KEY
from genparams.runtime.core.rules import RuleError, compile_rule
from genparams.schema.errors import SchemaProblem
from genparams.schema.loader import LoadedDocument, Path, dotted
from genparams.schema.model import Parameter, Rule


def build_rules(
    document: LoadedDocument,
    parameters: Iterable[Parameter],
    unbuilt: Callable[[str], bool] = lambda name: False,
) -> tuple[tuple[Rule, ...], list[SchemaProblem]]:
    """``unbuilt``: spellings of parameters left out for problems of their own, already
    reported; a rule reading one is skipped rather than told it reads no parameter."""
    # Entries of mapped groups come and go at run time: rules read fixed parameters only.
    by_name = {p.ros_name: p for p in parameters if ENTRY_KEY not in p.ros_name.split(".")}
    types = {name: p.type.name for name, p in by_name.items()}
    rules: list[Rule] = []
    problems: list[SchemaProblem] = []

    def problem(path: Path, message: str) -> None:
        problems.append(SchemaProblem(document.value_location(path), dotted(path), message))

    seen: dict[str, int] = {}
    entries = document.data.get("rules", [])
    for index, entry in enumerate(entries if isinstance(entries, list) else []):
        path: Path = ("rules", index)
        if not _well_formed(entry):
            continue  # the schema check reports its shape; the other rules are still checked
        name, check = entry["name"], entry["check"]
        description = entry.get("description", "")
        if name in seen:
            problem((*path, "name"), f"rule name {name!r} is already used by rules[{seen[name]}]")
        seen.setdefault(name, index)
        try:
            compiled = compile_rule(name, check, description, types)
        except RuleError as exc:
            if exc.unknown_name is None or not unbuilt(exc.unknown_name):
                problem((*path, "check"), str(exc))
            continue
        defaults = {n: by_name[n].default for n in compiled.parameters}
        # A required parameter has no default, and a bad default is already reported.
        if not any(by_name[n].required or defaults[n] is None for n in compiled.parameters):
            failure = compiled.failure(defaults)
            if failure is not None:
                problem((*path, "check"), f"the defaults break rule {name!r}: {failure}")
        rules.append(
            Rule(
                name=name,
                check=check,
                description=description,
                parameters=compiled.parameters,
                location=document.value_location((*path, "check")),
            )
        )
    return tuple(rules), problems


def _well_formed(entry: Any) -> bool:
    return (
        isinstance(entry, dict)
        and isinstance(entry.get("name"), str)
        and isinstance(entry.get("check"), str)
        and isinstance(entry.get("description", ""), str)
    )
