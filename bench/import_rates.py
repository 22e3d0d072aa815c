"""import-rclpy's exact-import rate on public rclpy nodes, measured again from scratch.

    python -m bench.import_rates --mirrors DIR [--sample table|wide|all] [--only TEXT]

``DIR`` holds bare git copies of the repositories the manifest names
(``bench/import_rates_data/nodes.yaml``), one per repository, named ``owner+name`` (a
``repo`` folder in it is used when present). Each repository is exported at the
manifest's commit into a temporary folder; each node is imported

- *file by file*: the node's file copied alone into an empty folder;
- *whole*: the file in its repository, with its package and the manifest's params file;

and the class generated from each schema is declared on a real rclpy node, next to the
node's own code run on a real rclpy node (``bench.import_rates_node``). A parameter counts
*exact* when the import says so and, where the node's own run declared it, the generated
class declares it with the same descriptor fields and value. Prints a Markdown table, its
totals and the crashes (an exception of the import or of the generated module).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import pty
import shutil
import subprocess
import sys
import tempfile
import threading
from collections.abc import Iterator
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import yaml

import genparams
from genparams.importing import APPROXIMATE, EXACT, LEFT_OUT, schema_text
from genparams.rclpy_import.node_file import NodeFileError, import_node, node_name, scanned
from genparams.runtime.core.naming import class_name
from tests.domains import hold_free_domain
from tests.rclpy_import.declared import schema_key

MANIFEST = Path(__file__).parent / "import_rates_data" / "nodes.yaml"
RUN_TIMEOUT = 120
# How a node's own run ends once its constructor is done: it spins, or is still running
# when its time is up (bench.import_rates_node), or returns.
FINISHED = ("", "spin", "Stopped: timer")
SCRIPT_DOMAINS = range(101, 200)  # tests/domains.py: scripts' own, apart from test runs
# What a node's import and its run read: the repository's files of these kinds (a mirror
# may lack its largest files, images and meshes, which git archive cannot then export).
EXPORTED = (".py", ".yaml", ".yml", ".xml", ".cfg", ".toml", ".json", ".txt")


@dataclass(frozen=True)
class Entry:
    sample: str
    repo: str
    commit: str
    file: str
    cls: str | None = None
    params: str | None = None


@dataclass(frozen=True)
class Measured:
    """One import of one node, and what a real node made of it."""

    parameters: int = 0  # as the import counts them (one per declaring statement or item)
    exact: int = 0  # counted exact by the import and not contradicted on a real node
    checked: int = 0  # of them, declared alike by the node's own run
    approximate: int = 0
    left_out: int = 0
    differ: tuple[str, ...] = ()  # exact by the import, declared otherwise on a real node
    node_only: tuple[str, ...] = ()  # declared by the node's own run, not by the class
    class_only: tuple[str, ...] = ()  # declared by the class, not by the node's finished run
    crash: str = ""
    refused: str = ""  # a clean refusal (no declaration found): nothing imported


def entries(sample: str, manifest: Path = MANIFEST) -> list[Entry]:
    data = yaml.safe_load(manifest.read_text("utf-8"))
    chosen = ["table", "wide"] if sample == "all" else [sample]
    return [
        Entry(s, item["repo"], item["commit"], item["file"], item.get("class"), item.get("params"))
        for s in chosen
        for item in data[s] or []
    ]


def export(mirrors: Path, entry: Entry, into: Path) -> Path:
    """The repository at the entry's commit (its files of the kinds EXPORTED names),
    written once into ``into``."""
    owner_name = entry.repo.replace("/", "+")
    tree = into / f"{owner_name}@{entry.commit[:10]}"
    if tree.exists():
        return tree
    git_dir = mirrors / owner_name
    for inner in ("repo/.git", "repo"):
        if (git_dir / inner / "HEAD").exists():
            git_dir = git_dir / inner
            break
    git = ["git", f"--git-dir={git_dir}"]
    listing = subprocess.run([*git, "ls-tree", "-r", "-z", entry.commit], capture_output=True,
                             check=True).stdout.decode().split("\0")  # fmt: skip
    blobs = [line.split("\t", 1) for line in listing if line]
    wanted = [(meta.split()[2], path) for meta, path in blobs  # regular files only
              if meta.split()[0] in ("100644", "100755") and path.endswith(EXPORTED)]  # fmt: skip
    request = "".join(f"{sha}\n" for sha, _ in wanted).encode()
    batch = subprocess.run([*git, "cat-file", "--batch"], input=request, capture_output=True,
                           check=True).stdout  # fmt: skip
    at = 0
    for _, path in wanted:
        header_end = batch.index(b"\n", at)
        header = batch[at:header_end].split()
        at = header_end + 1
        if header[-1] == b"missing":
            continue
        size = int(header[2])
        target = tree / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(batch[at : at + size])
        at += size + 1
    return tree


def _child(args: list[str]) -> dict[str, Any]:
    """One run of bench.import_rates_node, on a terminal of its own (a teleop node draws
    on one); its JSON, or the reason it gave none."""
    repository = Path(__file__).parent.parent
    env = dict(os.environ, ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST", ROS_VERSION="2",
               TERM="xterm", PYTHONPATH=os.pathsep.join(
                   [str(repository), *filter(None, [os.environ.get("PYTHONPATH")])]))  # fmt: skip
    with tempfile.TemporaryDirectory(prefix="import-rates-run-") as temp:
        out = Path(temp) / "declared.json"
        controller, terminal = pty.openpty()
        drain = threading.Thread(target=_drain, args=(controller,), daemon=True)
        drain.start()
        try:
            subprocess.run(
                [sys.executable, "-m", "bench.import_rates_node", "--out", str(out), *args],
                stdin=terminal, stdout=terminal, stderr=terminal, timeout=RUN_TIMEOUT,
                env=env, check=False, cwd=temp,  # what a node writes stays in there
            )  # fmt: skip
        except subprocess.TimeoutExpired:
            return {"declared": {}, "stopped": "no answer in time", "node": None}
        finally:
            os.close(terminal)
            drain.join(timeout=10)
            os.close(controller)
        if not out.exists():
            return {"declared": {}, "stopped": "the run wrote nothing", "node": None}
        result: dict[str, Any] = json.loads(out.read_text("utf-8"))
        return result


def _drain(controller: int) -> None:
    """Read what the run prints on its terminal, so that it never waits on a full one."""
    with contextlib.suppress(OSError):
        while os.read(controller, 65536):
            pass


def original(tree: Path, entry: Entry) -> dict[str, Any]:
    args = ["original", str(tree), str(tree / entry.file)]
    args += ["--class", entry.cls] if entry.cls else []
    args += ["--params-file", str(tree / entry.params)] if entry.params else []
    return _child(args)


def measure(
    file: Path,
    entry: Entry,
    params: Path | None,
    node: dict[str, Any],
    work: Path,
    launch_params: Path | None = None,
) -> Measured:
    """Import ``file`` (reading ``params``), generate its class, declare it on a real node
    launched with ``launch_params`` (default ``params``) as the node's own run was, and
    compare."""
    from genparams.commands.import_rclpy import _overrides  # the command's own reading

    try:
        text = file.read_text("utf-8")
        overrides: dict[str, Any] = {}
        given_by = ""
        if params is not None:  # as the command reads it: the section of the node's name
            _, unit = scanned(text, str(file), entry.cls)
            overrides, given_by = _overrides([params], node_name(unit))
        result = import_node(text, str(file), entry.cls, overrides, given_by)
    except NodeFileError as exc:
        return Measured(refused=str(exc).rpartition(": ")[2])
    except Exception as exc:  # anything else the import raises is a crash
        return Measured(crash=f"import: {type(exc).__name__}: {exc}")
    imported = result.imported
    counts = Measured(
        parameters=imported.parameters,
        exact=imported.count(EXACT),
        approximate=imported.count(APPROXIMATE),
        left_out=imported.count(LEFT_OUT),
    )
    if not imported.imported:
        return counts
    try:
        schema = work / f"{imported.name}.yaml"
        schema.write_text(schema_text(imported, []), encoding="utf-8")
        module = work / f"{imported.name}_params.py"
        module.write_text(genparams.generate(schema), encoding="utf-8")
    except Exception as exc:  # the schema written or its module: a crash
        return replace(counts, crash=f"generate: {type(exc).__name__}: {exc}")
    name = node.get("node") or node_name(result.unit) or imported.name
    args = ["generated", str(module), class_name(imported.name), name]
    launched_with = launch_params or params
    ours = _child([*args, *(["--params-file", str(launched_with)] if launched_with else [])])
    if ours.get("stopped"):
        return replace(counts, crash=f"declare: {ours['stopped']}")
    return _compared(counts, imported.outcomes, ours["declared"], node)


def _compared(
    counts: Measured, outcomes: Any, ours: dict[str, Any], node: dict[str, Any]
) -> Measured:
    """Exact outcomes a real node contradicts are not exact: a parameter the class
    declares otherwise than the node's own run, or one it declares that the run, having
    finished its constructor, does not."""
    theirs: dict[str, Any] = node.get("declared", {})
    exact_keys = {o.key for o in outcomes if o.fate == EXACT and o.key}
    differ = sorted(n for n in set(ours) & set(theirs) if ours[n] != theirs[n]
                    and schema_key(exact_keys, n) is not None)  # fmt: skip
    finished = node.get("node") is not None and node.get("stopped", "") in FINISHED
    class_only = sorted(set(ours) - set(theirs)) if finished else []
    wrong = [n for n in [*differ, *class_only] if schema_key(exact_keys, n) is not None]
    wrong_keys = {schema_key(exact_keys, n) for n in wrong}
    alike = {schema_key(exact_keys, n) for n in set(ours) & set(theirs) if ours[n] == theirs[n]}
    return replace(
        counts,
        exact=counts.exact - len(wrong_keys),
        checked=len(alike - wrong_keys - {None}),
        differ=tuple(differ),
        class_only=tuple(class_only),
        node_only=tuple(sorted(set(theirs) - set(ours))),
    )


def alone(file: Path, into: Path) -> Path:
    """The node's file copied alone into an empty folder."""
    into.mkdir(parents=True)
    copy = into / file.name
    shutil.copyfile(file, copy)
    return copy


