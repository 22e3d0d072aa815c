"""``.launch.xml`` and ``.launch.yaml`` read as data: both are launch's "frontend", the
same entities (``node``, ``arg``, ``include``, ``group``, ``push-ros-namespace``, ``param``,
``node_container``, ``composable_node``...) with the same attributes and substitutions
(``$(var x)``, ``$(find-pkg-share pkg)``, ``$(env X)``, ``$(dirname)``). The two readers
turn a file into entities; this module follows them.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from genparams.launch.model import InlineParameters, Unknown
from genparams.launch.nodes import Substituted, add_node, parameter_value
from genparams.launch.scope import Scope, Value, condition_holds, environment, package_share
from genparams.schema.errors import Location

SUBSTITUTION = re.compile(r"\$\(([\w-]+)((?:\s+[^()\s]+)*)\s*\)")
NODE_TAGS = {"node": "node", "lifecycle_node": "lifecycle_node"}
CONTAINER_TAGS = ("node_container", "node-container")
COMPOSABLE_TAGS = ("composable_node", "composable-node")
PUSH_TAGS = ("push-ros-namespace", "push_ros_namespace")


@dataclass
class Entity:
    tag: str
    attributes: dict[str, str]
    location: Location
    children: list[Entity] = field(default_factory=list)
    values: dict[str, Location] = field(default_factory=dict)  # where each attribute is


def substituted(written: str, scope: Scope, location: Location) -> Value:
    """An attribute's value with its substitutions made; Unknown when one cannot be."""
    unknown: list[Unknown] = []

    def one(match: re.Match[str]) -> str:
        kind, words = match[1], match[2].split()
        found = _substitution(kind, words, scope, location)
        if isinstance(found, Unknown):
            unknown.append(found)
            return ""
        return str(found)

    result = SUBSTITUTION.sub(one, written)
    if unknown:
        return unknown[0]
    if "$(" in result:
        return scope.unknown(f"the substitution in {written!r}", location)
    return Substituted(result) if result != written else written


def _substitution(kind: str, words: list[str], scope: Scope, location: Location) -> Value:
    if kind in ("var", "arg") and words:
        found = scope.arguments.get(words[0])
        if found is None:
            return scope.unknown(f"launch configuration {words[0]} (never declared)", location)
        return found
    if kind == "find-pkg-share" and words:
        return package_share(words[0], scope, location)
    if kind == "env" and words:
        return environment(
            words[0], " ".join(words[1:]) if len(words) > 1 else None, scope, location
        )
    if kind == "dirname":
        return str(scope.file.parent)
    return scope.unknown(
        f"the substitution $({kind} {' '.join(words)})".replace(" )", ")"), location
    )


def follow(entities: list[Entity], scope: Scope) -> None:
    for entity in entities:
        scope = _perform(entity, scope)


def _attribute(entity: Entity, name: str, scope: Scope, default: str = "") -> Value:
    written = entity.attributes.get(name)
    if written is None:
        return default
    return substituted(written, scope, entity.values.get(name, entity.location))


def _runs(entity: Entity, scope: Scope) -> bool:
    for key, unless in (("if", False), ("unless", True)):
        if key in entity.attributes:
            holds = condition_holds(_attribute(entity, key, scope), unless)
            if isinstance(holds, Unknown):
                scope.unknown(
                    f"the condition {key}={entity.attributes[key]!r}",
                    entity.values.get(key, entity.location),
                )
                return False
            if not holds:
                return False
    return True


