"""Mutation testing of the runtime and the params-file checker, module by module (mutmut).

    python -m tests.mutate run [MODULE ...]     # test the unchecked mutants of these modules
    python -m tests.mutate recheck [MODULE ...] # survivors against the tests written for them
    python -m tests.mutate quick MODULE ...     # unchecked mutants, the same way
    python -m tests.mutate report               # score per module, survivors not accepted
    python -m tests.mutate survivors [MODULE ...]  # the survivors still to kill or explain
    python -m tests.mutate baseline [MODULE ...]  # record the killed mutants for `sample`
    python -m tests.mutate sample [N [SEED]]    # N recorded kills run afresh; fail on a survivor
    python -m tests.mutate try NAME TEST ...    # do these tests kill this mutant?
    python -m tests.mutate typecheck mypy       # (mutmut's type_check_command, in mutants/)

mutmut (configured in pyproject.toml, [tool.mutmut]) copies the package into
mutants/, records which tests call each function, and runs each mutant against
only those tests. Its results stay in mutants/*.meta between runs, so a long run
can be stopped and resumed. MODULE is a dotted name such as
``genparams.runtime.node.binding``; without one, every module in CORE then the rest.

Survivors that no test can kill (equivalent mutants) or that are accepted are
listed with the reason in tests/mutation_accepted.txt; ``report`` fails only on
a survivor missing from it. ``sample`` (CI) draws from the mutants the last full
run killed (tests/mutation_killed.txt): one that survives now means a test got weaker.
Each recorded kill carries the hash of its function as mutmut saw it; a mutant whose
function is gone or has changed since (mutmut numbers its mutants anew) is not drawn,
so a code change never fails ``sample`` by itself, it only shrinks what can be drawn
until ``baseline`` is run again.
"""

from __future__ import annotations

import json
import os
import random
import re
import shutil
import subprocess
import sys
from collections import Counter
from collections.abc import Sequence
from pathlib import Path

from tests import corpus

ROOT = Path(__file__).resolve().parent.parent
MUTANTS = ROOT / "mutants"
ACCEPTED = ROOT / "tests" / "mutation_accepted.txt"
KILLED = ROOT / "tests" / "mutation_killed.txt"
# Tests run once per mutant: property tests try a tenth as many examples (tests/budget.py).
# They run from mutants/, so the real-world corpus is named where it is (tests/corpus.py).
MUTATE_ENV = {"GENPARAMS_TEST_PROFILE": "mutate", corpus.ENV: str(corpus.location())}
KILLERS = MUTANTS / "killers.txt"  # mutant, then the test that failed first under it
MUTMUT = [sys.executable, "-m", "mutmut"]

# The modules whose every change of behaviour a test must catch, first.
CORE = (
    "genparams.runtime.core.validators",
    "genparams.runtime.core.validator_kinds",
    "genparams.runtime.node.binding",
    "genparams.runtime.core.spec",
    "genparams.runtime.core.entries",
    "genparams.runtime.core.tree",
    "genparams.paramsfile.check_params",
    "genparams.paramsfile.params_reader",
    "genparams.paramsfile.ros_yaml",
)
PACKAGES = ("genparams/runtime", "genparams/paramsfile")
# Copied into mutants/ by every mutmut run, merged into what is already there: removed
# first so a test file deleted or moved here does not linger there and break collection.
COPIES = ("tests", "examples", "schemas", "templates")

STATUS = {1: "killed", 3: "killed", 0: "survived", 5: "no tests", 33: "no tests", 37: "typed"}
TIMEOUTS = {24, -24, 152, 255, 36}


def status(code: int | None) -> str:
    if code is None:
        return "unchecked"
    if code in TIMEOUTS:
        return "timeout"  # a mutant that hangs the tests is caught
    return STATUS.get(code, "suspicious")


