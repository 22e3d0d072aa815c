"""Read a node's schema message as a tuning page or an audit receives it: never trusted.

Anyone can publish on ``/<node>/genparams/schema``. The text is read with the
codec's limits, then its shape is checked field by field against format 1
(the format :mod:`~genparams.runtime.node.schema_topic` writes), and every
parameter is compiled with the runtime's own validators, as the node compiled
it. Whatever is wrong comes back as a :class:`SchemaProblem` naming the field,
never as an exception.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from dataclasses import dataclass
from typing import Any

from genparams.runtime.core.conditions import controlling_names, json_condition
from genparams.runtime.core.errors import GenparamsError
from genparams.runtime.core.json_codec import JsonError, Limits, loads
from genparams.runtime.core.naming import ENTRY_KEY, strip_prefix
from genparams.runtime.core.param_spec import ParamSpec
from genparams.runtime.core.spec import RuleSpec, SchemaSpec, compile_param
from genparams.runtime.core.tree import Group
from genparams.runtime.core.types import TYPES
from genparams.runtime.core.validators import Custom, Pattern

FORMAT_VERSION = 1
"""The version of the schema message's shape: written by the node, checked by readers."""

SCHEMA_MESSAGE_LIMITS = Limits(max_chars=16 << 20, max_depth=32)
"""16 MiB is about 40,000 described parameters; format 1 nests 9 deep at most."""


@dataclass(frozen=True)
class SchemaProblem:
    """Why a schema message cannot be used: shown for its node, in place of the schema."""

    detail: str


class _ShapeError(GenparamsError, ValueError):
    pass


def _kind(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, int | float):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, list):
        return "a list"
    return "an object"


_CHECKS: dict[str, tuple[str, Any]] = {
    "str": ("a string", lambda v: isinstance(v, str)),
    "bool": ("a boolean", lambda v: isinstance(v, bool)),
    "list": ("a list", lambda v: isinstance(v, list)),
    "object": ("an object", lambda v: isinstance(v, dict)),
    "number": ("a number", lambda v: isinstance(v, int | float) and not isinstance(v, bool)),
    "str list": ("a list of strings", lambda v: isinstance(v, list) and all(map(_is_str, v))),
}


def _is_str(value: Any) -> bool:
    return isinstance(value, str)


def _field(
    holder: Mapping[str, Any], key: str, kind: str, where: str, *, null: bool = False
) -> Any:
    if key not in holder:
        raise _ShapeError(f"{where}: no {key!r}")
    value = holder[key]
    expected, accepts = _CHECKS[kind]
    if not (accepts(value) or (null and value is None)):
        also = " or null" if null else ""
        raise _ShapeError(f"{where}.{key}: expected {expected}{also}, got {_kind(value)}")
    return value


def _items(holder: Mapping[str, Any], key: str, where: str) -> list[tuple[str, dict[str, Any]]]:
    """The objects of a list field, each with its place (``classes[0]``)."""
    items = _field(holder, key, "list", where)
    for index, item in enumerate(items):
        if not isinstance(item, dict):
            raise _ShapeError(f"{where}.{key}[{index}]: expected an object, got {_kind(item)}")
    return [(f"{where}.{key}[{index}]", item) for index, item in enumerate(items)]


def frozen(value: Any) -> Any:
    """JSON lists as the tuples a ParamSpec holds (dicts, such as length's, stay)."""
    if isinstance(value, list):
        return tuple(frozen(item) for item in value)
    return value


def param_from_json(described: Mapping[str, Any], name: str) -> ParamSpec:
    """The ParamSpec a shape-checked parameter description stands for."""
    kind = TYPES[described["type"]]
    optional = described.get("optional", False)
    no_default = described["required"] or optional
    default = None if no_default else kind.coerce_default(described["default"])
    span = described.get("range")
    return ParamSpec(
        name=name,
        type=described["type"],
        default=default,
        required=described["required"],
        optional=optional,
        read_only=described["read_only"],
        range=None if span is None else (span["min"], span["max"], span["step"]),
        choices=None if described["choices"] is None else frozen(described["choices"]),
        validators=tuple((rule, frozen(arg)) for rule, arg in described["validators"]),
        aliases=tuple(described.get("aliases", ())),
        when=json_condition(described["when"], "when") if "when" in described else (),
    )


def class_spec(described: Mapping[str, Any]) -> SchemaSpec:
    """One shape-checked class description as the spec it was declared from, names
    relative to its prefix: it compiles, with the runtime's compiler, to the node's checks.

    Raises ValueError when a parameter is not under the class prefix, or its condition
    (``when``) names no parameter of the class.
    """
    prefix = described["prefix"]

    def relative(name: str) -> str:
        if name == prefix:
            return ""
        found = strip_prefix(prefix, name) if prefix else name
        if found is None:
            raise ValueError(f"{name!r} is not under the class prefix {prefix!r}")
        return found

    params = [param_from_json(p, relative(p["name"])) for p in described["parameters"]]
    fixed = {param.name for param in params}
    for param in params:
        for name in controlling_names(param.when):
            if name not in fixed:
                raise ValueError(f"{param.name!r}: when names {name!r}, not a parameter")
    groups: dict[str, type[Group]] = {}
    for param in params:  # every namespace that holds a fixed parameter
        parts = param.name.split(".")
        groups.update((".".join(parts[:i]), Group) for i in range(1, len(parts)))
    maps = {}
    for group in described["maps"]:
        path = relative(group["path"])
        maps[path] = relative(group["for_each"])
        head = f"{path}.{ENTRY_KEY}" if path else ENTRY_KEY
        groups[head] = Group
        params.extend(param_from_json(f, f"{head}.{f['name']}") for f in group["fields"])
    rules = tuple(
        RuleSpec(r["name"], r["check"], r.get("description", "")) for r in described["rules"]
    )
    return SchemaSpec(str(described["class"]), tuple(params), groups, maps, rules)


