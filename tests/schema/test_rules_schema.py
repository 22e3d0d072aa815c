"""Rules in schemas: every bad rule is named at its place, nothing in a check ever runs."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import genparams
from genparams.cli import main
from genparams.schema.errors import SchemaError
from tests.support import load_generated

HEADER = """\
genparams: 1
name: motion
parameters:
  min_speed: {type: double, default: 0.5}
  max_speed: {type: double, default: 2.0}
  camera:
    width: {type: int, default: 640}
    from: {type: int, default: 1}
  serial: {type: string}
  topics: {type: string_array, default: [/a]}
rules:
"""


def _validate(tmp_path: Path, rules: str, capsys: pytest.CaptureFixture[str]) -> list[str]:
    schema = tmp_path / "bad.yaml"
    schema.write_text(HEADER + rules)
    code = main(["validate", str(schema)])
    captured = capsys.readouterr()
    assert code == 2, captured
    prefix = f"{schema}:"
    lines = captured.err.strip().splitlines()
    assert all(line.startswith(prefix) for line in lines), lines
    return [line[len(prefix) :] for line in lines]


def test_bad_rules_are_reported_at_their_check(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    rules = """\
  - name: typo
    check: min_sped <= max_speed
  - name: syntax
    check: "min_speed <= (max_speed"
  - name: not_a_condition
    check: max_speed - min_speed
  - name: wrong_types
    check: len(min_speed) > 0
  - name: defaults_break_it
    check: min_speed > max_speed
  - name: typo
    check: camera.from_ > 0 and len(serial) == 8
"""
    assert _validate(tmp_path, rules, capsys) == [
        "13:12: rules[0].check: unknown parameter 'min_sped' (did you mean 'min_speed'?) "
        "(at character 1)",
        "15:12: rules[1].check: invalid expression: '(' was never closed (at character 14)",
        "17:12: rules[2].check: a check must be true or false (a comparison, say), not a number",
        "19:12: rules[3].check: len() takes one string or array, not a number (at character 1)",
        "21:12: rules[4].check: the defaults break rule 'defaults_break_it': "
        "min_speed > max_speed is false for min_speed=0.5, max_speed=2.0",
        "22:11: rules[5].name: rule name 'typo' is already used by rules[0]",
    ]


def test_rule_keys_are_checked_by_the_schema(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    rules = """\
  - name: Bad Name
    check: min_speed < 1
  - name: no_check
  - name: extra
    check: min_speed < 1
    severity: high
"""
    assert _validate(tmp_path, rules, capsys) == [
        "12:11: rules[0].name: 'Bad Name' must match ^[a-z][a-z0-9_]*$",
        "14:5: rules[1]: 'check' is required",
        "17:5: rules[2].severity: unknown key 'severity'",
    ]


@pytest.mark.parametrize(
    ("check", "message"),
    [
        (
            "__import__('os').system('touch {sentinel}') == 0",
            "rules cannot call methods: the functions are abs, len, max, min (at character 1)",
        ),
        (
            "len(topics) > 0 or open('{sentinel}', 'w') == 1",
            "rules cannot call 'open': the functions are abs, len, max, min (at character 20)",
        ),
        (
            "min_speed.__class__.__name__ == 'float'",
            "'min_speed.__class__.__name__' is not a parameter: attribute access is not allowed "
            "('min_speed' is a parameter) (at character 1)",
        ),
        (
            "().__class__.__bases__ == ()",
            "attribute access is not allowed: only dotted parameter names such as a.b "
            "(at character 1)",
        ),
        (
            "[c for c in ().__class__.__base__.__subclasses__()] == []",
            "rules cannot use comprehensions (at character 1)",
        ),
        (
            "(lambda: 1)() == 1",
            "rules cannot call methods: the functions are abs, len, max, min (at character 1)",
        ),
        ("topics[0] == '/a'", "rules cannot use indexing (at character 1)"),
        ("min_speed ** 99999999 > 0", "rules cannot use the operator ** (at character 1)"),
        ("f'{{min_speed}}' == '1'", "rules cannot use f-strings (at character 1)"),
    ],
)
def test_code_in_a_check_is_refused_and_never_run(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], check: str, message: str
) -> None:
    sentinel = tmp_path / "executed"
    text = check.format(sentinel=sentinel)
    rules = f"  - name: evil\n    check: {text!r}\n".replace("\\\\", "\\")
    assert _validate(tmp_path, rules, capsys) == [f"13:12: rules[0].check: {message}"]
    # The generator refuses it too, and nothing ran at any point.
    with pytest.raises(SchemaError):
        genparams.generate(tmp_path / "bad.yaml")
    assert not sentinel.exists()


def test_rules_reach_generated_code_as_data(tmp_path: Path) -> None:
    check = 'camera.width != 7 or min_speed < 1 and "it\'s \\\\ \\"quoted\\"" != \'\''
    schema = tmp_path / "motion.yaml"
    schema.write_text(
        HEADER.replace("  serial: {type: string}\n", "")
        + f"  - name: quoting\n    check: {_yaml_single_quoted(check)}\n"
        + "    description: 'Text with \"quotes\" and \\\\ backslashes.'\n"
    )
    text = genparams.generate(schema)
    assert "_RuleSpec(" in text and "eval(" not in text
    module = load_generated(schema, tmp_path)
    (rule,) = module.MotionParams._SPEC.rules
    assert rule.check == check
    assert rule.description == 'Text with "quotes" and \\\\ backslashes.'
    assert module.MotionParams.defaults().camera.width == 640


def _yaml_single_quoted(text: str) -> str:
    return "'" + text.replace("'", "''") + "'"


def test_generated_module_with_rules_is_lint_and_type_clean(tmp_path: Path) -> None:
    schema = tmp_path / "motion.yaml"
    schema.write_text(
        HEADER.replace("  serial: {type: string}\n", "")
        + "  - {name: speed_order, check: min_speed <= max_speed, description: Order.}\n"
        + "  - {name: camera_size, check: 'camera.width >= 64 if camera.from_ > 0 else true'}\n"
    )
    output = tmp_path / "motion_params.py"
    assert main(["generate", str(schema), "-o", str(output)]) == 0
    root = Path(__file__).resolve().parents[2]
    config = str(root / "pyproject.toml")
    for command in (
        # RUF100: the header's blanket noqa for long lines is unused when no line is long.
        ["ruff", "check", "--config", config, "--extend-ignore", "RUF100", str(output)],
        ["ruff", "format", "--check", "--config", config, str(output)],
        ["mypy", "--config-file", config, str(output)],
    ):
        result = subprocess.run(
            [sys.executable, "-m", *command], capture_output=True, text=True, cwd=tmp_path
        )
        assert result.returncode == 0, result.stdout + result.stderr
