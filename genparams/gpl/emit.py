"""Text of an imported schema and of the stub module for its custom validators."""

from __future__ import annotations

import textwrap

from genparams.gpl.convert import CustomUse, GplImported
from genparams.importing import schema_text as imported_schema_text

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


def schema_text(imported: GplImported, source: str) -> str:
    return imported_schema_text(
        imported,
        [
            f"genparams schema imported from the generate_parameter_library file {source}",
            "by `genparams import-gpl`. Edit freely: this file is now the source.",
        ],
    )


def stub_text(imported: GplImported, module: str) -> str:
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
