"""The wide sample of ``bench.import_rates``, chosen by its rule rather than by hand.

    python -m bench.import_rates_select --mirrors DIR [OWNER/NAME[@BRANCH] ...]

Each repository (default: the manifest's ``repositories``) is read at the newest commit
of its ``jazzy`` (or ``jazzy-devel``) branch where it has one, else of ``BRANCH``, else
of its default branch. Printed, as manifest entries, from the Python files outside test
folders:

- *node classes*: every class that subclasses ``Node`` (or a node class of the same
  repository), is subclassed by no other node class, and calls ``declare_parameter``,
  ``get_parameter``, ... or, on ``self``, a method of a node class of the repository
  (other than ``__init__`` and the like) that calls one. A file with several such
  classes gives one entry per class (``class``).
- *script nodes*: a file none of whose classes is picked, where a function of the module
  (``main()``) or its ``if __name__ == "__main__":`` block builds a plain node
  (``Node(...)`` or ``LifecycleNode(...)`` imported from rclpy, ``rclpy.node.Node(...)``,
  ``rclpy.create_node(...)``), binds it to a name and calls one of those methods on that
  name. The file is one entry, without ``class``: import-rclpy reads the module's own
  functions as one node where no class declares.

A repository gives at most ten entries, its node classes first and its script nodes in
the room they leave, each by path: the cap keeps one repository from weighing more than
ten nodes, and counting scripts after classes leaves every class entry as the class rule
alone picks it. The entries of files of the manifest's table are then left to the table;
the rest are printed by path. A folder is a test folder when a word of its name (split
at ``_`` and ``-``) is test, tests or testing. ``params`` is the first YAML file, by
path, of the node's package (the folder of its nearest ``package.xml``) with a section
for the node's name (a class's literal ``super().__init__("x")``, a script's
``Node("x")`` or ``create_node("x")``, or ``node_name="x"``) holding
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

from genparams.rclpy_import.reads import is_main_guard

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
# What builds a plain node, imported from rclpy or called on it: Node(...), create_node(...)
PLAIN_NODES = {*NODE_CLASSES, "create_node"}


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
    inits = [node for node in ast.walk(cls) if isinstance(node, ast.Call)
             and isinstance(node.func, ast.Attribute) and node.func.attr == "__init__"]  # fmt: skip
    return _literal_name(inits)


def _literal_name(calls: list[ast.Call]) -> str | None:
    """The first literal node name the calls give: their first argument or ``node_name``."""
    for call in calls:
        written = [k.value for k in call.keywords if k.arg == "node_name"] + call.args[:1]
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


def _script(path: str, text: bytes) -> Candidate | None:
    """The file as a script node: a function of the module, or its ``__main__`` block,
    that builds a plain rclpy node, binds it to a name and calls a parameter method on
    that name. ``cls`` is ""."""
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError):
        return None
    builders, modules = _rclpy_bindings(tree)
    parts = [s for s in tree.body if isinstance(s, (ast.FunctionDef, ast.AsyncFunctionDef))
             or (isinstance(s, ast.If) and is_main_guard(s))]  # fmt: skip
    builds: list[ast.Call] = []
    for part in parts:
        bound = _bound_nodes(part, builders, modules)
        on_node = {_receiver(call) for call in ast.walk(part)
                   if isinstance(call, ast.Call) and _receiver(call) in bound}  # fmt: skip
        builds += [bound[name] for name in sorted(on_node)]
    if not builds:
        return None
    builds.sort(key=lambda call: (call.lineno, call.col_offset))
    return Candidate(path, "", (), frozenset(), frozenset(), _literal_name(builds))


def _bound_nodes(part: ast.stmt, builders: set[str], modules: set[str]) -> dict[str, ast.Call]:
    """The names ``part`` binds to a plain node it builds (``node = Node("x")``), each
    with the call that built it."""
    bound: dict[str, ast.Call] = {}
    for node in ast.walk(part):
        if isinstance(node, ast.Assign):
            value, targets = node.value, node.targets
        elif isinstance(node, ast.AnnAssign) and node.value is not None:
            value, targets = node.value, [node.target]
        else:
            continue
        if isinstance(value, ast.Call) and _builds_node(value, builders, modules):
            bound.update((t.id, value) for t in targets if isinstance(t, ast.Name))
    return bound


def _receiver(call: ast.Call) -> str:
    """The name a parameter method is called on (``node`` of ``node.get_parameter()``)."""
    func = call.func
    if isinstance(func, ast.Attribute) and func.attr in PARAMETER_CALLS:
        return getattr(func.value, "id", "")
    return ""


def _rclpy_bindings(tree: ast.Module) -> tuple[set[str], set[str]]:
    """The names the module binds to rclpy's node builders (``from rclpy.node import
    Node``) and to rclpy's modules (``import rclpy``, ``from rclpy import node``)."""
    builders: set[str] = set()
    modules: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            modules |= {(a.asname or a.name).partition(".")[0] for a in node.names
                        if a.name.partition(".")[0] == "rclpy"}  # fmt: skip
        elif isinstance(node, ast.ImportFrom) and not node.level and node.module:
            if node.module.partition(".")[0] != "rclpy":
                continue
            for alias in node.names:
                named = builders if alias.name in PLAIN_NODES else modules
                named.add(alias.asname or alias.name)
    return builders, modules


def _builds_node(call: ast.Call, builders: set[str], modules: set[str]) -> bool:
    """``Node(...)`` of rclpy, ``rclpy.node.Node(...)``, ``rclpy.create_node(...)``."""
    func = call.func
    if isinstance(func, ast.Name):
        return func.id in builders
    if not (isinstance(func, ast.Attribute) and func.attr in PLAIN_NODES):
        return False
    root = func.value
    while isinstance(root, ast.Attribute):
        root = root.value
    return isinstance(root, ast.Name) and root.id in modules


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
    with_class = {c.path for c in chosen}
    scripts = [script for path, text in sorted(texts.items())
               if path.endswith(".py") and _outside_tests(path) and path not in with_class
               and (script := _script(path, text)) is not None]  # fmt: skip
    chosen += scripts[: MOST_PER_REPOSITORY - len(chosen)]
    chosen.sort(key=lambda c: (c.path, c.cls))
    packages = {str(PurePosixPath(p).parent) for p in texts if p.endswith("package.xml")}
    entries = []
    for c in chosen:
        entry = {"repo": repo, "commit": commit, "file": c.path}
        if c.cls and sum(other.path == c.path for other in chosen) > 1:
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
