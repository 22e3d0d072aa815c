"""Entries of mapped groups: templates (``gains.*.p``) expanded over key lists. Pure Python."""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import replace
from typing import Any

from genparams.runtime.naming import ENTRY_KEY
from genparams.runtime.resolve import resolve_values
from genparams.runtime.spec import CompiledParam, CompiledSchema


def map_chain(template_name: str) -> tuple[str, ...]:
    """The maps a template lies in, outermost first: ``a.*.b.*.x`` -> ``a``, ``a.*.b``."""
    parts = template_name.split(".")
    return tuple(".".join(parts[:i]) for i, part in enumerate(parts) if part == ENTRY_KEY)


def _fill(parts: Sequence[str], keys: Sequence[str]) -> list[str]:
    chosen = iter(keys)
    return [next(chosen) if part == ENTRY_KEY else part for part in parts]


def template_keys(template_name: str, name: str) -> list[str] | None:
    """The keys that fill the ``*`` of a template to give ``name``, or None if it has
    another shape: ``gains.*.p`` and ``gains.elbow.p`` -> ``["elbow"]``."""
    pattern = template_name.split(".")
    parts = name.split(".")
    if len(pattern) != len(parts):
        return None
    keys = []
    for part, expected in zip(parts, pattern, strict=True):
        if expected == ENTRY_KEY:
            keys.append(part)
        elif part != expected:
            return None
    return keys


def instantiate(template: CompiledParam, keys: Sequence[str]) -> CompiledParam:
    """The parameter of one entry: each ``*`` of the template replaced by the next key."""
    name = ".".join(_fill(template.name.split("."), keys))
    path = tuple(_fill(template.attribute_path, keys))
    return replace(template, spec=replace(template.spec, name=name), attribute_path=path)


def expand(
    compiled: CompiledSchema,
    values: Mapping[str, Any],
    existing: Mapping[str, CompiledParam] | None = None,
) -> dict[str, CompiledParam]:
    """Every entry's parameter for the key lists in ``values`` (maps whose key is absent: none).

    Entries found in ``existing`` (by name) are reused rather than built again.
    """
    existing = existing or {}
    entries: dict[str, CompiledParam] = {}
    for template in compiled.templates.values():
        key_lists = [values.get(compiled.maps[m]) for m in map_chain(template.name)]
        if any(keys is None for keys in key_lists):
            continue
        parts = template.name.split(".")
        for keys in itertools.product(*key_lists):  # type: ignore[arg-type]
            name = ".".join(_fill(parts, keys))
            entry = existing.get(name)
            entries[name] = entry if entry is not None else instantiate(template, keys)
    return entries


def _controlling(compiled: CompiledSchema) -> dict[str, CompiledParam]:
    """The parameters that conditions (``when``) read."""
    names = {name for param in compiled.parameters.values() for name, _ in param.spec.when}
    return {name: compiled.parameters[name] for name in names}


def flatten(values: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    """Dotted names -> values from nested and dotted keys (no parameter value is a mapping)."""
    out: dict[str, Any] = {}
    for key, value in values.items():
        name = f"{prefix}.{key}" if prefix else str(key)
        if isinstance(value, Mapping):
            out.update(flatten(value, name))
        else:
            out[name] = value
    return out


def resolve_all(
    compiled: CompiledSchema,
    read: Callable[[Iterable[str]], Mapping[str, Any]],
    full_name: Callable[[str], str] = lambda name: name,
    source: str = "override",
    lenient: bool = False,
) -> tuple[dict[str, CompiledParam], dict[str, Any], list[str]]:
    """Parameters (fixed ones, then entries) with their starting values, and every problem.

    Key parameters are fixed, so their values are known before the entries
    they key are expanded. ``read`` gives the ROS-form values given for names.
    A parameter with a condition (``when``) whose condition does not hold is
    left out of the parameters, and its value is None.
    """
    parameters = dict(compiled.parameters)
    given = read(parameters)
    conditional = [name for name, param in parameters.items() if param.spec.when]
    if conditional:
        controlling, _ = resolve_values(compiled, given, parameters=_controlling(compiled))
        for name in conditional:
            if not parameters[name].spec.declared_with(controlling):
                del parameters[name]
    values, problems = resolve_values(
        compiled, given, full_name, source, parameters=parameters, lenient=lenient
    )
    values.update((name, None) for name in conditional if name not in parameters)
    if compiled.templates:
        entries = expand(compiled, values)
        entry_values, entry_problems = resolve_values(
            compiled, read(entries), full_name, source, parameters=entries, lenient=lenient
        )
        parameters.update(entries)
        values.update(entry_values)
        problems.extend(entry_problems)
    return parameters, values, problems
