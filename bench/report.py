"""Results -> docs/benchmarks.md (the targets, a table per scenario) and docs/benchmarks.csv."""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from dataclasses import dataclass, field

from bench import build_scenarios as build
from bench import memory_scenarios as memory
from bench import node_scenarios as nodes
from bench.measure import Result
from bench.schemas import bench_schema
from bench.targets import Judged


@dataclass(frozen=True)
class Section:
    scenario: str
    title: str
    text: str
    variants: tuple[str, ...]
    ratios: tuple[tuple[str, str], ...] = ()  # (numerator, denominator) variants
    per_parameter: tuple[str, ...] = ()  # variants also shown divided by N


SECTIONS: tuple[Section, ...] = (
    Section(
        "codegen",
        "Code generation",
        "Schema file to generated module: load, check, build, render. The whole process "
        "includes starting Python and importing the generator; its CPU time (user + system) "
        "is what the targets are judged on, as the wall-clock time also counts waiting for "
        "the shared cores. In process, the generator's caches are warm.",
        (build.GENERATE_PROCESS, build.GENERATE_PROCESS_WALL, build.GENERATE_CALL),
        per_parameter=(build.GENERATE_CALL,),
    ),
    Section(
        "codegen_stages",
        "Code generation, stage by stage",
        "The in-process pipeline timed one stage at a time (CPU time), to show where "
        "generation time goes.",
        (build.STAGE_LOAD, build.STAGE_CHECK, build.STAGE_BUILD, build.STAGE_RENDER),
        per_parameter=(build.STAGE_LOAD, build.STAGE_CHECK, build.STAGE_BUILD, build.STAGE_RENDER),
    ),
    Section(
        "import",
        "Importing the module",
        "A fresh process per sample (CPU time) that has already imported rclpy, its messages and "
        "genparams.runtime, as any node has; the time is the module's own. The generated "
        "module builds its classes and parameter specs at import; the hand-written module "
        "only defines a function (its descriptors are built when it declares).",
        (build.GENPARAMS_COLD, build.PLAIN_COLD, build.GENPARAMS_WARM, build.PLAIN_WARM),
        ratios=((build.GENPARAMS_COLD, build.PLAIN_COLD), (build.GENPARAMS_WARM, build.PLAIN_WARM)),
    ),
    Section(
        "declare",
        "Declaring on a node",
        "`XParams.declare(node)` against the hand-written `node.declare_parameters` with the "
        "same names and descriptors plus a trivial on-set callback. Each sample is the first "
        "declaration of a freshly imported module on a new node, so genparams' one-off "
        "compilation of its specs is included. rclpy itself sets every parameter one by "
        "one and publishes a ParameterEvent for each, on both sides.",
        (nodes.GENPARAMS, nodes.PLAIN),
        ratios=((nodes.GENPARAMS, nodes.PLAIN),),
        per_parameter=(nodes.GENPARAMS, nodes.PLAIN),
    ),
    Section(
        "read",
        "Reading one value",
        "One read of a parameter at full depth (`depth` attribute hops) with `timeit`. "
        "The plain attribute chain is nested `SimpleNamespace` objects holding the same "
        "values. Each row includes timeit's loop overhead, shown on its own.",
        (nodes.READ_GENPARAMS, nodes.READ_CHAIN, nodes.READ_NODE, nodes.READ_LOOP),
        ratios=((nodes.READ_GENPARAMS, nodes.READ_CHAIN),),
    ),
    Section(
        "snapshot",
        "A consistent view of every value",
        "`cfg.snapshot()` hands out the current immutable tree. The closest plain-rclpy "
        "equivalent reads every parameter.",
        (nodes.SNAPSHOT_GENPARAMS, nodes.SNAPSHOT_PLAIN),
    ),
    Section(
        "set_one",
        "Setting one parameter (node.set_parameters)",
        "One parameter set to a new value through `node.set_parameters`: genparams validates "
        "it and commits it to the typed view; plain rclpy runs a callback that accepts "
        "everything. Both pay rclpy's own descriptor checks and ParameterEvent publication.",
        (nodes.GENPARAMS, nodes.PLAIN),
        ratios=((nodes.GENPARAMS, nodes.PLAIN),),
    ),
    Section(
        "set_one_service",
        "Setting one parameter through the parameter service",
        "What `ros2 param set` does: a `SetParameters` request from a client node in the same "
        "process and executor, timed until the response arrives.",
        (nodes.GENPARAMS, nodes.PLAIN),
        ratios=((nodes.GENPARAMS, nodes.PLAIN),),
    ),
    Section(
        "set_all",
        "Setting all N parameters (node.set_parameters, one by one)",
        "Every parameter to a new value in one `set_parameters` call, which rclpy applies "
        "one parameter at a time.",
        (nodes.GENPARAMS, nodes.PLAIN),
        ratios=((nodes.GENPARAMS, nodes.PLAIN),),
        per_parameter=(nodes.GENPARAMS, nodes.PLAIN),
    ),
    Section(
        "set_all_atomic",
        "Setting all N parameters atomically",
        "Every parameter in one `set_parameters_atomically` call: one validation pass and "
        "one commit of the whole tree.",
        (nodes.GENPARAMS, nodes.PLAIN),
        ratios=((nodes.GENPARAMS, nodes.PLAIN),),
        per_parameter=(nodes.GENPARAMS, nodes.PLAIN),
    ),
    Section(
        "memory",
        "Memory of a node with N parameters",
        "A fresh process per sample: rclpy initialised with one node is the baseline; then "
        "the module is imported (from its .pyc, as when installed) and its parameters "
        "declared. RSS growth is what the operating system sees (page-granular: Python's "
        "allocator reuses freed memory, so it reads near zero at small N); the Python heap "
        "still allocated afterwards (tracemalloc) is exact. genparams' figures include "
        "importing its runtime.",
        (
            memory.RSS_GENPARAMS,
            memory.RSS_PLAIN,
            memory.TRACED_GENPARAMS,
            memory.TRACED_PLAIN,
        ),
        ratios=(
            (memory.RSS_GENPARAMS, memory.RSS_PLAIN),
            (memory.TRACED_GENPARAMS, memory.TRACED_PLAIN),
        ),
    ),
)