@dataclass(frozen=True)
class Row:
    entry: Entry
    node: dict[str, Any]
    by_file: Measured
    whole: Measured


def rows(mirrors: Path, chosen: list[Entry]) -> Iterator[Row]:
    with tempfile.TemporaryDirectory(prefix="import-rates-") as temp:
        base = Path(temp)
        for index, entry in enumerate(chosen):
            tree = export(mirrors, entry, base / "trees")
            node = original(tree, entry)
            work = base / f"work{index}"
            file = tree / entry.file
            params = tree / entry.params if entry.params else None
            copy = alone(file, work / "alone")
            by_file = measure(copy, entry, None, node, work / "alone", launch_params=params)
            (work / "whole").mkdir()
            whole = measure(file, entry, params, node, work / "whole")
            yield Row(entry, node, by_file, whole)


def main(argv: list[str] | None = None) -> int:
    from bench.import_rates_report import report

    parser = argparse.ArgumentParser(prog="python -m bench.import_rates", description=__doc__)
    parser.add_argument("--mirrors", type=Path, required=True, metavar="DIR")
    parser.add_argument("--manifest", type=Path, default=MANIFEST, metavar="FILE")
    parser.add_argument("--sample", choices=["table", "wide", "all"], default="all")
    parser.add_argument("--only", default="", help="only entries whose file contains TEXT")
    parser.add_argument("--details", action="store_true", help="list differing names")
    args = parser.parse_args(argv)
    if "ROS_DOMAIN_ID" not in os.environ:  # the nodes' runs: a domain no other run shares
        os.environ["ROS_DOMAIN_ID"] = str(hold_free_domain(SCRIPT_DOMAINS))
    chosen = [e for e in entries(args.sample, args.manifest) if args.only in e.file]
    measured = []
    for row in rows(args.mirrors, chosen):
        measured.append(row)
        print(f"measured {row.entry.repo} {row.entry.file}", file=sys.stderr, flush=True)
    sys.stdout.write(report(measured, details=args.details))
    return 1 if any(r.by_file.crash or r.whole.crash for r in measured) else 0


if __name__ == "__main__":
    sys.exit(main())
