"""Golden files: what each case folder expects, computed the one way tests compare it.

One folder per schema under tests/cases holds its schema.yaml and every output of it:
the generated module (expected_params.py), the docs pages (.md, .rst), the default
params file (.params.yaml), the JSON Schema (.schema.json) and, under check_params/,
one folder per params file with its check-params report. The example's schema.yaml
is a link to examples/camera_node/camera_driver.yaml, whose docs pages are committed
beside it. The CLI errors of bad schemas are a corpus of their own (tests/bad_schemas).
"""

from __future__ import annotations

import contextlib
import io
import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import genparams
from genparams.api import load_schema
from genparams.cli import main
from genparams.outputs.docs_model import docs_page
from genparams.outputs.json_schema import params_file_schema
from genparams.outputs.params_file import default_params_file
from genparams.outputs.render import render_docs, render_params_file
from genparams.runtime.core.json_codec import dumps

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent
EXAMPLE_SCHEMA = ROOT / "examples" / "camera_node" / "camera_driver.yaml"
CASES = TESTS / "cases"
OUTPUT_CASES = CASES  # every case folder holds the outputs of its schema
CHECK_PARAMS = "check_params"  # in a case folder: one folder per checked params file
BAD_SCHEMAS = TESTS / "bad_schemas"


@dataclass(frozen=True)
class OutputCase:
    """A schema and the folder holding its golden outputs, each named after the schema."""

    schema: Path
    folder: Path

    @property
    def name(self) -> str:
        return "example" if self.schema == EXAMPLE_SCHEMA else self.folder.name

    def golden(self, kind: str) -> Path:
        return self.folder / f"{load_schema(self.schema).name}{SUFFIXES[kind]}"


SUFFIXES = {
    "markdown": ".md",
    "rst": ".rst",
    "defaults": ".params.yaml",
    "json-schema": ".schema.json",
}


# The cases written to exercise docs, defaults and JSON Schema (each has a required
# parameter, which the defaults file leaves out); the other cases' outputs are goldens too.
OUTPUT_TEST_CASES = ("example", "mapped", "rules", "tricky")


def all_output_cases() -> list[OutputCase]:
    """The example (its docs are committed beside it), then every other case folder."""
    cases = [OutputCase(EXAMPLE_SCHEMA, EXAMPLE_SCHEMA.parent / "docs")]
    for folder in case_dirs():
        if case_schema(folder) != EXAMPLE_SCHEMA:
            cases.append(OutputCase(case_schema(folder), folder))
    return cases


def output_cases() -> list[OutputCase]:
    return [case for case in all_output_cases() if case.name in OUTPUT_TEST_CASES]


def runtime_cases() -> list[Path]:
    """The case folders whose module the read-back test declares: no mapped groups (their
    entries come from a for_each list), values for required parameters in overrides.yaml."""
    return [case for case in case_dirs() if not load_schema(case_schema(case)).maps]


def check_params_cases() -> list[Path]:
    """Every params file folder, of every case: ``tests/cases/<schema>/check_params/<case>``."""
    folders = (params.parent for params in CASES.glob(f"*/{CHECK_PARAMS}/*/params.yaml"))
    return sorted(folders, key=lambda folder: folder.name)


def outputs(case: OutputCase) -> dict[str, str]:
    """Every output genparams makes from a case's schema, by kind."""
    schema = load_schema(case.schema)
    page = docs_page(schema)
    return {
        "markdown": render_docs(page, "markdown"),
        "rst": render_docs(page, "rst"),
        "defaults": render_params_file(default_params_file(schema)),
        "json-schema": dumps(params_file_schema(schema), indent=2, ensure_ascii=False) + "\n",
    }


def case_arguments(case: Path) -> list[str]:
    args = case / "args.txt"
    return args.read_text(encoding="utf-8").split() if args.is_file() else []


def case_schema(case: Path) -> Path:
    """The schema of a case folder, or of the case folder a check_params folder lies in; the
    example's link resolved, so outputs name camera_driver.yaml as its users see them."""
    folder = case.parent.parent if case.parent.name == CHECK_PARAMS else case
    return (folder / "schema.yaml").resolve()


@contextlib.contextmanager
def _inside(folder: Path) -> Iterator[None]:
    before = Path.cwd()
    os.chdir(folder)
    try:
        yield
    finally:
        os.chdir(before)


def check_params_output(case: Path) -> tuple[int, str]:
    """Exit code and output of ``genparams check-params`` run inside the case folder."""
    out = io.StringIO()
    with _inside(case), contextlib.redirect_stdout(out):
        code = main(["check-params", str(case_schema(case)), "params.yaml", *case_arguments(case)])
    return code, out.getvalue()


def update() -> None:
    for case in all_output_cases():
        case.folder.mkdir(exist_ok=True)
        for kind, text in outputs(case).items():
            case.golden(kind).write_text(text, encoding="utf-8")
    for folder in check_params_cases():
        _code, text = check_params_output(folder)
        (folder / "expected.txt").write_text(text, encoding="utf-8")


def case_dirs() -> list[Path]:
    return sorted(path.parent for path in CASES.glob("*/schema.yaml"))


def render_case(case: Path) -> str:
    return genparams.generate(case_schema(case))


def bad_schemas() -> list[Path]:
    return sorted(BAD_SCHEMAS.glob("*.yaml"))


def relative(text: str) -> str:
    """Error output with the checkout's path removed, so goldens hold ``tests/...`` paths."""
    return text.replace(f"{ROOT}/", "")


def run_cli(*argv: str) -> tuple[int, str]:
    """Run the genparams command in-process: (exit code, stderr with relative paths)."""
    stderr = io.StringIO()
    with contextlib.redirect_stderr(stderr), contextlib.redirect_stdout(io.StringIO()):
        try:
            code = main(list(argv))
        except SystemExit as exc:  # argparse usage errors
            code = exc.code if isinstance(exc.code, int) else 2
    return code, relative(stderr.getvalue())


def validate_stderr(schema: Path) -> tuple[int, str]:
    return run_cli("validate", str(schema))


def expected_stderr_path(schema: Path) -> Path:
    return schema.with_suffix(".stderr")