class Results:
    def __init__(self, results: Sequence[Result]) -> None:
        self.by_key = {(r.scenario, r.variant, r.size): r for r in results}
        self.sizes = sorted({r.size for r in results})

    def get(self, scenario: str, variant: str, size: int) -> Result | None:
        return self.by_key.get((scenario, variant, size))

    def sizes_of(self, scenario: str, variant: str) -> list[int]:
        return [n for n in self.sizes if (scenario, variant, n) in self.by_key]

    def ratio(self, scenario: str, pair: tuple[str, str], size: int) -> tuple[float, float] | None:
        top, bottom = self.get(scenario, pair[0], size), self.get(scenario, pair[1], size)
        if top is None or bottom is None or bottom.min <= 0 or bottom.median <= 0:
            return None
        return top.min / bottom.min, top.median / bottom.median


def format_seconds(value: float) -> str:
    for scale, unit in ((1.0, "s"), (1e-3, "ms"), (1e-6, "µs")):
        if abs(value) >= scale:
            return f"{value / scale:.3g} {unit}"
    return f"{value / 1e-9:.3g} ns"


def format_bytes(value: float) -> str:
    for scale, unit in ((2**30, "GiB"), (2**20, "MiB"), (2**10, "KiB")):
        if abs(value) >= scale:
            return f"{value / scale:.3g} {unit}"
    return f"{value:.0f} B"


def format_value(value: float, unit: str) -> str:
    return format_bytes(value) if unit == "B" else format_seconds(value)


def section_table(section: Section, results: Results) -> str:
    header = ["N", "depth"]
    for variant in section.variants:
        header.append(f"{variant}: min / median")
    for variant in section.per_parameter:
        header.append(f"{variant}: per parameter (min)")
    for top, bottom in section.ratios:
        header.append(f"{_short(top)} ÷ {_short(bottom)}: min / median")
    rows = []
    for size in results.sizes:
        row = [f"{size:,}", str(bench_schema(size).depth)]
        present = False
        for variant in section.variants:
            result = results.get(section.scenario, variant, size)
            if result is None:
                row.append("–")
                continue
            present = True
            row.append(
                f"{format_value(result.min, result.unit)} / "
                f"{format_value(result.median, result.unit)}"
            )
        for variant in section.per_parameter:
            result = results.get(section.scenario, variant, size)
            row.append("–" if result is None else format_seconds(result.min / size))
        for pair in section.ratios:
            ratio = results.ratio(section.scenario, pair, size)
            row.append("–" if ratio is None else f"{ratio[0]:.2f} / {ratio[1]:.2f}")
        if present:
            rows.append(row)
    if not rows:
        return "_not measured in this run_\n"
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines.extend("| " + " | ".join(row) + " |" for row in rows)
    return "\n".join(lines) + "\n"


