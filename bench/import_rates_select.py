"""The wide sample of ``bench.import_rates``, chosen by its rule rather than by hand.

    python -m bench.import_rates_select --mirrors DIR [OWNER/NAME[@BRANCH] ...]

Each repository (default: the manifest's ``repositories``) is read at the newest commit
of its ``jazzy`` (or ``jazzy-devel``) branch where it has one, else of ``BRANCH``, else
of its default branch. Printed, as manifest entries: every class, in a Python file
outside test folders, that subclasses ``Node`` (or a node class of the same repository),
is subclassed by no other node class, and calls ``declare_parameter``,
``get_parameter``, ... or, on ``self``, a method of a node class of the repository
(other than ``__init__`` and the like) that calls one; at
most the first ten of a repository by path; none in a file of the manifest's table. A
folder is a test folder when a word of its name (split at ``_`` and ``-``) is test,
tests or testing. A file with several such classes gives one entry per class
(``class``). ``params`` is the first YAML file, by path, of the node's package (the
folder of its nearest ``package.xml``) with a section for the node's name holding
``ros__parameters``. Nothing is run: the files are read from git and parsed.
"""

from __future__ import annotations

import argparse
import ast
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import Any

import yaml

NODE_CLASSES = {"Node", "LifecycleNode"}
# Calls on a node that declare or read its parameters.
PARAMETER_CALLS = {
    "declare_parameter",
    "declare_parameters",
    "get_parameter",
    "get_parameters",
    "get_parameter_or",
    "get_parameters_by_prefix",
    "has_parameter",
}
TEST_WORDS = {"test", "tests", "testing"}  # a folder named by one: tests, nav2_system_tests
BRANCHES = ("jazzy", "jazzy-devel")  # preferred where a repository has one
MOST_PER_REPOSITORY = 10


@dataclass(frozen=True)
class Candidate:
    path: str
    cls: str
    bases: tuple[str, ...]
    called: frozenset[str]  # parameter calls on anything, and the methods called on self
    helpers: frozenset[str]  # its methods (not __init__ and the like) calling one
    node_name: str | None


def _git(git_dir: Path, *args: str) -> bytes:
    return subprocess.run(["git", f"--git-dir={git_dir}", *args], capture_output=True,
                          check=True).stdout  # fmt: skip


def git_dir(mirrors: Path, repo: str) -> Path:
    """The bare git copy of ``repo`` in ``mirrors`` (``owner+name``, or its ``repo`` folder)."""
    folder = mirrors / repo.replace("/", "+")
    for inner in ("repo/.git", "repo"):
        if (folder / inner / "HEAD").exists():
            return folder / inner
    return folder


def _files(git: Path, commit: str) -> dict[str, str]:
    """Path -> blob of the commit's Python, YAML and package.xml files."""
    listing = _git(git, "ls-tree", "-r", "-z", commit).decode().split("\0")
    kept = {}
    for line in filter(None, listing):
        meta, path = line.split("\t", 1)
        mode, _, sha = meta.split()
        if mode in ("100644", "100755") and path.endswith((".py", ".yaml", ".yml", "package.xml")):
            kept[path] = sha
    return kept


def _texts(git: Path, blobs: dict[str, str]) -> dict[str, bytes]:
    request = "".join(f"{sha}\n" for sha in blobs.values()).encode()
    batch = _git_input(git, request)
    texts, at = {}, 0
    for path in blobs:
        header_end = batch.index(b"\n", at)
        header = batch[at:header_end].split()
        at = header_end + 1
        if header[-1] == b"missing":
            continue
        size = int(header[2])
        texts[path] = batch[at : at + size]
        at += size + 1
    return texts


def _git_input(git: Path, request: bytes) -> bytes:
    return subprocess.run(["git", f"--git-dir={git}", "cat-file", "--batch"], input=request,
                          capture_output=True, check=True).stdout  # fmt: skip


def _base_name(base: ast.expr) -> str:
    if isinstance(base, ast.Attribute):
        return base.attr
    if isinstance(base, ast.Name):
        return base.id
    return ""


def _node_name(cls: ast.ClassDef) -> str | None:
    """The literal name the class gives its node: ``super().__init__("x")``."""
    for node in ast.walk(cls):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)):
            continue
        if node.func.attr != "__init__":
            continue
        written = [k.value for k in node.keywords if k.arg == "node_name"] + node.args[:1]
        for value in written:
            if isinstance(value, ast.Constant) and isinstance(value.value, str):
                return value.value
    return None


def _classes(path: str, text: bytes) -> list[Candidate]:
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError):
        return []
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.ClassDef):
            continue
        helpers = frozenset(
            method.name
            for method in node.body
            if isinstance(method, ast.FunctionDef)
            and not method.name.startswith("__")
            and _calls(method) & PARAMETER_CALLS
        )
        bases = tuple(_base_name(b) for b in node.bases)
        called = _calls(node) & PARAMETER_CALLS | _calls(node, on_self=True)
        found.append(Candidate(path, node.name, bases, called, helpers, _node_name(node)))
    return found


