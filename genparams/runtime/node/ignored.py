"""Say what rclpy ignores without a word: overrides no parameter owns, and params-file
sections meant for this node that miss it by one slip of its name.

rclpy keeps a node's overrides (``-p``, params files, launch) and applies each only when
a parameter of that name is declared; every other one is dropped in silence. After a
class is declared, an override under its prefix that no parameter of the node owns is
such a value: the node logs a warning, with the closest name the class declares.

rcl merges the params files before the node sees them, and rclpy keeps neither the files
nor the arguments that named them. The files are read again from the process's own
arguments (``sys.argv``, where ``ros2 run`` and launch put ``--ros-args --params-file``):
a section there whose node name is one slip away from this node's (``/robot/camra`` for
``/robot/camera``) is a warning. Files given only through ``Node(cli_args=...)`` or
``rclpy.init(args=...)`` cannot be reached this way. Only the names of sections are read,
line by line (the runtime parses no YAML): the keys that hold a ``ros__parameters``.
"""

from __future__ import annotations

import sys
import weakref
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path

from rclpy.node import Node

from genparams.runtime.node.rclpy_internals import parameter_overrides

PARAMS_KEY = "ros__parameters"
# Declared by rclpy itself, some only when a publisher asks (qos_overrides.<topic>...).
RCLPY_PREFIXES = ("qos_overrides.",)
# A node is told about a file's sections once, however many classes it declares.
_SECTIONS_SEEN: weakref.WeakSet[Node] = weakref.WeakSet()


def warn_ignored(
    node: Node, prefix: str, owned: Sequence[str], declares: Callable[[str], bool]
) -> None:
    """Warn on ``node``'s logger for what rclpy will ignore; ``owned``: the class's full
    names (for the hint), ``declares``: whether the class owns a full name."""
    logger = node.get_logger()
    for name in unowned_overrides(node, prefix, declares):
        from genparams.runtime.core.suggest import did_you_mean_name  # with the first slip

        hint = did_you_mean_name(name, owned)
        logger.warning(
            f"parameter override {name!r} is owned by no parameter of this node{hint}: "
            "rclpy ignores it"
        )
    if node in _SECTIONS_SEEN:
        return
    _SECTIONS_SEEN.add(node)
    this = node.get_fully_qualified_name()
    for file in params_files(sys.argv):
        for section in section_names(file):
            if section != this and one_slip(section, this):
                logger.warning(
                    f"{file}: section {section} is not this node ({this}): rclpy applies it to "
                    f"no node of that name here; a typo of {this}?"
                )


def unowned_overrides(node: Node, prefix: str, declares: Callable[[str], bool]) -> list[str]:
    """Overrides under ``prefix`` that neither the class nor the node holds, in order."""
    head = prefix + "." if prefix else ""
    return [
        name
        for name in parameter_overrides(node)
        if name.startswith(head)
        and not declares(name)
        and not node.has_parameter(name)
        and not name.startswith(RCLPY_PREFIXES)
    ]


def one_slip(written: str, meant: str) -> bool:
    """One edit apart, and not numbered copies (``/robot_1/cam``, ``/robot_2/cam``)."""
    from genparams.runtime.core.suggest import edit_distance, numbered_copies  # with a file

    return edit_distance(written, meant) == 1 and not numbered_copies(written, meant)


def params_files(argv: Sequence[str]) -> list[Path]:
    """The files ``--params-file`` names inside ``--ros-args`` blocks, in order."""
    files: list[Path] = []
    inside = False
    arguments = iter(argv)
    for argument in arguments:
        if argument == "--ros-args":
            inside = True
        elif argument == "--":
            inside = False
        elif inside and argument == "--params-file":
            following = next(arguments, None)
            if following is not None:
                files.append(Path(following))
    return files


def section_names(file: Path) -> list[str]:
    """The node names of a params file's sections (those holding ``ros__parameters``);
    patterns (``/**``, ``*``) left out: they are for many nodes. Nothing for an unreadable
    file: rcl has already refused it, or read what it could."""
    try:
        text = file.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return []
    names: list[str] = []
    for path in _key_paths(text):
        if path[-1] == PARAMS_KEY and len(path) > 1:
            name = "/" + "/".join(part.strip("/") for part in path[:-1])
            if "*" not in name and name not in names:
                names.append(name)
    return names


def _key_paths(text: str) -> Iterator[tuple[str, ...]]:
    """Each block-style mapping key with the keys it sits under."""
    stack: list[tuple[int, str]] = []
    for line in text.splitlines():
        stripped = line.lstrip(" ")
        if not stripped or stripped.startswith(("#", "-", "---", "...")):
            continue
        key, colon, _ = stripped.partition(":")
        if not colon or key.startswith(("{", "[")):
            continue
        indent = len(line) - len(stripped)
        while stack and stack[-1][0] >= indent:
            stack.pop()
        stack.append((indent, key.strip().strip("'\"")))
        yield tuple(k for _, k in stack)
