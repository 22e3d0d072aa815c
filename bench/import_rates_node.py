"""What a real rclpy node declares, for ``bench.import_rates``: run in a process of its own,
writes one JSON object to ``--out FILE``.

``original ROOT FILE``: the public node's own code runs, as ``ros2 run`` would start it
(``FILE`` as ``__main__``, a module of its package where it is in one, its repository's
packages importable, ``--ros-args --params-file`` in ``sys.argv``). Modules this
environment lacks (message packages, drivers, ``carla``) are stand-ins, and
``get_package_share_directory`` finds the repository's packages (their own folders);
spinning stops the run at once, and so does a timer, so a node is read as its
constructor left it. Every node built is kept; the one read is the class asked for, else
the first built by a class of the file, else the first built; a file that builds none
when run has its first node class built, without arguments.

``generated MODULE CLASS NODE``: a fresh node named ``NODE`` declares the generated class
``CLASS`` of ``MODULE`` (with the params file, as the original was started).
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import importlib.abc
import importlib.machinery
import importlib.util
import json
import os
import signal
import sys
import types
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any
from xml.etree import ElementTree

import rclpy
import rclpy.executors
import rclpy.utilities
from rclpy.node import Node

from tests.rclpy_import.declared import Declared, declared, without_item_rule

RUN_SECONDS = 20


class Stopped(BaseException):
    """The run is stopped where it was: spinning, or out of time."""


class _StandIn:
    """Whatever a missing module is asked for: callable, indexable, iterable (empty)."""

    def __init__(self, name: str) -> None:
        self._name = name

    def __getattr__(self, name: str) -> _StandIn:
        if name.startswith("__"):
            raise AttributeError(name)
        return _StandIn(f"{self._name}.{name}")

    def __call__(self, *args: Any, **kwargs: Any) -> _StandIn:
        return _StandIn(f"{self._name}()")

    def __getitem__(self, key: Any) -> _StandIn:
        return _StandIn(f"{self._name}[]")

    def __iter__(self) -> Any:
        return iter(())

    def __mro_entries__(self, bases: tuple[Any, ...]) -> tuple[type, ...]:
        return (object,)


def _message_stand_in(module: str, name: str) -> Any:
    """A real interface type for a message, service or action of a missing package: the
    node's code can create publishers, services and clients with it."""
    from rcl_interfaces.msg import ParameterEvent
    from rcl_interfaces.srv import GetParameters

    kind = module.rpartition(".")[2]
    real: type | None = {"msg": ParameterEvent, "srv": GetParameters}.get(kind)
    if real is None:
        return _StandIn(f"{module}.{name}")

    def constant(cls: type, attribute: str) -> int:
        if attribute.isupper():  # a message's constant: STATUS_NO_FIX
            return 0
        raise AttributeError(attribute)

    meta = type(f"{name}Meta", (type(real),), {"__getattr__": constant})
    return meta(name, (real,), {})


class _StandInModule(types.ModuleType):
    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        if name[:1].isupper():
            return _message_stand_in(self.__name__, name)
        return _StandIn(f"{self.__name__}.{name}")