def all_modules() -> list[str]:
    names = [
        str(path.relative_to(ROOT).with_suffix("")).replace("/", ".")
        for package in PACKAGES
        for path in sorted((ROOT / package).rglob("*.py"))
        if path.name != "__init__.py"
    ]
    return [*CORE, *(name for name in names if name not in CORE)]


def _meta(module: str) -> dict[str, dict[str, object]]:
    meta = MUTANTS / (module.replace(".", "/") + ".py.meta")
    if not meta.exists():
        return {}
    data: dict[str, dict[str, object]] = json.loads(meta.read_text(encoding="utf-8"))
    return data


def results(module: str) -> dict[str, int | None]:
    codes: dict[str, int | None] = dict(_meta(module).get("exit_code_by_key", {}))  # type: ignore[arg-type]
    return codes


def function_hashes() -> dict[str, str]:
    """Mutant name -> hash of the function it changes, as mutmut last generated it."""
    out = {}
    for module in all_modules():
        meta = _meta(module)
        hashes = meta.get("hash_by_function_name", {})
        for name in meta.get("exit_code_by_key", {}):
            function = name[len(module) + 1 :].rpartition("__mutmut_")[0]
            if function in hashes:
                out[name] = str(hashes[function])
    return out


def accepted() -> dict[str, str]:
    """Mutant name -> why it may survive."""
    if not ACCEPTED.exists():
        return {}
    out = {}
    for line in ACCEPTED.read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            name, _, reason = line.partition(" ")
            out[name] = reason.strip()
    return out


# The tests written for a module, run first for its mutants: they are the likeliest to
# kill them, and a survivor is judged mostly by them (see MAX_TESTS_PER_MUTANT).
OWN_TESTS = {
    "genparams.runtime.core.validators": (
        "tests/runtime/test_validators.py",
        "tests/runtime/test_edge",
    ),
    "genparams.runtime.core.validator_kinds": ("tests/runtime/test_validators.py", "tests/schema/"),
    "genparams.runtime.node.binding": (
        "tests/runtime/test_commit_semantics.py",
        "tests/runtime/test_runtime_services.py",
    ),
    "genparams.runtime.core.tree": (
        "tests/runtime/test_tree_updates.py",
        "tests/runtime/test_commit_records.py",
    ),
    "genparams.runtime.node.mapped": ("tests/runtime/test_mapped.py",),
    "genparams.runtime.core.expressions": (
        "tests/schema/test_expressions.py",
        "tests/runtime/test_rules",
    ),
    "genparams.runtime.remote.client": ("tests/runtime/test_remote",),
    "genparams.runtime.remote.watch": ("tests/runtime/test_remote",),
    "genparams.runtime.node.schema_topic": ("tests/runtime/test_schema_message.py",),
    "genparams.paramsfile": ("tests/paramsfile/",),
}
# The tests written to kill each module's mutants, as globs: `recheck` runs every survivor
# against these (the longest prefix of its name that matches wins).
KERNEL_TESTS = (
    "tests/runtime/test_validators.py",
    "tests/runtime/test_custom_arguments.py",
    "tests/runtime/test_merged_values.py",
    "tests/runtime/test_naming_rules.py",
    "tests/runtime/test_rule_messages.py",
    "tests/runtime/test_suggest_cutoffs.py",
    "tests/runtime/test_type_messages.py",
    "tests/runtime/test_value_equality.py",
    "tests/schema/test_expressions.py",
)
KILLER_TESTS = {
    # the node side of the runtime
    "genparams.runtime": (
        "tests/runtime/test_commit_semantics.py",
        "tests/runtime/test_clashes_between_classes.py",
        "tests/runtime/test_entries_that_cannot_be_declared.py",
        "tests/runtime/test_group_values.py",
        "tests/runtime/test_mapped_checks.py",
        "tests/runtime/test_maps_beside_names.py",
        "tests/runtime/test_renamed_pairs.py",
        "tests/runtime/test_renames.py",
        "tests/runtime/test_rules_runtime.py",
        "tests/runtime/test_parameter_prefixes.py",
        "tests/runtime/test_declared_descriptors_and_notices.py",
    ),
    # its kernel: validators, types, naming, expressions and rules
    "genparams.runtime.core.validators": KERNEL_TESTS,
    "genparams.runtime.core.validator_kinds": KERNEL_TESTS,
    "genparams.runtime.core.types": KERNEL_TESTS,
    "genparams.runtime.core.naming": KERNEL_TESTS,
    "genparams.runtime.core.suggest": KERNEL_TESTS,
    "genparams.runtime.core.expression_words": KERNEL_TESTS,
    "genparams.runtime.core.expressions": KERNEL_TESTS,
    "genparams.runtime.core.rules": KERNEL_TESTS,
    "genparams.runtime.core.rule_check": KERNEL_TESTS,
    "genparams.runtime.core.errors": KERNEL_TESTS,
    "genparams.runtime.core.changes": KERNEL_TESTS,
    "genparams.runtime.remote.client": ("tests/runtime/test_remote*.py",),
    "genparams.runtime.remote.watch": ("tests/runtime/test_remote*.py",),
    "genparams.runtime.node.schema_topic": ("tests/runtime/test_schema_message.py",),
    "genparams.paramsfile": (
        "tests/paramsfile/test_[!c]*.py",
        "tests/paramsfile/test_check_params*.py",
    ),
}


