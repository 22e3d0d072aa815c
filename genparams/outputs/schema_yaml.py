"""A schema as people write it: the text import-gpl, import-rclpy and import-node write."""

from __future__ import annotations

from typing import Any

import yaml

from genparams.runtime.core.validator_kinds import KINDS

_RANGE_KEYS = {"min", "max", "step"}  # a range reads on one line: {min: 0.0, max: .inf}


class _Dumper(yaml.SafeDumper):
    """Block mappings (one key a line, as people write schemas), flow lists."""


def _list(dumper: yaml.SafeDumper, value: list[Any]) -> yaml.Node:
    """``[a, b]`` for values; one item a line for validators (lists holding mappings)."""
    flow = not any(isinstance(item, (dict, list)) for item in value)
    return dumper.represent_sequence("tag:yaml.org,2002:seq", value, flow_style=flow)


def _text(dumper: yaml.SafeDumper, value: str) -> yaml.Node:
    """Descriptions of several lines stay readable as literal blocks."""
    style = "|" if "\n" in value.strip("\n") else None
    return dumper.represent_scalar("tag:yaml.org,2002:str", value, style=style)


def _mapping(dumper: yaml.SafeDumper, value: dict[str, Any]) -> yaml.Node:
    """A validator entry (``{length: {min: 1}}``) or a range on one line; everything else one
    key a line."""
    flow = (len(value) == 1 and next(iter(value)) in KINDS) or set(value) <= _RANGE_KEYS
    return dumper.represent_mapping("tag:yaml.org,2002:map", value, flow_style=flow)


_Dumper.add_representer(list, _list)
_Dumper.add_representer(dict, _mapping)
_Dumper.add_representer(str, _text)


def schema_yaml(data: dict[str, Any]) -> str:
    """``data`` (a schema as plain data, keys in order) as YAML text."""
    return yaml.dump(
        data,
        Dumper=_Dumper,
        sort_keys=False,
        allow_unicode=True,
        width=100,
        default_flow_style=False,
    )
