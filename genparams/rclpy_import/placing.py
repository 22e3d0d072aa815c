"""Where imported parameters go in the schema's tree: plain names, per-item parameters
(``for_each``), parameters of a mapped group (``gains.*.p``) and of an open group; and
what keeps a name from its place (a namespace that is a parameter, a name declared twice).
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from typing import Any

from genparams.importing import attribute_clash
from genparams.rclpy_import.found import Found
from genparams.rclpy_import.leaves import condition_value
from genparams.runtime.core.conditions import KeyTest, NoneOf, passes, tested_values, written_test
from genparams.runtime.core.naming import ENTRY_KEY, NAME_RULE, NODE_PARAMETERS, is_ros_name
from genparams.schema.shape import is_parameter

FOR_EACH = "for_each"
_CONDITION_TYPES = ("bool", "int", "double", "string")
OVERRIDES_KEYS = "overrides"  # the for_each of an open group


@dataclass(frozen=True)
class ItemPlace:
    """Where the item sits in a name built from a loop's item: the text before it and
    after it (``f"gains.{joint}.p"``: ``gains`` and ``p``; ``joint`` alone: both empty).
    ``open`` when the items are the keys found under ``head`` in the overrides."""

    head: str
    tail: str
    open: bool = False

    @property
    def group(self) -> str:
        """The schema key holding the items: ``gains``, or ``*`` at the top level."""
        return self.head or ENTRY_KEY

    @property
    def key(self) -> str:
        """The schema key of the declaration: its per-item leaf (no tail), or its place in
        the mapped group with ``*`` for the entry."""
        if not self.tail:
            return self.group
        return f"{self.head}.{ENTRY_KEY}.{self.tail}" if self.head else f"{ENTRY_KEY}.{self.tail}"

    @property
    def what(self) -> str:
        if self.open:
            return "a parameter of an open group"
        return "a parameter of a mapped group" if self.tail else "a per-item parameter"

    def names(self) -> str:
        """What the items name, for the note on the key list."""
        if self.tail:
            where = "the top level" if not self.head else repr(self.head)
            return f"entries of {where} (a mapped group)"
        if not self.head:
            return "parameters of the top level"
        return f"the parameters of {self.head!r}"


@dataclass
class SchemaTree:
    """The parameters placed so far: the tree, the first declaration of each schema key,
    and each mapped group's key list."""

    tree: dict[str, Any] = field(default_factory=dict)
    first: dict[str, Found] = field(default_factory=dict)
    groups: dict[str, str] = field(default_factory=dict)

    def per_item(self, found: Found) -> tuple[ItemPlace | None, str]:
        """A declaration in a loop over a string_array parameter's value, named by the
        item (``joint``, ``f"offsets.{joint}"``) or by the item and more
        (``f"gains.{joint}.p"``, also as ``declare_parameters(f"gains.{joint}", ...)``):
        where the item sits in its name, or why it cannot be imported."""
        loop = found.runtime_loop
        what = found.name.problem.what if found.name.problem is not None else "the name"
        computed = f"one parameter per item of {loop}, its name computed from the item"
        if found.name_is_item:
            computed = f"one parameter per item of {loop}, named by the item"
        place = item_place(found)
        if place is None:
            variable = found.loop_variable
            if variable is None or not any(uses(n, variable) for n in name_nodes(found)):
                return None, f"a name computed at run time ({what})"
            return None, (
                f"{computed}: only a name holding the item as one whole part between dots "
                "translates"
            )
        if place.open:
            return self.open_entry(found, place, computed)
        key = found.loop_parameter
        target = self.first.get(key) if key is not None else None
        leaf = self.leaf(key) if key is not None and target is not None else None
        if (
            leaf is None
            or leaf.get("type") != "string_array"
            or "default" not in leaf
            or "when" in leaf
            or FOR_EACH in leaf
        ):
            return None, (
                f"{computed}: the loop must run over a string_array parameter declared "
                "before it, with a value and no condition"
            )
        if found.condition is not None:
            return None, f"{computed}, under a condition: {place.what} has no when"
        if found.in_list and not place.tail:
            return None, f"{computed}, in a declare_parameters list"
        return place, ""

    def open_entry(
        self, found: Found, place: ItemPlace, computed: str
    ) -> tuple[ItemPlace | None, str]:
        """A declaration in a loop over the keys found under a prefix in the overrides:
        a parameter of an open group when it is named ``<prefix>.<key>.<field>``."""
        prefix = found.loop_prefix
        under = f"one entry per key found under {prefix!r} in the overrides"
        if not place.tail:
            return None, (
                f"{computed}: one value per key found under {prefix!r} in the overrides: an "
                f"open group holds parameters of each key ({prefix}.<key>.<field>)"
            )
        if place.head != prefix:
            return None, (
                f"{computed}: the keys are found under {prefix!r} in the overrides, the name "
                f"puts them under {place.head or 'the top level'!r}: an open group holds "
                f"{under}, under {prefix!r} itself"
            )
        if found.condition is not None:
            return None, f"{computed}, under a condition: {place.what} has no when"
        return place, ""

    def when(self, found: Found) -> tuple[dict[str, Any] | None, str]:
        """The ``when:`` of a declaration under ``if``, or why it cannot have one."""
        simple = (
            "only ==, !=, in or not in against literals, or a bool's truth, of a parameter "
            "declared before it translates, in its body or its else"
        )
        if found.when is None:
            return None, simple
        name, test = found.when
        leaf = self.leaf(name) if name in self.first else None
        if leaf is None:
            return None, f"{name!r} is not a parameter imported before it"
        kind = leaf.get("type")
        if kind not in _CONDITION_TYPES or "default" not in leaf or "when" in leaf:
            return None, (
                f"{name!r} must be a bool, int, double or string parameter with a value and "
                "no condition of its own"
            )
        kept = [condition_value(kind, v) for v in tested_values(test)]
        if any(v is None for v in kept):
            return None, (
                f"a value compared with {name!r} is not a {kind} (a truth test translates "
                "on a bool parameter only)"
            )
        kept_test: KeyTest = NoneOf(*kept) if isinstance(test, NoneOf) else tuple(kept)
        if kind == "bool" and isinstance(kept_test, NoneOf):  # not true: false
            kept_test = tuple(v for v in (True, False) if passes(kept_test, v))
        if not tested_values(kept_test):
            return None, f"no value of {name!r} passes the tests around it: it is never declared"
        return {name: written_test(kept_test)}, ""

    def per_entry(self, name: str) -> bool:
        """Whether ``name`` is an entry of a per-item parameter or of a group
        (``offsets.a`` under ``offsets: {for_each: joints}``): the schema states it."""
        node: Any = self.tree
        for part in name.split(".")[:-1]:
            if not isinstance(node, dict) or part not in node:
                return False
            node = node[part]
            if isinstance(node, dict) and FOR_EACH in node:
                return True
        return False

    def leaf(self, name: str) -> dict[str, Any] | None:
        node: Any = self.tree
        for part in name.split("."):
            if not isinstance(node, dict) or part not in node:
                return None
            node = node[part]
        return node if is_parameter(node) else None

    def name_problem(self, name: str) -> str | None:
        if name in self.first:
            where = self.first[name].where
            return f"declared again (first at {where.line}:{where.column}; rclpy refuses it)"
        if name != "*" and not is_ros_name(name):
            return f"not a name genparams declares (dotted names of {NAME_RULE})"
        if name in NODE_PARAMETERS:
            return "every node declares it already"
        parts = name.split(".")
        clash = attribute_clash(name, self.first)
        if clash is not None:
            return clash
        for index in range(1, len(parts) + 1):
            space = ".".join(parts[:index])
            if space in self.groups:
                return (
                    f"{where_of(space)} holds {entries_of(self.groups[space])}: "
                    "a parameter of its own cannot sit in it"
                )
        for index in range(1, len(parts)):
            if ".".join(parts[:index]) in self.first:
                return f"{'.'.join(parts[:index])!r} is a parameter, not a namespace"
        if any(other.startswith(name + ".") for other in self.first):
            return f"{name!r} is already a namespace"
        return None

    def entry_problem(self, place: ItemPlace, key_list: str) -> str | None:
        """Why a parameter of a mapped group cannot be placed, or None."""
        name = place.key
        if name in self.first:
            where = self.first[name].where
            return f"declared again (first at {where.line}:{where.column}; rclpy refuses it)"
        inner = place.tail.split(".")
        group = place.group
        owner = self.groups.get(group)
        if owner is not None and owner != key_list:
            return f"{where_of(group)} already holds {entries_of(owner)}"
        if owner is None:
            outer = place.head.split(".") if place.head else []
            for index in range(1, len(outer)):
                space = ".".join(outer[:index])
                if space in self.first:
                    return f"{space!r} is a parameter, not a namespace"
                if space in self.groups:
                    return (
                        f"{space!r} holds {entries_of(self.groups[space])}: a "
                        "mapped group inside it is not written by the import"
                    )
            if group in self.first:
                what = "per-item parameters" if group == ENTRY_KEY else "a parameter"
                return f"{where_of(group)} is {what}, not a mapped group"
            if place.head and any(other.startswith(group + ".") for other in self.first):
                return (
                    f"{where_of(group)} already holds parameters of its own: a mapped group "
                    "holds only its entries"
                )
        base = name[: -len(place.tail)]
        for index in range(1, len(inner)):
            if base + ".".join(inner[:index]) in self.first:
                return f"{'.'.join(inner[:index])!r} is a parameter, not a namespace"
        if any(other.startswith(name + ".") for other in self.first):
            return f"{place.tail!r} is already a namespace"
        return attribute_clash(name, self.first)

    def unplace(self, name: str) -> None:
        """Take a parameter out of the tree, and the namespaces and mapped groups it
        leaves empty."""
        parts = _tree_path(name)
        chain = [self.tree]
        for part in parts[:-1]:
            chain.append(chain[-1][part])
        del chain[-1][parts[-1]]
        for depth in range(len(parts) - 1, 0, -1):
            if set(chain[depth]) <= {FOR_EACH}:
                del chain[depth - 1][parts[depth - 1]]
                self.groups.pop(".".join(parts[:depth]), None)

    def place_entry(self, place: ItemPlace, key_list: str, leaf: dict[str, Any]) -> None:
        """Put a parameter of a mapped group in the tree, making the group if needed."""
        node = self.tree
        for part in place.head.split(".") if place.head else [ENTRY_KEY]:
            node = node.setdefault(part, {})
        node.setdefault(FOR_EACH, key_list)
        self.groups[place.group] = key_list
        *spaces, last = place.tail.split(".")
        for part in spaces:
            node = node.setdefault(part, {})
        node[last] = leaf

    def place(self, name: str, leaf: dict[str, Any]) -> None:
        *spaces, last = name.split(".")
        node = self.tree
        for part in spaces:
            node = node.setdefault(part, {})
        node[last] = leaf