# A mutant that survives would otherwise run every test that calls its function (over
# 500 node tests for a range check: minutes on a loaded machine). It runs the module's
# own tests and then the fastest others, this many in all; `recheck` runs the survivors
# again with no cap, so a test past it still gets its chance.
MAX_TESTS_PER_MUTANT = 150

# Workers run the same tests at once, with the same node names: each gets a DDS domain
# of its own (200-231), or a service call could be answered by another worker's node.
# They wait on ROS services and executors more than they compute: 6 keep 2 cores busy.
WORKERS = int(os.environ.get("MUTATE_WORKERS", "6"))
# mutmut hands pytest the tests in no particular order, so a mutant a 1 ms test kills
# often waits for a slow node test first. The patch below orders and caps them; the
# workers fork from this process, so it reaches them. It runs in a fresh interpreter
# that imports nothing from tests/ (pytest imports tests/ from mutants/, and a package
# already imported from here would clash).
ORDERED_RUN = """
import os, sys
from mutmut.runners import harness
from mutmut.state import state
own_tests, cap, killers = OWN_TESTS, MAX_TESTS_PER_MUTANT, KILLERS
plain = harness.PytestRunner._pytest_args_regular_run
def ordered(self, tests):
    mutant = os.environ.get("MUTANT_UNDER_TEST", "")
    if mutant:  # a worker: its nodes must not answer another worker's service calls
        take_a_domain()
    own = next((v for k, v in own_tests.items() if mutant.startswith(k + ".")), ())
    durations = state().duration_by_test
    def key(test):
        return (not test.startswith(own), durations.get(test, 0.0), test)
    tests = sorted(tests, key=key)
    return plain(self, tests[:cap] if mutant and tests else tests)
def take_a_domain():  # the first free of 200-231, held until this worker exits
    import fcntl, tempfile
    for domain in range(200, 232):
        lock = os.path.join(tempfile.gettempdir(), f"genparams-mutate-domain-{domain}.lock")
        fd = os.open(lock, os.O_CREAT | os.O_RDWR)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            continue
        os.environ["ROS_DOMAIN_ID"] = str(domain)
        return
class Killer:  # records the test that failed first under a mutant, for `sample`
    def __init__(self, mutant):
        self.mutant = mutant
    def pytest_runtest_logreport(self, report):
        if report.failed and self.mutant:
            with open(killers, "a", encoding="utf-8") as out:
                test = report.nodeid  # an id with a line break in it: its function's
                test = test.split("[")[0] if "\\n" in test else test
                out.write(self.mutant + " " + test + "\\n")
            self.mutant = ""
def run_tests(self, *, mutant_name, tests):
    with harness.change_cwd("mutants"):
        args = self._pytest_args_regular_run(tests)
        return int(self.execute_pytest(args, plugins=[Killer(mutant_name)]))
harness.PytestRunner._pytest_args_regular_run = ordered
harness.PytestRunner.run_tests = run_tests
from mutmut.__main__ import cli
cli.main(args=sys.argv[1:], standalone_mode=False)
"""