def _short(variant: str) -> str:
    return variant.split(":")[0].split(",")[0]


@dataclass(frozen=True)
class TargetOutcome:
    target: str
    measured: str
    met: bool | None  # None: not measured in this run

    @property
    def verdict(self) -> str:
        return {True: "met", False: "**missed**", None: "not measured"}[self.met]


@dataclass
class Targets:
    results: Results
    outcomes: list[TargetOutcome] = field(default_factory=list)

    def evaluate(self) -> list[TargetOutcome]:
        self.codegen_under(1_000, 1.0)
        self.codegen_under(10_000, 5.0)
        self.linear("codegen", build.GENERATE_PROCESS, "codegen grows linearly (whole process CPU)")
        pair = (nodes.GENPARAMS, nodes.PLAIN)
        self.ratio_at_most("set_one_service", pair, 1.3, "one set (parameter service)")
        self.flat("set_one", nodes.GENPARAMS, "one set independent of N")
        self.linear("set_all", nodes.GENPARAMS, "set all grows linearly (one by one)")
        self.linear("set_all_atomic", nodes.GENPARAMS, "set all grows linearly (atomic)")
        return self.outcomes

    def add(self, target: str, measured: str, met: bool | None) -> None:
        self.outcomes.append(TargetOutcome(target, measured, met))

    def codegen_under(self, size: int, limit: float) -> None:
        target = (
            f"codegen of {size:,} parameters under {limit:g} s (whole process CPU time, median)"
        )
        result = self.results.get("codegen", build.GENERATE_PROCESS, size)
        if result is None:
            self.add(target, "–", None)
        else:
            self.add(target, format_seconds(result.median), result.median < limit)

    def ratio_at_most(self, scenario: str, pair: tuple[str, str], limit: float, what: str) -> None:
        target = f"{what}: within {limit:g}x of plain at every N (ratio of minimums)"
        ratios = {
            n: r[0]
            for n in self.results.sizes
            if (r := self.results.ratio(scenario, pair, n)) is not None
        }
        if not ratios:
            self.add(target, "–", None)
            return
        worst = max(ratios, key=ratios.__getitem__)
        measured = ", ".join(f"{r:.2f} at {n:,}" for n, r in ratios.items())
        self.add(target, measured, ratios[worst] <= limit)

    def flat(self, scenario: str, variant: str, target: str, limit: float = 1.5) -> None:
        sizes = self.results.sizes_of(scenario, variant)
        target = f"{target} (largest N ÷ smallest N ≤ {limit:g}, minimums)"
        if len(sizes) < 2:
            self.add(target, "–", None)
            return
        first = self.results.get(scenario, variant, sizes[0])
        last = self.results.get(scenario, variant, sizes[-1])
        assert first is not None and last is not None
        growth = last.min / first.min
        measured = (
            f"{format_seconds(first.min)} at {sizes[0]:,}, "
            f"{format_seconds(last.min)} at {sizes[-1]:,}: {growth:.2f}x"
        )
        self.add(target, measured, growth <= limit)

    def linear(self, scenario: str, variant: str, target: str, limit: float = 1.5) -> None:
        """Per-parameter marginal cost of the last step ≤ limit x that of the step before."""
        sizes = self.results.sizes_of(scenario, variant)
        target = (
            f"{target}: marginal cost per parameter between the two largest N "
            f"≤ {limit:g}x that of the step before (minimums)"
        )
        if len(sizes) < 3:
            self.add(target, "–", None)
            return
        times = {}
        for n in sizes[-3:]:
            result = self.results.get(scenario, variant, n)
            assert result is not None
            times[n] = result.min
        a, b, c = sizes[-3:]
        before = (times[b] - times[a]) / (b - a)
        last = (times[c] - times[b]) / (c - b)
        measured = (
            f"{format_seconds(before)} per parameter from {a:,} to {b:,}, "
            f"{format_seconds(last)} from {b:,} to {c:,}"
        )
        self.add(target, measured, before > 0 and last <= limit * before)


