"""Naming rules, in one place: ROS names, Python attribute and class names."""

from __future__ import annotations

import keyword
import re

# One token of a ROS parameter name. ROS also accepts a leading underscore;
# genparams reserves those for the generated classes' internals.
ROS_TOKEN = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
SCHEMA_NAME = re.compile(r"[a-z][a-z0-9_]*")

# Methods of the generated top-level class: a top-level parameter or namespace
# with one of these names would hide them.
RESERVED_TOP_LEVEL = frozenset(
    {"declare", "defaults", "snapshot", "on_change", "to_dict", "remote", "changes"}
)


def is_ros_token(name: str) -> bool:
    return ROS_TOKEN.fullmatch(name) is not None


def attribute_name(ros_token: str) -> str:
    """Python attribute for a ROS name token: keywords get a trailing underscore (PEP 8)."""
    if keyword.iskeyword(ros_token):
        return ros_token + "_"
    return ros_token


def pascal_case(name: str) -> str:
    return "".join(part[:1].upper() + part[1:] for part in name.split("_") if part)


def class_name(schema_name: str) -> str:
    return pascal_case(schema_name) + "Params"


def module_name(schema_name: str) -> str:
    return schema_name + "_params"


def join_prefix(prefix: str, name: str) -> str:
    """Join a parameter prefix and a name with exactly one dot."""
    prefix = prefix.strip(".")
    return f"{prefix}.{name}" if prefix else name