def mutmut_run(names: list[str], cap: int | None = MAX_TESTS_PER_MUTANT) -> None:
    """``mutmut run NAMES`` (mutmut reads its config from pyproject.toml in the cwd)."""
    if names:
        for copy in COPIES:
            shutil.rmtree(MUTANTS / copy, ignore_errors=True)
        code = (
            ORDERED_RUN.replace("OWN_TESTS", repr(OWN_TESTS))
            .replace("MAX_TESTS_PER_MUTANT", str(cap or 1_000_000))
            .replace("KILLERS", repr(str(KILLERS)))
        )
        command = [sys.executable, "-c", code, "run", "--max-children", str(WORKERS), *names]
        # mutmut runs its type_check_command as `python -m tests.mutate typecheck mypy`:
        # this interpreter's directory first on PATH makes `python` the one with mypy.
        path = f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"
        env = {**os.environ, "PATH": path, **MUTATE_ENV}
        subprocess.run(command, cwd=ROOT, check=False, env=env)


# A mutant function as mutmut writes it into mutants/: `def x_name__mutmut_12(` at the top
# level or `def xǁClassǁname__mutmut_12(` in its class.
MUTANT_DEF = re.compile(r"^(?:    )?def (\S+__mutmut_\d+)\(")
ANY_DEF = re.compile(r"^(?:    )?(?:def|class) |^\S")


def typecheck() -> int:
    """mypy --strict over the mutated packages, as JSON lines, errors inside mutants only.

    A mutant that fails the type check is caught: CI runs mypy --strict on the package,
    so it could never land. mutmut needs every error to fall inside a mutant; the copy it
    keeps of each original function (``__mutmut_orig``) is not one, and a few of those
    fail only because of their new name (mypy allows ``return NotImplemented`` in a
    method named ``__eq__`` alone), so errors outside mutants are left out here.
    """
    command = [sys.executable, "-m", "mypy", "--strict", "--no-warn-unused-ignores"]
    done = subprocess.run(
        [*command, "--output", "json", *PACKAGES], capture_output=True, text=True, check=False
    )
    lines: dict[str, list[str]] = {}
    for line in done.stdout.splitlines():
        if not line.strip():
            continue
        error = json.loads(line)
        source = lines.setdefault(error["file"], Path(error["file"]).read_text("utf-8").split("\n"))
        index = error["line"] - 1
        while index >= 0 and not ANY_DEF.match(source[index]):
            index -= 1
        if index >= 0 and MUTANT_DEF.match(source[index]):
            print(line)
    return 0


def generate() -> None:
    """Create or refresh mutants/ (mutmut does it as part of any run; this one runs nothing)."""
    if not MUTANTS.exists() or not any(results(m) for m in CORE):
        for copy in COPIES:
            shutil.rmtree(MUTANTS / copy, ignore_errors=True)
        subprocess.run([*MUTMUT, "run", "genparams.runtime.core.changes*"], cwd=ROOT, check=False)


def run(modules: list[str], *, which: tuple[str, ...]) -> None:
    """One mutmut run over the ``which`` mutants of ``modules`` (one clean-test pass)."""
    generate()
    explained = accepted()
    names = []
    for module in modules:
        codes = results(module).items()
        found = [n for n, code in codes if status(code) in which and n not in explained]
        print(f"{module}: {len(found)} {' or '.join(which)} mutants", flush=True)
        names += found
    mutmut_run(names)