class _StandIns(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Last on sys.meta_path: a module the repository's code imports that no other finder
    finds is a stand-in (a module others only probe for stays missing)."""

    def __init__(self, imported: set[str]) -> None:
        self.imported = imported
        self.names: list[str] = []

    def find_spec(
        self, fullname: str, path: Sequence[str] | None, target: types.ModuleType | None = None
    ) -> importlib.machinery.ModuleSpec | None:
        if fullname.partition(".")[0] not in self.imported:
            return None
        self.names.append(fullname)
        return importlib.machinery.ModuleSpec(fullname, self, is_package=True)

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> types.ModuleType:
        module = _StandInModule(spec.name)
        module.__path__ = []
        return module

    def exec_module(self, module: types.ModuleType) -> None:
        return None


def _package_roots(root: Path) -> list[str]:
    """The folders a repository's Python packages are imported from: the parent of every
    top-level package (a folder with ``__init__.py`` whose parent has none)."""
    roots = {
        str(init.parent.parent)
        for init in root.rglob("__init__.py")
        if not (init.parent.parent / "__init__.py").exists()
    }
    return sorted(roots)


def _imported_names(root: Path) -> set[str]:
    """The top-level modules the repository's Python files import."""
    names: set[str] = set()
    for path in root.rglob("*.py"):
        try:
            tree = ast.parse(path.read_bytes())
        except (SyntaxError, ValueError):
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                names.update(alias.name.partition(".")[0] for alias in node.names)
            elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
                names.add(node.module.partition(".")[0])
    return names


def _init_as_newer_rclpy(init: Callable[..., None]) -> Callable[..., Any]:
    """``rclpy.init`` as rclpy after Jazzy has it: usable as ``with rclpy.init():``
    (shutting down on leaving), which nodes written for those releases do."""

    @contextlib.contextmanager
    def held() -> Iterator[None]:
        try:
            yield
        finally:
            rclpy.utilities.try_shutdown()

    def newer_init(*args: Any, **kwargs: Any) -> Any:
        init(*args, **kwargs)
        return held()

    return newer_init


def _stop(*args: Any, **kwargs: Any) -> None:
    raise Stopped("spin")


def _run_original(root: Path, file: Path, params: str | None, class_name: str | None) -> Any:
    built: list[Node] = []
    original_init: Callable[..., None] = Node.__init__

    def recording_init(self: Node, *args: Any, **kwargs: Any) -> None:
        built.append(self)
        original_init(self, *args, **kwargs)

    Node.__init__ = recording_init  # type: ignore[method-assign]
    for owner in (rclpy, rclpy.executors.Executor):
        for name in ("spin", "spin_once", "spin_until_future_complete"):
            setattr(owner, name, _stop)
    rclpy.init = _init_as_newer_rclpy(rclpy.init)
    os.environ["AMENT_PREFIX_PATH"] = str(_ament_prefix(root))
    stand_ins = _StandIns(_imported_names(root))
    sys.meta_path.append(stand_ins)
    package = _package_of(file)
    # a package's module is run from the package's parent; its own folder comes last, for
    # the scripts installed beside each other that import one another
    if package:
        sys.path[:0] = [str(file.parents[package.count(".") + 1]), *_package_roots(root)]
        sys.path.append(str(file.parent))
    else:
        sys.path[:0] = [str(file.parent), *_package_roots(root)]
    sys.argv = [str(file), *(["--ros-args", "--params-file", params] if params else [])]

    def out_of_time(*args: Any) -> None:
        raise Stopped("timer")

    signal.signal(signal.SIGALRM, out_of_time)
    signal.alarm(RUN_SECONDS)
    stopped = ""
    namespace: dict[str, Any] = {"__name__": "__main__", "__file__": str(file)}
    if package:  # as its console script runs it: a module of its package
        namespace["__package__"] = package
    try:
        exec(compile(file.read_text("utf-8"), str(file), "exec"), namespace)
        if not built and callable(namespace.get("main")):
            namespace["main"]()
    except BaseException as exc:  # the node's own code: whatever it raises ends the run
        stopped = "spin" if isinstance(exc, Stopped) and str(exc) == "spin" else _what(exc)
    if class_name is None and not built:  # a module that builds no node: its node class
        class_name = next((name for name, value in namespace.items()
                           if isinstance(value, type) and issubclass(value, Node)
                           and value.__module__ == "__main__"), None)  # fmt: skip
    if class_name and not any(type(n).__name__ == class_name for n in built):
        try:
            if not rclpy.utilities.ok():
                rclpy.init(args=sys.argv)
            namespace[class_name]()
        except BaseException as exc:  # as above
            stopped = _what(exc)
    signal.alarm(0)
    node = _chosen(built, class_name)
    missing = sorted({n.partition(".")[0] for n in stand_ins.names})
    if node is None:
        return {"node": None, "declared": {}, "stopped": stopped, "stand_ins": missing}
    return {
        "node": node.get_name(),
        "declared": _plain(declared(node)),
        "stopped": stopped,
        "stand_ins": missing,
    }


def _ament_prefix(root: Path) -> Path:
    """An install prefix beside the repository where every package of it is found, as
    ``get_package_share_directory`` looks them up: its share directory is its folder."""
    prefix = root.parent / f"{root.name}.ament"
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True, exist_ok=True)
    for manifest in root.rglob("package.xml"):
        try:
            name = ElementTree.parse(manifest).findtext("name")
        except ElementTree.ParseError:
            continue
        share = prefix / "share" / (name or "").strip()
        if name and name.strip() and not share.exists():
            (index / name.strip()).touch()
            share.symlink_to(manifest.parent.resolve(), target_is_directory=True)
    return prefix


