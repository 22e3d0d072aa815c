"""Fuzzing the schema front end for a bounded time, plus every crasher it has found.

CI spends ``fuzz_seconds(20)`` per target (three targets); a long run:
``.venv/bin/python -m tests.fuzz --seconds 3600`` or GENPARAMS_TEST_PROFILE=dev.
"""

from __future__ import annotations

import pytest

from genparams.api import load_schema
from genparams.schema.errors import SchemaError
from tests.budget import fuzz_seconds
from tests.fuzz import TARGETS, check, run_for

HEAD = "genparams: 1\nname: a\nparameters:\n"
BIG = "1" * 400

# Inputs that once raised something other than SchemaError (or crashed the process).
FOUND = {
    "huge int as double default": (
        f"  x: {{type: double, default: {BIG}}}\n",
        "is too large for a double",
    ),
    "huge int as double range": (
        f"  x: {{type: double, default: 1.0, range: {{min: 0, max: {BIG}}}}}\n",
        "max is too large for a double",
    ),
    "huge int as double choice": (
        f"  x: {{type: double, default: 1.0, choices: [1.0, {BIG}]}}\n",
        "is too large for a double",
    ),
    "step with an infinite range": (
        "  x: {type: double, default: 1.0, range: {min: -.inf, max: 10.0, step: 0.5}}\n",
        "needs finite min and max",
    ),
    "step too small for the span": (
        "  x: {type: double, default: 0.0, range: {min: 0.0, max: 1.0e+10, step: 5.0e-324}}\n",
        "needs finite min and max",
    ),
    "NaN comparison limit": (
        "  x: {type: double, validators: [{gt: .nan}]}\n",
        "gt must be a number, not NaN",
    ),
    "limit beyond int64": (
        f"  x: {{type: int, validators: [{{gt: {2**64}}}]}}\n",
        "no value satisfies all of them",
    ),
    "bad !!int": (
        "  x: {type: int, default: !!int abc}\n",
        "cannot be read as tag:yaml.org,2002:int",
    ),
    "bad !!float": ("  x: {type: double, default: !!float ''}\n", "cannot be read as"),
    "python tag on a sequence": (
        "  x: {type: int, default: !!python/object/apply:os.system [touch PWNED]}\n",
        "unsupported YAML tag",
    ),
    "set tag": ("  x: {type: string_array, default: !!set {a, b}}\n", "unsupported YAML tag"),
    "NUL in a default": ('  x: {type: string, default: "a\\0b"}\n', "cannot contain NUL"),
    "NUL in a description": (
        '  x: {type: int, default: 1, description: "a\\0b"}\n',
        "cannot contain NUL",
    ),
    "for_each over a string_array whose default is not a list": (
        "  keys: {type: string_array, default: {a: 1}}\n"
        "  arms:\n    for_each: keys\n    gain: {type: double, default: 1.0}\n",
        "default does not match type",
    ),
    "flow nesting 100000 deep (segfault in libyaml's composer)": (
        "  x: " + "[" * 100_000 + "]" * 100_000 + "\n",
        "nested deeper than 64 levels",
    ),
}


@pytest.mark.parametrize("body, message", FOUND.values(), ids=list(FOUND))
def test_found_crashers_are_schema_errors(body: str, message: str) -> None:
    with pytest.raises(SchemaError) as caught:
        load_schema("found.yaml", HEAD + body)
    assert message in str(caught.value)
    check(HEAD + body)


def test_int_range_edges_are_valid_like_in_rclpy() -> None:
    schema = load_schema(
        "edge.yaml", HEAD + "  x: {type: int, default: 10, range: {min: 0, max: 10, step: 3}}\n"
    )
    assert schema.parameters[0].default == 10


@pytest.mark.parametrize("target", sorted(TARGETS))
def test_fuzz_front_end(target: str) -> None:
    count = run_for(TARGETS[target], fuzz_seconds(20))
    assert count > 0