def killer_tests(name: str) -> list[str]:
    """The test files written for the module of mutant ``name`` (KILLER_TESTS)."""
    prefix = max((k for k in KILLER_TESTS if name.startswith(k + ".")), key=len, default="")
    found = {str(f.relative_to(ROOT)) for g in KILLER_TESTS.get(prefix, ()) for f in ROOT.glob(g)}
    return sorted(found)


UNCAUGHT = ("survived", "suspicious", "no tests")
RECHECK_TIMEOUT_S = 300  # a set of KILLER_TESTS files takes seconds


def recheck(modules: list[str], which: tuple[str, ...] = UNCAUGHT) -> int:
    """Run each survivor (and mutant no test reached) against the tests written for it.

    A full mutmut pass over survivors runs up to MAX_TESTS_PER_MUTANT tests for each
    mutant that truly survives: minutes apiece. Here each runs the test files of
    KILLER_TESTS, four at a time, each in a DDS domain of its own; a mutant they kill
    is recorded as killed in mutmut's results, with the test that failed first.
    """
    from concurrent.futures import ThreadPoolExecutor

    explained = accepted()
    todo = [
        name
        for module in modules
        for name, code in results(module).items()
        if status(code) in which and name not in explained
    ]
    shutil.rmtree(MUTANTS / "tests", ignore_errors=True)  # the mutants stay, tests afresh
    shutil.copytree(ROOT / "tests", MUTANTS / "tests")
    for tests in {tuple(killer_tests(name)) for name in todo}:  # they pass with no mutant
        if run_one("", *tests) != "survived":
            print(f"these tests fail without a mutant in mutants/: {' '.join(tests)}")
            return 2
    slots = list(range(232 - 4, 232))

    def one(name: str) -> tuple[str, str, str]:
        domain = slots.pop()
        try:
            try:
                tests = killer_tests(name)
                done = pytest_under(name, tests, domain=domain, timeout=RECHECK_TIMEOUT_S)
            except subprocess.TimeoutExpired:  # a mutant that hangs its tests is caught
                return name, "timeout", ""
        finally:
            slots.append(domain)
        failed = re.search(r"^FAILED (\S+)", done.stdout, re.MULTILINE)
        verdict = "killed" if done.returncode == 1 and failed else "survived"
        return name, verdict, runnable(failed.group(1)) if failed else ""

    with ThreadPoolExecutor(4) as pool:
        for name, verdict, test in pool.map(one, todo):  # recorded as they come
            print(f"{verdict:9} {name}", flush=True)
            if verdict == "timeout":
                _record(name, code=-24)  # mutmut's own code for a timeout
            elif verdict == "survived":
                _record(name, code=0)
            else:
                _record(name, code=1)
                with KILLERS.open("a", encoding="utf-8") as out:
                    out.write(f"{name} {test}\n")
    return report()


def _record(name: str, code: int) -> None:
    module = next(m for m in all_modules() if name.startswith(m + "."))
    meta_path = MUTANTS / (module.replace(".", "/") + ".py.meta")
    meta = _meta(module)
    meta.setdefault("exit_code_by_key", {})[name] = code
    meta_path.write_text(json.dumps(meta), encoding="utf-8")


def score(counts: Counter[str]) -> float | None:
    """Caught / judged, equivalent mutants (no behaviour to catch) set aside."""
    caught = counts["killed"] + counts["timeout"] + counts["typed"]
    judged = caught + counts["survived"] + counts["suspicious"] + counts["no tests"]
    judged -= counts["equivalent"]
    return None if not judged else 100.0 * caught / judged


COLUMNS = ("typed", "killed", "timeout", "survived", "equivalent", "accepted", "no tests")


