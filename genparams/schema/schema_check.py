"""Check a loaded document against schemas/genparams.schema.json, errors mapped to line/col."""

from __future__ import annotations

import functools
import json
from collections.abc import Iterator
from typing import Any

import jsonschema

from genparams.runtime.core.suggest import did_you_mean
from genparams.schema.errors import SchemaProblem
from genparams.schema.loader import LoadedDocument, Path, dotted
from genparams.schema.resources import resource_dir
from genparams.schema.shape import TYPE_KEY


@functools.cache
def _meta_schema() -> dict[str, Any]:
    text = (resource_dir("schemas") / "genparams.schema.json").read_text("utf-8")
    schema: dict[str, Any] = json.loads(text)
    return schema


@functools.cache
def _validator() -> jsonschema.Draft202012Validator:
    return jsonschema.Draft202012Validator(_meta_schema())


def check_document(document: LoadedDocument) -> list[SchemaProblem]:
    problems: list[SchemaProblem] = []
    for error in _validator().iter_errors(document.data):
        problems.extend(_problems(document, error))
    return problems


def _problems(
    document: LoadedDocument, error: jsonschema.ValidationError
) -> Iterator[SchemaProblem]:
    path: Path = tuple(error.absolute_path)
    schema = error.schema if isinstance(error.schema, dict) else {}
    if error.validator == "additionalProperties" and isinstance(error.instance, dict):
        allowed = set(schema.get("properties", {}))
        for key in error.instance:
            if key not in allowed:
                key_path = (*path, key)
                yield SchemaProblem(
                    document.key_location(key_path),
                    dotted(key_path),
                    f"unknown key {key!r}{did_you_mean(key, allowed)}",
                )
        return
    if error.validator == "required":
        yield SchemaProblem(
            document.key_location(path),
            dotted(path),
            error.message.replace("is a required property", "is required"),
        )
        return
    if error.validator == "enum":
        options: list[Any] = list(error.validator_value)  # type: ignore[arg-type]
        if isinstance(error.instance, str):
            message = (
                f"{error.instance!r} is not one of {', '.join(map(str, options))}"
                f"{did_you_mean(error.instance, options)}"
            )
        else:
            message = f"{_json(error.instance)} is not one of {', '.join(map(str, options))}"
        yield SchemaProblem(document.value_location(path), dotted(path), message)
        return
    if error.validator == "anyOf" and len(path) >= 2 and path[-2] == "validators":
        yield SchemaProblem(
            document.value_location(path), dotted(path), _validator_message(error.instance)
        )
        return
    if error.validator == "anyOf" and schema == _meta_schema()["$defs"]["condition_values"]:
        yield SchemaProblem(
            document.value_location(path), dotted(path), _condition_message(path, error.instance)
        )
        return
    if not path and error.validator == "type":
        yield SchemaProblem(
            document.value_location(path),
            "",
            "a schema is a mapping with genparams, name and parameters; "
            f"got {_json(error.instance)}",
        )
        return
    # Only namespaces take any key whose value is another node.
    is_namespace = isinstance(schema.get("additionalProperties"), dict)
    if error.validator == "type" and path[:1] == ("parameters",) and is_namespace:
        yield SchemaProblem(
            document.value_location(path),
            dotted(path),
            "expected a parameter (a mapping with 'type:') or a namespace (a mapping of "
            f"parameters), got {json.dumps(error.instance, default=str)[:60]}"
            + _type_namespace_hint(document, path),
        )
        return
    yield SchemaProblem(document.value_location(path), dotted(path), _plain(error))


def _type_namespace_hint(document: LoadedDocument, path: Path) -> str:
    """Why the mapping holding ``path`` is a namespace, when a ``type:`` mapping made it one."""
    holder: Any = document.data
    for part in path[:-1]:
        holder = holder[part]
    if isinstance(holder, dict) and isinstance(holder.get(TYPE_KEY), dict):
        return (
            f" ({dotted(path[:-1])} is a namespace: its 'type:' holds a mapping, so it names "
            "a parameter or namespace 'type')"
        )
    return ""


def _condition_message(path: Path, instance: Any) -> str:
    """Why a ``when`` value is not one: ``[]``, ``{not: []}``, a mapping in a list."""
    values = "a value or a non-empty list of values (booleans, numbers or strings)"
    if path[-1:] == ("not",):
        return f"not takes {values}, got {_json(instance)}"
    return f"a condition is {values}, or {{not: value or list}}, got {_json(instance)}"


def _validator_message(instance: Any) -> str:
    from genparams.runtime.core.validator_kinds import KINDS

    if isinstance(instance, str) and instance in KINDS:
        return f"validator {instance!r} needs an argument: {{{instance}: ...}}"
    if isinstance(instance, str):
        return f"unknown validator {instance!r}{did_you_mean(instance, KINDS)}"
    if isinstance(instance, dict) and len(instance) == 1:
        (name,) = instance
        return f"unknown validator {name!r}{did_you_mean(str(name), KINDS)}"
    return (
        "a validator is a name (not_empty) or a single-key mapping ({gt: 0}), "
        f"got {json.dumps(instance, default=str)[:60]}"
    )


def _plain(error: jsonschema.ValidationError) -> str:
    if error.validator == "type":
        return f"must be {_article(str(error.validator_value))}, got {_json(error.instance)}"
    if error.validator == "const":
        return (
            f"must be {error.validator_value!r}, got {json.dumps(error.instance, default=str)[:60]}"
        )
    if error.validator == "pattern":
        return f"{error.instance!r} must match {error.validator_value}"
    return error.message


def _json(value: Any) -> str:
    return json.dumps(value, default=str)[:60]


def _article(json_type: str) -> str:
    names = {
        "object": "a mapping",
        "array": "a list",
        "string": "a string",
        "number": "a number",
        "integer": "an integer",
        "boolean": "true or false",
    }
    return names.get(json_type, json_type)