def _package_of(file: Path) -> str:
    """The dotted package ``file`` is a module of (its folders holding ``__init__.py``,
    or its own folder when it imports relatively), or "" for a script outside any."""
    parts: list[str] = []
    folder = file.parent
    while (folder / "__init__.py").exists():
        parts.insert(0, folder.name)
        folder = folder.parent
    if not parts and _imports_relatively(file):  # a namespace package's module
        parts = [file.parent.name]
    return ".".join(parts)


def _imports_relatively(file: Path) -> bool:
    try:
        tree = ast.parse(file.read_bytes())
    except (SyntaxError, ValueError):
        return False
    return any(isinstance(n, ast.ImportFrom) and n.level for n in ast.walk(tree))


def _what(exc: BaseException) -> str:
    return f"{type(exc).__name__}: {exc}".splitlines()[0][:200]


def _chosen(built: list[Node], class_name: str | None) -> Node | None:
    if class_name:
        return next((n for n in built if type(n).__name__ == class_name), None)
    own = [n for n in built if type(n).__module__ == "__main__"]
    chosen = own or built
    return chosen[0] if chosen else None


def _run_generated(module_file: Path, class_name: str, node_name: str, params: str | None) -> Any:
    rclpy.init(args=["--ros-args", "--params-file", params] if params else [])
    spec = importlib.util.spec_from_file_location(module_file.stem, module_file)
    if spec is None or spec.loader is None:
        raise SystemExit(f"cannot load {module_file}")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    node = Node(node_name)
    stopped = ""
    try:
        getattr(module, class_name).declare(node)
    except Exception as exc:  # a refusal of the params file's values: reported
        stopped = _what(exc)
    found = {n: (without_item_rule(d), v) for n, (d, v) in declared(node).items()}
    return {"node": node_name, "declared": _plain(found), "stopped": stopped, "stand_ins": []}


def _plain(found: Declared) -> Any:
    """JSON's view of the declared parameters (tuples as lists), as both sides compare."""
    return json.loads(json.dumps(found, default=repr))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m bench.import_rates_node")
    sub = parser.add_subparsers(dest="mode", required=True)
    original = sub.add_parser("original")
    original.add_argument("root", type=Path)
    original.add_argument("file", type=Path)
    original.add_argument("--class", dest="class_name")
    original.add_argument("--params-file")
    generated = sub.add_parser("generated")
    generated.add_argument("module", type=Path)
    generated.add_argument("class_name")
    generated.add_argument("node")
    generated.add_argument("--params-file")
    parser.add_argument("--out", type=Path, required=True, help="where the JSON goes")
    args = parser.parse_args(argv)
    if args.mode == "original":
        result = _run_original(args.root, args.file, args.params_file, args.class_name)
    else:
        result = _run_generated(args.module, args.class_name, args.node, args.params_file)
    args.out.write_text(json.dumps(result), encoding="utf-8")
    os._exit(0)  # threads the node started must not hold the process


if __name__ == "__main__":
    sys.exit(main())
