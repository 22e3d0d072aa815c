"""Naming rules, in one place: ROS names, Python attribute and class names."""

from __future__ import annotations

import keyword
import re
import sys
from collections.abc import Collection, Sequence

# One token of a parameter name: the text between two dots. rclpy declares any
# non-empty name and rcl's params-file parser takes any key, so the rule is
# genparams' own: letters, digits, '_' and '-', starting with a letter, in parts
# joined by single '/' (rcl's `-p a/b:=1` reads those too; it refuses '-').
# ROS also accepts a leading underscore; genparams reserves those for the
# generated classes' internals.
ROS_TOKEN = re.compile(r"[A-Za-z][A-Za-z0-9_-]*(?:/[A-Za-z][A-Za-z0-9_-]*)*")
# What rcl's `-p NAME:=VALUE` reads as NAME: tokens of letters, digits and '_' (no digit
# first) between '.' and '/'. Names with '-' come from params files or parameter services.
COMMAND_LINE_NAME = re.compile(r"[./]*[A-Za-z_][A-Za-z0-9_]*(?:[./]+[A-Za-z_][A-Za-z0-9_]*)*[./]*")
NAME_RULE = "letters, digits, '_' and '-', starting with a letter, in parts joined by single '/'"
# The characters of a name a Python attribute cannot hold: each becomes '_'.
_NOT_IN_ATTRIBUTES = str.maketrans({"-": "_", "/": "_"})
_WORD_SEPARATORS = re.compile(r"[_/-]")
# Schema names and rule names: snake_case (schemas/genparams.schema.json states it too).
SNAKE_CASE = re.compile(r"[a-z][a-z0-9_]*")
SCHEMA_NAME = SNAKE_CASE
RULE_NAME = SNAKE_CASE

# Methods of the generated top-level class: a top-level parameter or namespace
# with one of these names gets an attribute with a trailing underscore.
RESERVED_TOP_LEVEL = frozenset(
    {"declare", "defaults", "snapshot", "on_change", "to_dict", "remote", "changes"}
)

# Names the generated classes use inside their bodies (annotations, ClassVar): a
# parameter or namespace of that name gets an attribute with a trailing underscore.
SHADOWING = frozenset({"bool", "bytes", "float", "int", "str", "tuple", "ClassVar"})

# Parameters rclpy declares on every node: a schema may not declare them again
# (it may adopt them, see ``adopt``).
NODE_PARAMETERS = frozenset({"use_sim_time", "start_type_description_service"})


def is_ros_token(name: str) -> bool:
    return ROS_TOKEN.fullmatch(name) is not None


def check_prefix(prefix: str) -> str:
    """``prefix`` if it is empty or a dotted ROS name (a class's parameters live under it)."""
    if prefix and not all(is_ros_token(part) for part in prefix.split(".")):
        raise ValueError(f"invalid parameter prefix {prefix!r}: dot-separated names of {NAME_RULE}")
    return prefix


def is_ros_name(name: str) -> bool:
    """A dotted ROS parameter name relative to a prefix: tokens joined by single dots."""
    return all(is_ros_token(part) for part in name.split("."))


# In the names of a mapped group's parameters, this segment stands for one key.
ENTRY_KEY = "*"

# ``for_each: overrides`` on a namespace: its entries are the keys the node's overrides
# hold under it when it is declared (an open group). In the runtime's SchemaSpec.maps the
# group maps to OVERRIDE_KEYS, which is no ROS name, so no parameter can be taken for it.
FROM_OVERRIDES = "overrides"
OVERRIDE_KEYS = "(overrides)"

# The slot of a generated group holding the entries of its in-place mapped group
# (schema key "*"). Attributes never start with "_", so it hides no parameter.
MAP_SLOT = "_map"

# An item of a for_each key list becomes one segment of its entries' ROS names.
# rcl reads params files, and the parameter services carry names, segment by
# segment with "." as the only separator, so a key may hold any other text:
# "left-arm", "1st", "wheel_left/position". genparams refuses "." (it would
# split the key), "*" (it stands for an entry in templates), and spaces and
# control characters (no ROS tool can type them). rcl's `-p name:=value`
# parser wants name tokens, so overrides for other keys come from params files.
ENTRY_KEY_TEXT = re.compile(r"[^.*\s\x00-\x1f\x7f]+")
ENTRY_KEY_RULE = "any text but '.', '*', spaces and control characters"


def is_entry_key(key: str) -> bool:
    return ENTRY_KEY_TEXT.fullmatch(key) is not None


