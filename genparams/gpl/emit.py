"""Text of an imported schema and of the stub module for its custom validators."""

from __future__ import annotations

import textwrap
from typing import Any

import yaml

from genparams.gpl.convert import CustomUse, Imported
from genparams.runtime.validator_kinds import KINDS

# Python bodies for custom validators that ros2_controllers uses, whose meaning
# their names and control_toolbox's documentation state: the import can write
# them whole instead of a stub.
KNOWN_BODIES = {
    "gt_eq_or_nan": (
        "value: Any, limit: float",
        "Every value (or item) is NaN or >= limit.",
        "    items = value if isinstance(value, (list, tuple)) else (value,)\n"
        "    bad = [v for v in items if not (math.isnan(v) or v >= limit)]\n"
        '    return f"must be NaN or >= {limit}, got {bad[0]!r}" if bad else None\n',
    ),
    "lt_eq_or_nan": (
        "value: Any, limit: float",
        "Every value (or item) is NaN or <= limit.",
        "    items = value if isinstance(value, (list, tuple)) else (value,)\n"
        "    bad = [v for v in items if not (math.isnan(v) or v <= limit)]\n"
        '    return f"must be NaN or <= {limit}, got {bad[0]!r}" if bad else None\n',
    ),
}


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


def schema_text(imported: Imported, source: str) -> str:
    header = (
        f"# genparams schema imported from the generate_parameter_library file {source}\n"
        "# by `genparams import-gpl`. Edit freely: this file is now the source.\n"
    )
    body = yaml.dump(
        imported.data,
        Dumper=_Dumper,
        sort_keys=False,
        allow_unicode=True,
        width=100,
        default_flow_style=False,
    )
    return header + body


def stub_text(imported: Imported, module: str) -> str:
    """A module defining every custom validator the schema references."""
    lines = [
        f'"""Custom validators of the {imported.name} schema.',
        "",
        f"The schema references each as {module}:NAME.",
        "",
        "Each takes the parameter's value (then the schema's args) and returns None",
        "when it is valid, or a reason (str) when it is not. An empty string also means",
        "valid, as in generate_parameter_library's Python validators, so a body ported from",
        "one (which took the rclpy Parameter: use `value` where it read `param.value`)",
        'may keep returning ""."""',
        "",
        "from __future__ import annotations",
        "",
        *(["import math"] if set(imported.customs) & set(KNOWN_BODIES) else []),
        "from typing import Any",
    ]
    for name in sorted(imported.customs):
        lines.extend(["", "", *_function(imported.customs[name])])
    return "\n".join(lines) + "\n"


def _function(use: CustomUse) -> list[str]:
    users = ", ".join(sorted({p for p, _ in use.used_by}))
    known = KNOWN_BODIES.get(use.function)
    if known is not None:
        signature, doc, body = known
        return [
            f"def {use.function}({signature}) -> str | None:",
            *_docstring(f"{doc} GPL: {use.gpl_name}; used by {users}."),
            *body.rstrip("\n").split("\n"),
        ]
    takes = max((len(args) for _, args in use.used_by), default=0)
    params = "".join(f", arg{n}: Any" for n in range(takes))
    return [
        f"def {use.function}(value: Any{params}) -> str | None:",
        *_docstring(f"GPL: {use.gpl_name}; used by {users}."),
        '    # TODO: port GPL\'s check (a C++ function, or a Python one returning "" when',
        "    # valid, which this stub may keep doing); until then it accepts every value.",
        "    return None",
    ]


def _docstring(text: str) -> list[str]:
    wrapped = textwrap.wrap(text, width=88)
    lines = [f'    """{wrapped[0]}', *(f"    {line}" for line in wrapped[1:])]
    lines[-1] += '"""'
    return lines
