"""Render the model with the jinja2 templates. One Environment, built once."""

from __future__ import annotations

import functools
import math
import re
from typing import Any

import jinja2

from genparams._version import __version__
from genparams.outputs import markup, module_layout
from genparams.outputs.docs_model import DocsPage
from genparams.outputs.params_file import ParamsFile
from genparams.runtime import RUNTIME_API, NoneOf
from genparams.schema.model import Schema
from genparams.schema.resources import resource_dir

_ESCAPE_OR_DOUBLE_QUOTE = re.compile(r'\\.|"', re.DOTALL)


def _ruff_quoted(literal: str, prefix: str = "") -> str:
    """Re-quote a ``repr`` literal as ruff format would: double quotes, unless the text
    holds more double than single quotes.

    ``repr`` escapes every character that could end the literal early (quotes,
    backslashes, newlines, NUL, U+2028 ...), so schema text never becomes code.
    """
    body = literal[len(prefix) + 1 : -1]
    if literal[len(prefix)] == '"' or body.count('"') > body.count("\\'"):
        return literal

    def requote(match: re.Match[str]) -> str:
        token = match.group()
        return {"\\'": "'", '"': '\\"'}.get(token, token)

    return f'{prefix}"{_ESCAPE_OR_DOUBLE_QUOTE.sub(requote, body)}"'


def python_literal(value: Any) -> str:
    """A Python literal for schema data; never lets schema text become code."""
    if isinstance(value, str):
        return _ruff_quoted(repr(value))
    if isinstance(value, bool) or value is None:
        return repr(value)
    if isinstance(value, int):
        return repr(value)
    if isinstance(value, float):
        if math.isnan(value):
            return 'float("nan")'
        if math.isinf(value):
            return 'float("inf")' if value > 0 else 'float("-inf")'
        return repr(value).replace("e+", "e")  # ruff's spelling of exponents
    if isinstance(value, bytes):
        return _ruff_quoted(repr(value), prefix="b")
    if isinstance(value, tuple):
        if len(value) == 1:
            return f"({python_literal(value[0])},)"
        return "(" + ", ".join(python_literal(v) for v in value) + ")"
    if isinstance(value, dict):
        items = ", ".join(f"{python_literal(k)}: {python_literal(v)}" for k, v in value.items())
        return "{" + items + "}"
    if isinstance(value, NoneOf):  # a negated condition: the module imports it as _NoneOf
        return f"_NoneOf({', '.join(python_literal(v) for v in value.values)})"
    raise TypeError(f"no Python literal for {type(value).__name__}")


# Python reads a coding declaration from a comment on line 1 or 2 (PEP 263); a file name
# written there as 'coding=utf_7 x.yaml' would make the module be read as UTF-7.
_CODING_DECLARATION = re.compile(r"(?<=coding)[:=]")


def comment_literal(text: str) -> str:
    """``text`` as a Python literal fit for a header comment: it never declares a coding."""
    return _CODING_DECLARATION.sub(
        lambda match: f"\\x{ord(match.group()):02x}", python_literal(text)
    )


LINE_LENGTH = 100


def _items(value: Any) -> tuple[str, str, list[Any]] | None:
    """Brackets and items of a container literal, or None for a scalar."""
    if isinstance(value, tuple) and value:
        return "(", ")", list(value)
    if isinstance(value, dict) and value:
        return "{", "}", list(value.items())
    return None


def _item_literal(item: Any, is_dict: bool, indent: int) -> str:
    if is_dict:
        key, value = item
        head = f"{python_literal(key)}: "
        return head + wrapped_literal(value, indent, indent + markup.column_width(head), 1)
    return wrapped_literal(item, indent, indent, 1)