def entry_key_problem(keys: Sequence[str], maps: str) -> str | None:
    """Why the items of a ``for_each`` parameter cannot name the entries of ``maps``, or None.

    Each item becomes one segment of the entries' ROS names, so it must be
    non-empty text of ``ENTRY_KEY_RULE``, and distinct.
    """
    seen: set[str] = set()
    where = maps or "the top level"
    for index, key in enumerate(keys):
        if not is_entry_key(key):
            return f"item {index} {key!r} cannot name an entry of {where}: use {ENTRY_KEY_RULE}"
        if key in seen:
            return f"item {index} {key!r} repeats: each item names one entry of {where}"
        seen.add(key)
    return None


def entry_beside_problem(keys: Sequence[str], map_path: str, names: Collection[str]) -> str | None:
    """Why an item cannot key an entry of the in-place map at ``map_path``, beside its fixed
    ``names``: it is one of them, or spelt as one in Python (``twist-x`` beside
    ``twist_x``: entries and fields share the namespace's attributes). None when it can."""
    where = map_path or "the top level"
    top = not map_path
    spelt = {attribute_name(name, top_level=top): name for name in names}
    for key in keys:
        if key in names:
            return f"item {key!r} is already a name in {where}: an entry cannot share it"
        attribute = attribute_name(key, top_level=top)
        if attribute in spelt:
            return (
                f"item {key!r} and {spelt[attribute]!r} of {where} share the Python attribute "
                f"{attribute!r}: an entry cannot share it"
            )
    return None


def attribute_name(ros_token: str, *, top_level: bool = False) -> str:
    """Python attribute for a ROS name token; the ROS name itself never changes.

    '-' and '/' become '_' (``twist-linear-x`` -> ``twist_linear_x``). A trailing
    underscore (PEP 8) is added to Python keywords (``from_``), to names the
    generated class bodies use (``int_``), and at the top level to the generated
    class's methods (``defaults_``, ``snapshot_``). Two names of one namespace
    with one attribute are a schema error.
    """
    attribute = ros_token.translate(_NOT_IN_ATTRIBUTES)
    if (
        keyword.iskeyword(attribute)
        or attribute in SHADOWING
        or (top_level and attribute in RESERVED_TOP_LEVEL)
    ):
        return attribute + "_"
    return attribute


def attribute_parts(ros_name: str) -> tuple[str, ...]:
    """The attribute path of a dotted ROS name (its first token is at the top level)."""
    parts = ros_name.split(".")
    # Interned: the same few names (`a0`, `gain`) recur in every path of a large schema.
    return tuple(
        sys.intern(attribute_name(part, top_level=index == 0)) for index, part in enumerate(parts)
    )


def pascal_case(name: str) -> str:
    """``twist-linear_x`` -> ``TwistLinearX``: words split at '_', '-' and '/'."""
    return "".join(part[:1].upper() + part[1:] for part in _WORD_SEPARATORS.split(name) if part)


def class_name(schema_name: str) -> str:
    return pascal_case(schema_name) + "Params"


def module_name(schema_name: str) -> str:
    return schema_name + "_params"


def join_prefix(prefix: str, name: str) -> str:
    """Join a parameter prefix and a name with exactly one dot."""
    prefix = prefix.strip(".")
    return f"{prefix}.{name}" if prefix else name


def strip_prefix(prefix: str, full_name: str) -> str | None:
    """The name under ``prefix`` that ``full_name`` stands for, or None if it lies elsewhere."""
    prefix = prefix.strip(".")
    if not prefix:
        return full_name
    head = prefix + "."
    return full_name[len(head) :] if full_name.startswith(head) else None


# Node names in params files and on the command line. A token of a node or namespace
# name (rcl's rule): a letter or '_' first. ROS prepends "/" when it is missing.
NODE_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
WILDCARD_ONE = "*"  # in a params-file section's node name: exactly one name token
WILDCARD_ANY = "**"  # zero or more name tokens


def absolute(name: str) -> str:
    return name if name.startswith("/") else "/" + name


def node_pattern_problem(pattern: str) -> str | None:
    """Why ROS refuses ``pattern`` as the node name of a params-file section, or None.

    ``*`` stands for one name token and ``**`` for any number of them.
    """
    return _name_problem(absolute(pattern), wildcards=True)


def node_name_problem(name: str) -> str | None:
    """Why ``name`` is not a fully qualified node name such as ``/ns/camera``, or None."""
    return _name_problem(absolute(name), wildcards=False)


def _name_problem(name: str, *, wildcards: bool) -> str | None:
    if name == "/":
        return "node name must not be empty"
    tokens = name[1:].split("/")
    for index, token in enumerate(tokens):
        last = index == len(tokens) - 1
        if token == "":
            return "node name must not be empty" if last else "contains repeated forward slash"
        if wildcards and token in (WILDCARD_ONE, WILDCARD_ANY):
            continue
        if NODE_TOKEN.fullmatch(token) is None:
            what = "node name" if last else "namespace"
            if token[0].isdigit():
                return f"{what} must not start with a number: {token!r}"
            return f"{what} {token!r} may hold only letters, digits and '_'"
    return None