def report() -> int:
    """A Markdown table per module and in all; fails on a survivor not explained."""
    allowed = accepted()
    unexplained: list[str] = []
    total: Counter[str] = Counter()
    head = ("module", "mutants", *COLUMNS, "unchecked", "score")
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for module in all_modules():
        codes = results(module)
        if not codes:
            continue
        counts = Counter(status(code) for code in codes.values())
        for name, code in codes.items():
            if status(code) in ("survived", "suspicious", "no tests") and name in allowed:
                kind = "equivalent" if allowed[name].startswith("equivalent") else "accepted"
                counts[kind] += 1
            elif status(code) in ("survived", "suspicious"):
                unexplained.append(name)
        total += counts
        total["mutants"] += len(codes)
        _row(module, len(codes), counts)
    _row("**all**", total["mutants"], total)
    for name in unexplained:
        print(f"survivor not explained in {ACCEPTED.name}: {name}")
    known = {name for module in all_modules() for name in results(module)}
    stale = [name for name in allowed if known and name not in known]
    for name in stale:  # its function changed or went: the reason may no longer hold
        print(f"{ACCEPTED.name} names a mutant that no longer exists: {name}")
    return 1 if unexplained or stale else 0


def _row(module: str, mutants: int, counts: Counter[str]) -> None:
    value = score(counts)
    cells = [module, str(mutants), *(str(counts[c]) for c in COLUMNS), str(counts["unchecked"])]
    print("| " + " | ".join([*cells, "-" if value is None else f"{value:.1f}%"]) + " |")


def killers() -> dict[str, str]:
    """Mutant name -> the test that failed first under it, from the runs so far."""
    out = {}
    if KILLERS.exists():
        for line in KILLERS.read_text(encoding="utf-8").splitlines():
            name, _, test = line.partition(" ")
            if test:
                out[name] = test
    return out


def survivors(modules: list[str]) -> int:
    """Print the survivors (and mutants no test reaches) of ``modules`` not yet accepted."""
    allowed = accepted()
    for module in modules:
        for name, code in results(module).items():
            if status(code) in ("survived", "suspicious", "no tests") and name not in allowed:
                print(f"{status(code):9} {name}")
    return 0


# A recorded kill: the hash of its mutant's function as mutmut saw it, and the test that
# failed first under it.
Record = tuple[str, str]


def read_records(text: str) -> dict[str, Record]:
    """Mutant name -> its record, from the text of tests/mutation_killed.txt."""
    records = {}
    for line in text.splitlines():
        name, function_hash, test = [*line.split(" ", 2), "", ""][:3]
        if name and not name.startswith("#") and test:
            records[name] = (function_hash, test)
    return records


def rerecorded(
    old: dict[str, Record],
    codes: dict[str, int | None],
    hashes: dict[str, str],
    tests: dict[str, str],
) -> dict[str, Record]:
    """The records of the mutants in ``codes`` (a module's results in mutants/).

    A mutant a test killed is recorded afresh. One not yet checked keeps its old
    record while its function is unchanged, so a run stopped part way loses nothing
    still valid; any other old record (a survivor now, or of a changed function) goes.
    """
    records = {}
    for name, code in codes.items():
        if status(code) == "killed" and name in hashes and name in tests:
            records[name] = (hashes[name], tests[name])
        elif code is None and name in old and old[name][0] == hashes.get(name):
            records[name] = old[name]
    return records


def baseline(modules: Sequence[str] = ()) -> int:
    """Record the mutants a test killed: their function's hash and the test (see ``sample``).

    Without ``modules`` every record is written afresh from mutants/. With them only
    those modules' records are: the records of every other module stay as they are, so
    a run over a few modules can be recorded without a run over all of them.
    """
    known = all_modules()
    unknown = [module for module in modules if module not in known]
    if unknown:
        print(f"not a mutated module: {' '.join(unknown)}", file=sys.stderr)
        return 2
    chosen = list(modules) or known
    old = read_records(KILLED.read_text(encoding="utf-8")) if KILLED.exists() else {}
    hashes, tests = function_hashes(), killers()
    records = {}
    if modules:
        mine = tuple(module + "." for module in chosen)
        records = {name: record for name, record in old.items() if not name.startswith(mine)}
    for module in chosen:
        records |= rerecorded(old, results(module), hashes, tests)
    lines = "".join(f"{name} {h} {test}\n" for name, (h, test) in sorted(records.items()))
    KILLED.write_text(HEADER + lines, encoding="utf-8")
    print(f"{len(records)} killed mutants recorded in {KILLED.relative_to(ROOT)}")
    return 0


