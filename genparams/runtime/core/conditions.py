"""Conditional declaration (``when``): the one place that decides it, words it and writes it.

A parameter's ``when`` is a tuple of ``(name, test)`` pairs, each naming a controlling
parameter (relative to the class prefix); all must hold. A test is either the values of
which the controlling parameter must hold one (a tuple, as modules generated before
negation wrote it: ``(("mode", ("advanced", "expert")),)``) or a :class:`NoneOf`, the
values it must hold none of (``(("mode", NoneOf("proxied")),)``, from ``when: {mode:
{not: proxied}}``). Every reader (declaration, remote reads, params-file checks, docs,
the schema message, importers) decides and words a condition through this module.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from genparams.runtime.core.records import Record, store

NOT_KEY = "not"
"""The key of a negated test in a schema (``{not: [a, b]}``) and in a schema message."""


class NoneOf(Record):
    """The values a controlling parameter must not hold: ``NoneOf("proxied")``."""

    _fields = ("values",)
    __slots__ = _fields
    values: tuple[Any, ...]

    def __init__(self, *values: Any) -> None:
        store(self, "values", values)

    def __reduce__(self) -> tuple[Any, ...]:
        return (NoneOf, self.values)


KeyTest = tuple[Any, ...] | NoneOf
"""One key's test: the values to hold one of, or (NoneOf) the values to hold none of."""

Condition = tuple[tuple[str, KeyTest], ...]
"""A parameter's ``when``: every key's test must hold."""


def tested_values(test: KeyTest) -> tuple[Any, ...]:
    """The values a test names, whichever way it uses them."""
    return test.values if isinstance(test, NoneOf) else test


def passes(test: KeyTest, value: Any) -> bool:
    """Whether a controlling parameter holding ``value`` passes ``test``."""
    if isinstance(test, NoneOf):
        return value not in test.values
    return value in test


def condition_holds(when: Condition, values: Mapping[str, Any]) -> bool:
    """Whether every key of ``when`` holds for ``values`` (relative name -> typed value)."""
    return all(passes(test, values.get(name)) for name, test in when)


def controlling_names(when: Condition) -> tuple[str, ...]:
    """The parameters ``when`` reads."""
    return tuple(name for name, _ in when)


def negated(test: KeyTest) -> KeyTest:
    """The test that holds exactly when ``test`` does not."""
    return test.values if isinstance(test, NoneOf) else NoneOf(*test)


def both(first: KeyTest, second: KeyTest) -> KeyTest:
    """The test that holds when both tests on one parameter hold (an ``elif``'s)."""
    if isinstance(first, NoneOf) and isinstance(second, NoneOf):
        return NoneOf(*first.values, *(v for v in second.values if v not in first.values))
    if isinstance(first, NoneOf):
        first, second = second, first
    return tuple(v for v in tested_values(first) if passes(second, v))


# Words --------------------------------------------------------------------------------


def value_words(value: Any) -> str:
    """A condition's value as a params file spells it: true, 2.5, 'advanced'."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value)


def key_words(test: KeyTest) -> str:
    """``is 'a' or 'b'``, ``is not 'a'``, ``is neither 'a' nor 'b'``, ``is none of ...``."""
    shown = [value_words(value) for value in tested_values(test)]
    if not isinstance(test, NoneOf):
        return "is " + " or ".join(shown)
    if len(shown) == 1:
        return f"is not {shown[0]}"
    if len(shown) == 2:
        return f"is neither {shown[0]} nor {shown[1]}"
    return f"is none of {', '.join(shown[:-1])} or {shown[-1]}"


def condition_text(when: Condition) -> str:
    """``when`` in words: "declared only when mode is not 'proxied'"; "" without one."""
    parts = [f"{name} {key_words(test)}" for name, test in when]
    return "declared only when " + " and ".join(parts) if parts else ""


# Written forms ------------------------------------------------------------------------


def json_test(test: KeyTest) -> Any:
    """A test as a schema message holds it: ``["a", "b"]`` or ``{"not": ["a"]}``."""
    values = list(tested_values(test))
    return {NOT_KEY: values} if isinstance(test, NoneOf) else values


def condition_json(when: Condition) -> dict[str, Any]:
    return {name: json_test(test) for name, test in when}


def _values(written: Any) -> tuple[Any, ...]:
    return tuple(written) if isinstance(written, list | tuple) else (written,)


def schema_test(written: Any) -> KeyTest:
    """A test as a schema writes it (already shape-checked): ``advanced``, ``[a, b]``,
    ``{not: proxied}`` or ``{not: [a, b]}``."""
    if isinstance(written, Mapping):
        return NoneOf(*_values(written[NOT_KEY]))
    return _values(written)


def schema_condition(written: Mapping[Any, Any]) -> Condition:
    return tuple((str(name), schema_test(test)) for name, test in written.items())


def written_test(test: KeyTest) -> Any:
    """A test as a schema file writes it, one value bare: the reverse of schema_test."""
    values = list(tested_values(test))
    shown = values[0] if len(values) == 1 else values
    return {NOT_KEY: shown} if isinstance(test, NoneOf) else shown


_SCALAR = (bool, int, float, str)


def json_condition(written: Any, where: str) -> Condition:
    """A schema message's ``when``, checked as untrusted input: raises ValueError naming
    the field (``where``) and what is wrong."""
    if not isinstance(written, dict) or not written:
        raise ValueError(f"{where}: expected a non-empty object of tests")
    tests: list[tuple[str, KeyTest]] = []
    for name, test in written.items():
        at = f"{where}.{name}"
        negative = isinstance(test, dict)
        if negative:
            if set(test) != {NOT_KEY}:
                raise ValueError(f"{at}: a negated test is an object with only {NOT_KEY!r}")
            test = test[NOT_KEY]
            at = f"{at}.{NOT_KEY}"
        if not (isinstance(test, list) and test and all(isinstance(v, _SCALAR) for v in test)):
            raise ValueError(f"{at}: expected a non-empty list of booleans, numbers or strings")
        tests.append((name, NoneOf(*test) if negative else tuple(test)))
    return tuple(tests)