def trusted(check: Custom, packages: Collection[str]) -> bool:
    """Whether a custom validator's module is in one of ``packages`` (or is one).

    A message names any function it likes: a tool imports and calls one only
    from a package its user trusts (``--trust-package``), never ``os:system``
    because a message says so.
    """
    module = check.target.partition(":")[0]
    return any(module == package or module.startswith(package + ".") for package in packages)


def why_not_run(check: Custom, packages: Collection[str]) -> str | None:
    """Why a tool trusting ``packages`` does not run a message's custom validator, if it does not:
    its package is not trusted (it is then never imported), or it does not import here."""
    if not trusted(check, packages):
        package = check.target.partition(":")[0].partition(".")[0]
        return f"its package is not trusted (--trust-package {package})"
    try:
        check.resolve()
    except Exception as exc:  # any import error: the module is not usable on this machine
        return f"it does not import here ({type(exc).__name__}: {exc})"
    return None


def _check_parameter(described: dict[str, Any], where: str) -> None:
    name = _field(described, "name", "str", where)
    where = f"{where} ({name})"
    type_name = _field(described, "type", "str", where)
    if type_name not in TYPES:
        raise _ShapeError(f"{where}.type: unknown type {type_name!r} (known: {', '.join(TYPES)})")
    _field(described, "required", "bool", where)
    _field(described, "read_only", "bool", where)
    _field(described, "description", "str", where)
    _field(described, "unit", "str", where, null=True)
    _field(described, "constraints", "str list", where)
    _field(described, "aliases", "str list", where)
    _field(described, "choices", "list", where, null=True)
    span = _field(described, "range", "object", where, null=True)
    if span is not None:
        for key in ("min", "max", "step"):
            _field(span, key, "number", f"{where}.range")
    for index, pair in enumerate(_field(described, "validators", "list", where)):
        if not (isinstance(pair, list) and len(pair) == 2 and isinstance(pair[0], str)):
            raise _ShapeError(f"{where}.validators[{index}]: expected [rule, argument]")
    if "optional" in described:
        _field(described, "optional", "bool", where)
    if "when" in described:
        try:
            json_condition(described["when"], f"{where}.when")
        except ValueError as exc:
            raise _ShapeError(str(exc)) from None
    if "default" not in described:
        raise _ShapeError(f"{where}: no 'default'")
    try:
        for check in compile_param(param_from_json(described, name)).checks:
            if isinstance(check, Pattern):
                check.compiled()  # one the engine refuses is refused here, with the shape
    except KeyError as exc:  # build_validator's unknown rule
        raise _ShapeError(f"{where}: unknown validator {exc}") from None
    except Exception as exc:  # whatever a hostile argument makes a validator's builder raise
        raise _ShapeError(f"{where}: {exc}") from None


def _check_class(described: dict[str, Any], where: str) -> None:
    _field(described, "class", "str", where)
    _field(described, "prefix", "str", where)
    _field(described, "hash", "str", where)
    for place, parameter in _items(described, "parameters", where):
        _check_parameter(parameter, place)
    for place, group in _items(described, "maps", where):
        _field(group, "path", "str", place)
        _field(group, "for_each", "str", place)
        for field_place, field in _items(group, "fields", place):
            _check_parameter(field, field_place)
    for place, rule in _items(described, "rules", where):
        for key in ("name", "check", "description"):
            _field(rule, key, "str", place)
        _field(rule, "parameters", "str list", place)
    try:
        class_spec(described)
    except ValueError as exc:  # a parameter outside the class's prefix
        raise _ShapeError(f"{where}: {exc}") from None


def check_schema_message(message: Any, node: str) -> SchemaProblem | None:
    """What is wrong with a decoded message published on ``node``'s schema topic, if anything."""
    try:
        if not isinstance(message, dict):
            raise _ShapeError(f"expected an object, got {_kind(message)}")
        if "format" not in message:
            raise _ShapeError("no 'format'")
        version = message["format"]
        if type(version) is not int or version != FORMAT_VERSION:
            shown = repr(version) if type(version) is int else _kind(version)
            raise _ShapeError(f"format {shown}: this genparams reads format {FORMAT_VERSION}")
        named = _field(message, "node", "str", "message")
        if named != node:
            raise _ShapeError(f"names node {named!r}, but was published on the topic of {node}")
        _field(message, "genparams", "str", "message")
        _field(message, "hash", "str", "message")
        for place, described in _items(message, "classes", "message"):
            _check_class(described, place)
    except _ShapeError as exc:
        return SchemaProblem(f"schema message: {exc}")
    return None


def read_schema_message(text: str, node: str) -> dict[str, Any] | SchemaProblem:
    """The message ``node``'s schema topic carried, or why it cannot be used."""
    try:
        message = loads(text, SCHEMA_MESSAGE_LIMITS)
    except JsonError as exc:
        return SchemaProblem(f"schema message: {exc}")
    problem = check_schema_message(message, node)
    return message if problem is None else problem