HEADER = """\
# Mutants a test killed in the last `make mutate` (`python -m tests.mutate baseline`):
# NAME, the hash of its function as mutmut saw it, and the test that failed first.
"""


def generate_only() -> None:
    """Write mutants/ afresh without running a test (mutmut's own first step)."""
    for copy in COPIES:
        shutil.rmtree(MUTANTS / copy, ignore_errors=True)
    code = (
        "from mutmut.__main__ import copy_src_dir, copy_also_copy_files, setup_source_paths,"
        " create_mutants\n"
        "copy_src_dir(); copy_also_copy_files(); setup_source_paths(); create_mutants(2)\n"
    )
    subprocess.run([sys.executable, "-c", code], cwd=ROOT, check=True)


def pytest_under(
    name: str,
    tests: Sequence[str],
    *,
    quiet: bool = True,
    domain: int | None = None,
    timeout: float | None = None,
) -> subprocess.CompletedProcess[str]:
    """``pytest -x TESTS`` in mutants/ with mutant ``name`` switched on ("" for none)."""
    command = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider", *tests]
    env = {**os.environ, **MUTATE_ENV, "MUTANT_UNDER_TEST": name}
    if domain is not None:
        env["ROS_DOMAIN_ID"] = str(domain)
    return subprocess.run(
        command, cwd=MUTANTS, env=env, capture_output=quiet, text=True, check=False, timeout=timeout
    )


RUN_ONE_TIMEOUT_S = 300  # far beyond any one test's run; a mutant that hangs one is caught