def key_list(found: Found) -> str:
    """What keys the mapped group of a per-item declaration: its key list, or the
    overrides."""
    if found.loop_prefix is not None or found.loop_parameter is None:
        return OVERRIDES_KEYS
    return found.loop_parameter


def entries_of(key_list: str) -> str:
    if key_list == OVERRIDES_KEYS:
        return "one entry per key given under it in the overrides"
    return f"one entry per item of {key_list!r}"


def where_of(group: str) -> str:
    return "the top level" if group == ENTRY_KEY else repr(group)


def _tree_path(key: str) -> list[str]:
    """A schema key's place in the tree: ``gains.*.p`` -> gains, p (the entry is the
    group's content); ``*.p`` (a mapped group at the top level) -> ``*``, p."""
    parts = key.split(".")
    return parts[:1] + [p for p in parts[1:] if p != ENTRY_KEY]


def name_nodes(found: Found) -> list[ast.AST]:
    """The expressions a declaration's name is made of: the name, and the namespace of a
    declare_parameters list."""
    nodes = [found.name_node] if found.name_node is not None else []
    if found.in_list and found.namespace_node is not None:
        nodes.insert(0, found.namespace_node)
    return nodes


def item_place(found: Found) -> ItemPlace | None:
    """``joint`` -> ("", ""), ``f"offsets.{joint}"`` or ``"offsets." + joint`` ->
    ("offsets", ""), ``f"gains.{joint}.p"`` or ``declare_parameters(f"gains.{joint}",
    [("p", ...)])`` -> ("gains", "p"): where the loop's item sits in the name, when it is
    one whole part between dots and the name holds nothing else computed; else None."""
    variable = found.loop_variable
    if variable is None or (found.loop_parameter is None and found.loop_prefix is None):
        return None
    parts = _name_parts(found.name_node)
    if parts is None:
        return None
    if found.in_list and found.namespace_node is not None:
        space = _name_parts(found.namespace_node)
        if space is None:
            return None
        if None in space:
            parts = [*space, ".", *parts]
        elif "".join(p for p in space if p is not None):  # rclpy joins a namespace with "."
            parts = ["".join(p for p in space if p is not None), ".", *parts]
    if parts.count(None) != 1:
        return None
    names = [n.id for node in name_nodes(found) for n in ast.walk(node) if isinstance(n, ast.Name)]
    if names != [variable]:
        return None
    index = parts.index(None)
    head = "".join(p for p in parts[:index] if p is not None)
    tail = "".join(p for p in parts[index + 1 :] if p is not None)
    if head and not (head.endswith(".") and is_ros_name(head[:-1])):
        return None
    if tail and not (tail.startswith(".") and is_ros_name(tail[1:])):
        return None
    return ItemPlace(head[:-1], tail[1:], open=found.loop_prefix is not None)