def _perform(entity: Entity, scope: Scope) -> Scope:
    if not _runs(entity, scope):
        return scope
    tag = entity.tag
    if tag == "arg":
        name = entity.attributes.get("name", "")
        if name and name not in scope.arguments:
            if "default" in entity.attributes:
                scope.arguments[name] = _attribute(entity, "default", scope)
            elif "value" in entity.attributes:
                scope.arguments[name] = _attribute(entity, "value", scope)
            else:
                scope.arguments[name] = Unknown(
                    f"launch argument {name} (no default, none given)", entity.location
                )
        return scope
    if tag == "let":
        scope.arguments[entity.attributes.get("name", "")] = _attribute(entity, "value", scope)
        return scope
    if tag in PUSH_TAGS:
        return scope.pushed(_attribute(entity, "namespace", scope), entity.location)
    if tag == "group":
        inner = scope.pushed(_attribute(entity, "namespace", scope, ""), entity.location)
        follow(entity.children, inner)
        return scope
    if tag == "include":
        file = _attribute(entity, "file", scope)
        if isinstance(file, Unknown):
            return scope
        arguments = dict(scope.arguments)
        for child in entity.children:
            if child.tag == "arg":
                arguments[child.attributes.get("name", "")] = _attribute(child, "value", scope)
        scope.include(Path(str(file)), arguments, scope, entity.location)
        return scope
    if tag in NODE_TAGS or tag in CONTAINER_TAGS:
        kind = NODE_TAGS.get(tag, "container")
        node = add_node(
            scope, kind, _fields(entity, scope), _parameters(entity, scope), entity.location
        )
        if tag in CONTAINER_TAGS:
            _composables(entity.children, scope, node.full_name if node else "")
        return scope
    if tag in ("load_composable_node", "load-composable-node"):
        target = _attribute(entity, "target", scope)
        _composables(entity.children, scope, target if isinstance(target, str) else "")
        return scope
    if tag in ("set_parameter", "set-parameter"):
        value = _attribute(entity, "value", scope)
        read = parameter_value(value if isinstance(value, Unknown) else Substituted(value))
        if isinstance(read, Unknown):
            scope.unknown(f"parameter {entity.attributes.get('name', '')}", entity.location)
            return scope
        return scope.with_parameter(entity.attributes.get("name", ""), read, entity.location)
    if tag in ("opaque_function", "timer"):
        scope.unknown(f"what <{tag}> starts", entity.location)
    return scope


def _composables(children: list[Entity], scope: Scope, container: str) -> None:
    for child in children:
        if child.tag in COMPOSABLE_TAGS and _runs(child, scope):
            fields = _fields(child, scope)
            fields["executable"] = _attribute(child, "plugin", scope)
            add_node(
                scope,
                "composable_node",
                fields,
                _parameters(child, scope),
                child.location,
                container,
            )


def _fields(entity: Entity, scope: Scope) -> dict[str, Value]:
    executable = entity.attributes.get("exec", entity.attributes.get("executable"))
    return {
        "package": _attribute(entity, "pkg", scope),
        "executable": "" if executable is None else substituted(executable, scope, entity.location),
        "name": _attribute(entity, "name", scope),
        "namespace": _attribute(entity, "namespace", scope, _attribute(entity, "ns", scope)),
    }


def _parameters(entity: Entity, scope: Scope) -> list[Value]:
    """``<param name= value=/>`` (nested ``<param name=>`` too) and ``<param from=/>``, in
    order: consecutive values make one set, a file stands alone."""
    sources: list[Value] = []
    inline: list[tuple[str, object, Location]] = []

    def flush() -> None:
        if inline:
            sources.append(InlineParameters(tuple(inline)))
            inline.clear()

    def walk(params: list[Entity], head: str) -> None:
        for param in params:
            if param.tag != "param":
                continue
            if "from" in param.attributes:
                flush()
                sources.append(_attribute(param, "from", scope))
                continue
            name = head + param.attributes.get("name", "")
            if param.children:
                walk(param.children, name + ".")
                continue
            where = param.values.get("value", param.location)
            raw = param.attributes.get("value", "")
            value = substituted(raw, scope, where)
            read = parameter_value(value if isinstance(value, Unknown) else Substituted(value))
            if isinstance(read, Unknown):
                scope.unknown(f"parameter {name}", read.location)
                continue
            inline.append((name, read, where))

    walk(entity.children, "")
    flush()
    return sources
