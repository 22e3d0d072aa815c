"""Render the model with the jinja2 templates. One Environment, built once."""

from __future__ import annotations

import functools
import math
from typing import Any

import jinja2

from genparams import __version__
from genparams.model import Schema
from genparams.resources import resource_dir


def python_literal(value: Any) -> str:
    """A Python literal for schema data; never lets schema text become code.

    Strings go through ``repr`` (quotes, backslashes, newlines, NUL, U+2028 are
    escaped), preferring double quotes as ruff format does.
    """
    if isinstance(value, str):
        text = repr(value)
        if text.startswith("'") and '"' not in value:
            text = '"' + text[1:-1].replace("\\'", "'") + '"'
        return text
    if isinstance(value, bool) or value is None:
        return repr(value)
    if isinstance(value, int):
        return repr(value)
    if isinstance(value, float):
        if math.isnan(value):
            return 'float("nan")'
        if math.isinf(value):
            return 'float("inf")' if value > 0 else 'float("-inf")'
        return repr(value)
    if isinstance(value, bytes):
        text = repr(value)
        if text.startswith("b'") and '"' not in text:
            text = 'b"' + text[2:-1].replace("\\'", "'") + '"'
        return text
    if isinstance(value, tuple):
        if len(value) == 1:
            return f"({python_literal(value[0])},)"
        return "(" + ", ".join(python_literal(v) for v in value) + ")"
    if isinstance(value, dict):
        items = ", ".join(f"{python_literal(k)}: {python_literal(v)}" for k, v in value.items())
        return "{" + items + "}"
    raise TypeError(f"no Python literal for {type(value).__name__}")


@functools.cache
def environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(resource_dir("templates"))),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
        autoescape=False,
    )
    env.filters["py"] = python_literal
    return env


def render_module(schema: Schema) -> str:
    template = environment().get_template("module.py.j2")
    return template.render(schema=schema, version=__version__)