def written_name(found: Found) -> str:
    """A name built from a loop's item as the source writes it: ``offsets.{joint}``."""
    place = item_place(found)
    if place is None:
        return ""
    item = "{" + (found.loop_variable or "item") + "}"
    return ".".join(p for p in (place.head, item, place.tail) if p)


def _name_parts(node: ast.AST | None) -> list[str | None] | None:
    """A name as literal text and the loop variable (None), or None when it is more."""
    if isinstance(node, ast.Name):
        return [None]
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return [node.value]
    if isinstance(node, ast.JoinedStr):
        out: list[str | None] = []
        for part in node.values:
            if isinstance(part, ast.Constant) and isinstance(part.value, str):
                out.append(part.value)
            elif (
                isinstance(part, ast.FormattedValue)
                and part.conversion == -1
                and part.format_spec is None
                and isinstance(part.value, ast.Name)
            ):
                out.append(None)
            else:
                return None
        return out
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left, right = _name_parts(node.left), _name_parts(node.right)
        return None if left is None or right is None else left + right
    return None


def uses(node: ast.AST | None, variable: str) -> bool:
    """Whether every name in ``node`` is ``variable`` and there is one."""
    names = [n.id for n in ast.walk(node) if isinstance(n, ast.Name)] if node else []
    return bool(names) and all(n == variable for n in names)