def runtime_targets(judged: Sequence[Judged]) -> str:
    """The runtime's targets (bench/targets.py), each met or missed, with its numbers."""
    if not judged:
        return "_not measured in this run_\n"
    lines = ["| target | limit | measured | verdict |", "|---|---|---|---|"]
    for outcome in judged:
        verdict = "met" if outcome.met else "**missed**"
        measured = outcome.measured.replace("|", "\\|")
        lines.append(f"| {outcome.target} | {outcome.limit_text} | {measured} | {verdict} |")
    return "\n".join(lines) + "\n"


def markdown(
    results: Sequence[Result],
    machine: dict[str, str],
    command: str,
    judged: Sequence[Judged] = (),
) -> str:
    table = Results(results)
    outcomes = Targets(table).evaluate()
    out = io.StringIO()
    out.write("# Benchmarks\n\n")
    out.write(
        "genparams side by side with hand-written rclpy declaring the same parameters, "
        f"measured in one run by `{command}`. Each cell is the minimum / median over the "
        "repeats; ratios are genparams ÷ plain from the same run, and targets are judged on "
        "minimums, the least disturbed by other work on the machine. In-process times are "
        "CPU time of the measuring thread (`time.thread_time`), which other processes on a "
        "shared machine barely inflate; service round trips are wall-clock time, and whole "
        "processes are shown both ways. Samples of the two sides alternate. The raw numbers are in "
        "[benchmarks.csv](benchmarks.csv). Where the time of a declare and of one set goes, "
        "and why those targets are missed: [benchmarks-profile.md](benchmarks-profile.md) "
        "(`make bench-profile`).\n\n"
    )
    out.write(
        "The schemas have N parameters in groups of ten, one of each kind (double with a "
        "range, int with a stepped range, string with choices, bool, double with `gt`, "
        "string_array with `not_empty` and `unique`, int_array with `element_bounds`, "
        "double_array with `length`, string with `pattern`, int with `bounds`), nested in "
        "namespaces at most ten wide (`a3.b7.gain`); `depth` is the number of attribute "
        "hops to a parameter. They are written by `bench/schemas.py`.\n\n"
    )
    out.write("## Machine\n\n| | |\n|---|---|\n")
    for key, value in machine.items():
        out.write(f"| {key} | {value} |\n")
    out.write(
        "\n## Runtime targets\n\n"
        "Measured by `bench/targets.py` (also alone: `make bench-targets`) against hand-written "
        "rclpy in the same process, the two sides interleaved, as the ratio of the minimum CPU "
        "times of many short samples (RSS and whole processes: one fresh process per sample). "
        "Spreads are minimum / median / 90th percentile. The declare target times a fresh node "
        "declaring a class already declared once in the process (the first declaration, which "
        "compiles the class, is in [Declaring on a node](#declaring-on-a-node)). Where a target "
        "is missed, [benchmarks-profile.md](benchmarks-profile.md) shows the floor.\n\n"
    )
    out.write(runtime_targets(judged))
    out.write("\n## Other checks\n\n| target | measured | verdict |\n|---|---|---|\n")
    for outcome in outcomes:
        out.write(f"| {outcome.target} | {outcome.measured} | {outcome.verdict} |\n")
    for section in SECTIONS:
        out.write(f"\n## {section.title}\n\n{section.text}\n\n")
        out.write(section_table(section, table))
    return out.getvalue()


def csv_text(results: Sequence[Result]) -> str:
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["scenario", "variant", "n", "unit", "repeats", "min", "median", "samples"])
    for r in sorted(results, key=lambda r: (r.scenario, r.variant, r.size)):
        writer.writerow(
            [
                r.scenario,
                r.variant,
                r.size,
                r.unit,
                len(r.samples),
                f"{r.min:.9g}",
                f"{r.median:.9g}",
                " ".join(f"{s:.9g}" for s in r.samples),
            ]
        )
    return out.getvalue()