def _calls(node: ast.AST, *, on_self: bool = False) -> frozenset[str]:
    """The names of the methods called in ``node``: on anything, or on ``self`` only."""
    return frozenset(
        call.func.attr
        for call in ast.walk(node)
        if isinstance(call, ast.Call)
        and isinstance(call.func, ast.Attribute)
        and (not on_self or getattr(call.func.value, "id", "") == "self")
    )


def _node_classes(candidates: list[Candidate]) -> set[str]:
    """The names of the classes of the repository that are nodes: Node, and every class
    of it subclassing one, however deep."""
    nodes = set(NODE_CLASSES)
    grown = True
    while grown:
        more = {c.cls for c in candidates if set(c.bases) & nodes} - nodes
        nodes |= more
        grown = bool(more)
    return nodes


def _outside_tests(path: str) -> bool:
    folders = PurePosixPath(path).parts[:-1]
    return not any(set(re.split(r"[_\-]", folder.lower())) & TEST_WORDS for folder in folders)


def _package_of(path: str, packages: set[str]) -> str:
    for parent in PurePosixPath(path).parents:
        if str(parent) in packages:
            return str(parent)
    return ""


def _params_file(name: str | None, package: str, texts: dict[str, bytes]) -> str | None:
    if name is None:
        return None
    for path in sorted(texts):
        if not path.endswith((".yaml", ".yml")) or not _outside_tests(path):
            continue
        if package and not path.startswith(f"{package}/"):
            continue
        try:
            data: Any = yaml.safe_load(texts[path])
        except yaml.YAMLError:
            continue
        section = data.get(name) if isinstance(data, dict) else None
        if isinstance(section, dict) and "ros__parameters" in section:
            return path
    return None


def _commit(git: Path, branch: str | None) -> str:
    """The newest commit of the Jazzy branch where there is one, else of ``branch``, else
    of the default branch."""
    for name in [*(f"refs/heads/{b}" for b in BRANCHES), branch or "HEAD"]:
        verify = ["git", f"--git-dir={git}", "rev-parse", "-q", "--verify", f"{name}^{{commit}}"]
        found = subprocess.run(verify, capture_output=True, check=False)
        if found.returncode == 0:
            return found.stdout.decode().strip()
    raise SystemExit(f"{git}: no branch {branch}")


def selected(mirrors: Path, repo: str, branch: str | None) -> list[dict[str, str]]:
    """The manifest entries the rule takes from ``repo`` at ``branch`` (see _commit)."""
    git = git_dir(mirrors, repo)
    commit = _commit(git, branch)
    texts = _texts(git, _files(git, commit))
    candidates = [c for path, text in texts.items() if path.endswith(".py")
                  for c in _classes(path, text)]  # fmt: skip
    nodes = _node_classes(candidates)
    bases = {b for c in candidates if set(c.bases) & nodes for b in c.bases}
    helpers = {h for c in candidates if c.cls in nodes for h in c.helpers}
    chosen = sorted((c for c in candidates
                     if set(c.bases) & nodes and c.cls not in bases and _outside_tests(c.path)
                     and c.called & (PARAMETER_CALLS | helpers)),
                    key=lambda c: (c.path, c.cls))[:MOST_PER_REPOSITORY]  # fmt: skip
    packages = {str(PurePosixPath(p).parent) for p in texts if p.endswith("package.xml")}
    entries = []
    for c in chosen:
        entry = {"repo": repo, "commit": commit, "file": c.path}
        if sum(other.path == c.path for other in chosen) > 1:
            entry["class"] = c.cls
        params = _params_file(c.node_name, _package_of(c.path, packages), texts)
        if params:
            entry["params"] = params
        entries.append(entry)
    return entries


def _flow(entry: dict[str, str]) -> str:
    return "  - {" + ", ".join(f"{key}: {value}" for key, value in entry.items()) + "}\n"


def main(argv: list[str] | None = None) -> int:
    from bench.import_rates import MANIFEST

    parser = argparse.ArgumentParser(
        prog="python -m bench.import_rates_select", description=__doc__
    )
    parser.add_argument("--mirrors", type=Path, required=True, metavar="DIR")
    parser.add_argument("--manifest", type=Path, default=MANIFEST, metavar="FILE")
    parser.add_argument("repos", nargs="*", metavar="OWNER/NAME[@BRANCH]",
                        help="default: the manifest's `repositories`")  # fmt: skip
    args = parser.parse_args(argv)
    manifest = yaml.safe_load(args.manifest.read_text("utf-8"))
    table = {(t["repo"], t["file"]) for t in manifest["table"]}
    for spec in args.repos or manifest["repositories"]:
        repo, _, branch = spec.partition("@")
        for entry in selected(args.mirrors, repo, branch or None):
            if (entry["repo"], entry["file"]) not in table:
                sys.stdout.write(_flow(entry))
    return 0


if __name__ == "__main__":
    sys.exit(main())