def wrapped_literal(value: Any, indent: int, used: int, trailing: int) -> str:
    """``python_literal`` laid out as ruff format lays it out at this position.

    ``used`` is the column where the literal starts, ``trailing`` the characters
    that follow it on its last line. Generated files are then stable under
    ``ruff format``.
    """
    flat = python_literal(value)
    if isinstance(value, NoneOf) and used + markup.column_width(flat) + trailing > LINE_LENGTH:
        return _call_lines(flat[: flat.index("(")], value.values, indent)
    container = _items(value)
    # ruff measures lines in columns: a wide character takes two, a combining mark none.
    if container is None or used + markup.column_width(flat) + trailing <= LINE_LENGTH:
        return flat
    # A collection literal that does not fit gets one item per line (ruff, like black).
    opening, closing, items = container
    inner = indent + 4
    is_dict = opening == "{"
    lines = [f"{' ' * inner}{_item_literal(item, is_dict, inner)}," for item in items]
    return opening + "\n" + "\n".join(lines) + f"\n{' ' * indent}{closing}"


def _call_lines(function: str, arguments: tuple[Any, ...], indent: int) -> str:
    """A call too long for its line, as ruff splits it: every argument on one line of its
    own when they fit there, else one argument a line with a trailing comma."""
    inner = indent + 4
    joined = ", ".join(python_literal(argument) for argument in arguments)
    if len(arguments) == 1 or inner + markup.column_width(joined) <= LINE_LENGTH:
        return f"{function}(\n{' ' * inner}{joined}\n{' ' * indent})"
    lines = [f"{' ' * inner}{wrapped_literal(a, inner, inner, 1)}," for a in arguments]
    return f"{function}(\n" + "\n".join(lines) + f"\n{' ' * indent})"


# ruff splits a class header or an annotation too long for a line at brackets of its
# choosing; a line only very long names make so long keeps its one-line form and
# tells ruff so. Every other line is laid out here as ruff lays it out.
_KEEP_AS_IS = "  # fmt: skip"


def one_line(text: str, indent: int) -> str:
    """``text`` at ``indent``, marked for ruff to leave alone when it is too long."""
    return text + _KEEP_AS_IS if indent + markup.column_width(text) > LINE_LENGTH else text


def wrapped(value: Any, indent: int) -> str:
    """A literal on its own line at ``indent``, ending with a comma."""
    return wrapped_literal(value, indent, indent, 1)


def keyword_argument(option: tuple[str, Any], indent: int) -> str:
    """``key=value`` for a line at ``indent`` that ends with a comma."""
    key, value = option
    return f"{key}=" + wrapped_literal(value, indent, indent + len(key) + 1, 1)


def assignment(value: Any, name: str, indent: int) -> str:
    """``name = value`` for a line at ``indent``."""
    head = f"{name} = "
    return head + wrapped_literal(value, indent, indent + len(head), 0)


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
    env.filters["comment_literal"] = comment_literal
    env.filters["keyword_argument"] = keyword_argument
    env.filters["assignment"] = assignment
    env.filters["one_line"] = one_line
    env.filters["wrapped"] = wrapped
    env.filters.update(
        md_text=markup.md_text,
        md_paragraphs=markup.md_paragraphs,
        md_code=markup.md_code,
        rst_text=markup.rst_text,
        rst_literal=markup.rst_literal,
        rst_heading=markup.rst_heading,
    )
    return env


def render_module(schema: Schema) -> str:
    template = environment().get_template("module.py.j2")
    layout = module_layout.layout(schema)
    return template.render(
        schema=schema, layout=layout, version=__version__, runtime_api=RUNTIME_API
    )


def render_params_file(params_file: ParamsFile) -> str:
    return environment().get_template("params.yaml.j2").render(params_file=params_file)


_DOCS_TEMPLATES = {"markdown": "docs.md.j2", "rst": "docs.rst.j2"}


def render_docs(page: DocsPage, format: str) -> str:
    """The documentation page in ``format``: "markdown" or "rst"."""
    template = environment().get_template(_DOCS_TEMPLATES[format])
    return template.render(page=page, params_file=page.default_params)
