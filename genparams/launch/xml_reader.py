"""A ``.launch.xml`` as frontend entities, each element with its line and column (expat
says where every element starts; ElementTree would forget it)."""

from __future__ import annotations

from xml.parsers import expat

from genparams.launch.frontend import Entity
from genparams.launch.scope import Scope


def xml_entities(source: str, scope: Scope) -> list[Entity]:
    parser = expat.ParserCreate()
    root = Entity("", {}, scope.at(1, 1))
    stack = [root]

    def start(tag: str, attributes: dict[str, str]) -> None:
        where = scope.at(parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)
        entity = Entity(tag, dict(attributes), where, values=dict.fromkeys(attributes, where))
        stack[-1].children.append(entity)
        stack.append(entity)

    def end(tag: str) -> None:
        stack.pop()

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    try:
        parser.Parse(source, True)
    except expat.ExpatError as exc:
        scope.unknown(
            f"the launch file (not XML: {expat.errors.messages[exc.code]})",
            scope.at(exc.lineno, exc.offset + 1),
        )
        return []
    top = root.children
    if len(top) == 1 and top[0].tag == "launch":
        return top[0].children
    return top
