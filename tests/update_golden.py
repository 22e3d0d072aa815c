"""Rewrite the golden files after an intended change of output.

    python -m tests.update_golden           # every kind
    python -m tests.update_golden cases     # tests/cases/*/expected_params.py (modules)
    python -m tests.update_golden bad       # tests/bad_schemas/*.stderr
    python -m tests.update_golden outputs   # docs, defaults, JSON Schema, check_params/*
    python -m tests.update_golden rclpy     # tests/rclpy_import/golden (import-rclpy)

Review the diff before committing: every changed line is a change users see.
"""

from __future__ import annotations

import sys

from tests.golden import (
    bad_schemas,
    case_dirs,
    expected_stderr_path,
    render_case,
    update,
    validate_stderr,
)


def update_cases() -> int:
    for case in case_dirs():
        (case / "expected_params.py").write_text(render_case(case), encoding="utf-8")
    return len(case_dirs())


def update_bad_schemas() -> int:
    for schema in bad_schemas():
        code, stderr = validate_stderr(schema)
        if code != 2 or not stderr:
            raise SystemExit(f"{schema}: expected exit code 2 and an error, got {code}")
        expected_stderr_path(schema).write_text(stderr, encoding="utf-8")
    return len(bad_schemas())


KINDS = ("cases", "bad", "outputs", "rclpy")


def main(argv: list[str]) -> int:
    kinds = set(argv) or set(KINDS)
    if kinds - set(KINDS):
        print(__doc__, file=sys.stderr)
        return 2
    if "cases" in kinds:
        print(f"rewrote {update_cases()} generated modules under tests/cases")
    if "bad" in kinds:
        print(f"rewrote {update_bad_schemas()} expected errors under tests/bad_schemas")
    if "outputs" in kinds:
        update()
        print("rewrote docs, defaults, JSON Schema and check-params goldens")
    if "rclpy" in kinds:
        from tests.rclpy_import.test_import_rclpy import write_goldens

        write_goldens()
        print("rewrote import-rclpy schemas, messages and patches")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
