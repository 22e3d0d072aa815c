"""A ``.launch.yaml`` as frontend entities: ``launch:`` holds a list of one-key mappings
(``- node: {pkg: ..., param: [...]}``); every value keeps its line and column."""

from __future__ import annotations

import yaml

from genparams.launch.frontend import Entity
from genparams.launch.scope import Scope
from genparams.schema.errors import Location

CHILD_LISTS = ("param", "arg", "composable_node", "children", "remap", "env")


def yaml_entities(source: str, scope: Scope) -> list[Entity]:
    try:
        document = yaml.compose(source, Loader=yaml.SafeLoader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = scope.at(mark.line + 1, mark.column + 1) if mark else scope.at(1, 1)
        scope.unknown("the launch file (not YAML)", where)
        return []
    if not isinstance(document, yaml.MappingNode):
        return []
    for key, value in document.value:
        if key.value == "launch" and isinstance(value, yaml.SequenceNode):
            return _entities(value, scope)
    return []


def _where(node: yaml.Node, scope: Scope) -> Location:
    return scope.at(node.start_mark.line + 1, node.start_mark.column + 1)


def _entities(sequence: yaml.SequenceNode, scope: Scope) -> list[Entity]:
    found = []
    for item in sequence.value:
        if isinstance(item, yaml.MappingNode) and len(item.value) == 1:
            key, body = item.value[0]
            found.append(_entity(str(key.value), body, scope, _where(key, scope)))
    return found


def _entity(tag: str, body: yaml.Node, scope: Scope, where: Location) -> Entity:
    entity = Entity(tag, {}, where)
    if isinstance(body, yaml.SequenceNode):  # group: [...] / a list of children
        entity.children = _entities(body, scope)
        return entity
    if not isinstance(body, yaml.MappingNode):
        return entity
    for key, value in body.value:
        name = str(key.value)
        if isinstance(value, yaml.ScalarNode):
            entity.attributes[name] = value.value
            entity.values[name] = _where(value, scope)
        elif isinstance(value, yaml.SequenceNode) and name in CHILD_LISTS:
            child_tag = {"children": "", "composable_node": "composable_node"}.get(name, name)
            for item in value.value:
                if child_tag == "" and isinstance(item, yaml.MappingNode) and len(item.value) == 1:
                    k, v = item.value[0]
                    entity.children.append(_entity(str(k.value), v, scope, _where(k, scope)))
                elif isinstance(item, yaml.MappingNode):
                    entity.children.append(_entity(child_tag, item, scope, _where(item, scope)))
    return entity