def run_one(name: str, *tests: str, quiet: bool = True) -> str:
    """``killed``, ``survived``, or ``gone`` (no such test any more) for one mutant.

    A run that outlasts ``RUN_ONE_TIMEOUT_S`` counts as killed, as mutmut counts a timeout.
    """
    try:
        done = pytest_under(name, tests, quiet=quiet, timeout=RUN_ONE_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return "killed"
    return {0: "survived", 1: "killed"}.get(done.returncode, "gone")


def try_tests(name: str, tests: list[str]) -> int:
    """Run ``tests`` (as in this tree now) against one mutant: does a new test kill it?"""
    if not (MUTANTS / "genparams").exists():
        generate_only()
    else:  # the mutants stay; the tests are copied afresh
        shutil.rmtree(MUTANTS / "tests", ignore_errors=True)
        shutil.copytree(ROOT / "tests", MUTANTS / "tests")
    if run_one("", *tests) != "survived":  # no mutant: the tests must pass in mutants/ too
        print(f"{' '.join(tests)} fail(s) without a mutant in mutants/: no verdict")
        return 2
    verdict = run_one(name, *tests, quiet=False)
    print(f"{name}: {verdict}")
    return 0 if verdict == "killed" else 1


def runnable(test: str) -> str:
    """A recorded test id pytest can run: one cut at a line break inside its parameters
    (recorded before the writer kept such ids whole) stands for all of its function's."""
    return test.split("[")[0] if "[" in test and not test.endswith("]") else test


def function_of(mutant: str) -> str:
    """``pkg.mod.x_f__mutmut_3`` -> ``pkg.mod.x_f``: the function a mutant changes."""
    return mutant.rsplit("__mutmut_", 1)[0]


def sibling_tests(name: str, recorded: dict[str, tuple[str, str]]) -> list[str]:
    """The tests recorded for the other mutants of ``name``'s function, but its own."""
    function = function_of(name)
    tests = {test for other, (_, test) in recorded.items() if function_of(other) == function}
    return sorted(tests - {recorded[name][1]})


def killed_by_a_sibling_test(name: str, recorded: dict[str, tuple[str, str]]) -> str:
    """The verdict on a mutant that survived its recorded test, from the tests recorded
    for the other mutants of its function.

    A recorded test is the first one that failed under the mutant at the baseline. A
    later change to a caller (a faster path that no longer goes through the function
    for that test's values) can leave that one test blind to the mutant while the
    tests written for the function still kill it: that is a stale record, not a weaker
    suite. Only a mutant none of its function's tests kill counts as no longer killed.
    """
    for test in sibling_tests(name, recorded):  # one at a time: a renamed test is "gone"
        if run_one("", test) != "survived":  # it fails (or is gone) without a mutant too
            continue
        if run_one(name, test) == "killed":
            print(f"{'':9} killed by {test}: the record above is stale", flush=True)
            return "killed"
    return "survived"


def sample(size: int, seed: int) -> int:
    """Run ``size`` recorded kills against their tests; a mutant that now survives fails.

    Each recorded kill names the test that failed under it, so a draw costs one test
    run and no mutmut stats pass. Only mutants of functions unchanged since the
    baseline are drawn: mutmut numbers the mutants of a changed function anew, so the
    same name may be another change. A test since renamed or removed is skipped.
    """
    recorded = {
        name: (function_hash, runnable(test))
        for name, (function_hash, test) in read_records(KILLED.read_text("utf-8")).items()
    }
    if not recorded:
        print(f"{KILLED.name} records no kills with their test: run `make mutate`, then baseline")
        return 1  # nothing could be drawn: a green run here would check nothing
    generate_only()
    current = function_hashes()
    drawable = sorted(n for n, (h, _) in recorded.items() if current.get(n) == h)
    stale = len(recorded) - len(drawable)
    if stale:
        print(f"{stale} of {len(recorded)} recorded kills are of changed or removed functions")
    if not drawable:
        print("nothing to draw: run `make mutate` then `python -m tests.mutate baseline`")
        return 0
    order = random.Random(seed).sample(drawable, len(drawable))
    verdicts: dict[str, str] = {}
    for name in order:
        if sum(v != "gone" for v in verdicts.values()) == size:
            break
        verdicts[name] = run_one(name, recorded[name][1])
        print(f"{verdicts[name]:9} {name}  ({recorded[name][1]})", flush=True)
        if verdicts[name] == "survived":
            verdicts[name] = killed_by_a_sibling_test(name, recorded)
    counts = Counter(verdicts.values())
    print(f"sample of {size} (seed {seed}): {dict(counts)}")
    weak = [n for n, v in verdicts.items() if v == "survived"]
    for name in weak:
        print(f"no longer killed: {name}  (see: {sys.executable} -m mutmut show {name})")
    return 1 if weak else 0


def main(argv: list[str]) -> int:
    command, *rest = argv or ["report"]
    if command == "run":
        run(rest or all_modules(), which=("unchecked",))
        report()
        return 0
    if command == "recheck":
        return recheck(rest or all_modules())
    if command == "quick" and rest:  # the unchecked mutants of these modules, as recheck runs them
        return recheck(rest, which=("unchecked",))
    if command == "report":
        return report()
    if command == "baseline":
        return baseline(rest)
    if command == "typecheck":
        return typecheck()
    if command == "survivors":
        return survivors(rest or all_modules())
    if command == "try" and len(rest) >= 2:
        return try_tests(rest[0], rest[1:])
    if command == "sample":
        size = int(rest[0]) if rest else 25
        seed = int(rest[1]) if len(rest) > 1 else random.SystemRandom().randrange(1 << 30)
        return sample(size, seed)
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
