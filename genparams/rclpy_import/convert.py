"""A node's declarations -> a genparams schema, as plain data, with what could not be kept.

Each declaration is imported *exactly* (every descriptor field and the value
kept), *approximately* (imported, but part of it could not be read: a warning
says which) or *left out* (a warning says why). Nothing is dropped without a
warning at its FILE:LINE:COL.

A declaration by type only is ``optional``; ``dynamic_typing`` (or a name alone)
is ``type: any``; one in a loop over a string_array parameter's value, named by the
item, is a ``for_each`` leaf, and one named by the item and more
(``f"gains.{joint}.p"``) a parameter of a mapped group keyed by that list; one under
``if <parameter> == <literal>`` (or ``in``) has a ``when``.
"""

from __future__ import annotations

import ast
import math
import re
from dataclasses import dataclass, field
from typing import Any

from genparams.rclpy_import.features import AUTOMATIC, kept_by_the_node, what_it_needs
from genparams.rclpy_import.scan import Found, Unit, descriptor_of
from genparams.rclpy_import.values import DescriptorValue, RangeValue, TypeMarker, unparsed
from genparams.runtime.core.naming import ENTRY_KEY, NODE_PARAMETERS, SCHEMA_NAME, is_ros_name
from genparams.runtime.core.types import INT64_MAX, INT64_MIN
from genparams.schema.errors import Location, SchemaProblem

EXACT = "exact"
APPROXIMATE = "approximate"
LEFT_OUT = "left out"
FOR_EACH = "for_each"


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
class Imported:
    name: str
    data: dict[str, Any]
    warnings: list[SchemaProblem] = field(default_factory=list)
    notes: list[SchemaProblem] = field(default_factory=list)
    outcome: list[tuple[Found, str]] = field(default_factory=list)  # each declaration's fate
    # the schema key of each imported declaration, by id(found): a per-item one's is its
    # for_each leaf (``offsets``, or ``*`` at the top level), a mapped group's parameter's
    # its place with ``*`` for the entry (``gains.*.p``, ``*.p`` at the top level)
    keys: dict[int, str] = field(default_factory=dict)
    # the node declares what its overrides name, and the schema every parameter it reads:
    # the patch takes the option out
    replaces_automatic: bool = False

    def count(self, outcome: str) -> int:
        return sum(1 for _, o in self.outcome if o == outcome)

    @property
    def imported_names(self) -> set[str]:
        """The names of the imported declarations; a per-item one's its schema key."""
        return {
            f.name.value if f.name.problem is None else self.keys[id(f)]
            for f, o in self.outcome
            if o != LEFT_OUT
        }


def schema_name(unit_name: str, file_stem: str) -> str:
    """``KeyTeleopNode`` -> ``key_teleop``; a file's own functions take the file's name."""
    base = unit_name or file_stem
    if unit_name.endswith("Node") and len(unit_name) > len("Node"):
        base = unit_name[: -len("Node")]
    name = re.sub(r"(?<=[a-z0-9])([A-Z])|(?<=[A-Z])([A-Z])(?=[a-z])", r"_\1\2", base).lower()
    name = re.sub(r"[^a-z0-9_]+", "_", name).strip("_")
    return name if SCHEMA_NAME.fullmatch(name) else f"node_{name}".rstrip("_")


def convert(unit: Unit, file: str, lines: list[str], name: str) -> Imported:
    return _Converter(unit, file, lines, name).run()


class _Converter:
    def __init__(self, unit: Unit, file: str, lines: list[str], name: str) -> None:
        self.unit = unit
        self.file = file
        self.lines = lines
        self.imported = Imported(name, {})
        self.tree: dict[str, Any] = {}
        self.first: dict[str, Found] = {}
        self.groups: dict[str, str] = {}  # each mapped group's schema key: its key list

    def run(self) -> Imported:
        for found in self.unit.found:
            self.imported.outcome.append((found, self.declaration(found)))
        self.keep_groups_whole()
        automatic = any(o.option == AUTOMATIC for o in self.unit.options)
        reads = [r for r in self.unit.reads if automatic and not self.declared(r)]
        for read in reads:
            self.imported.outcome.append((read, self.declaration(read)))
        every_read = bool(reads) and all(
            o != LEFT_OUT for f, o in self.imported.outcome[-len(reads) :]
        )
        self.imported.replaces_automatic = every_read
        used = [*self.unit.found, *reads]
        read_by_loops = {id(f.loop_source) for f in used if f.loop_source is not None}
        for option in self.unit.options:
            if id(option.at) in read_by_loops:
                continue  # the keys of an open group: its declarations say the rest
            if kept_by_the_node(option, every_read):
                self.note(option.at, "", what_it_needs(option, every_read))
            else:
                self.warn(option.at, "", what_it_needs(option))
        for change in self.unit.afterwards:
            self.warn(change.at, "", f"{change.construct}: the schema keeps the declared one")
        data: dict[str, Any] = {"genparams": 1, "name": self.imported.name}
        if self.unit.docstring:
            data["description"] = " ".join(self.unit.docstring.strip().split("\n\n")[0].split())
        data["parameters"] = self.tree
        self.imported.data = data
        return self.imported

    def declared(self, read: Found) -> bool:
        """Whether a read is of a parameter the schema holds already."""
        if read.name.problem is None:
            return read.name.value in self.first
        place = item_place(read)
        return place is not None and place.key in self.first

    def keep_groups_whole(self) -> None:
        """One statement declaring several parameters (a loop over literal items, a
        declare_parameters list whose result is used) stays in the node whole when any
        of them is left out: the others are left out with it, or the node would declare
        them twice."""
        groups: dict[int, list[int]] = {}
        for index, (found, _) in enumerate(self.imported.outcome):
            if found.read is not None:
                continue  # reads stay in the node
            if found.literal_loop is not None:
                groups.setdefault(id(found.literal_loop), []).append(index)
            elif found.in_list and not (
                isinstance(found.statement, ast.Expr) and found.statement.value is found.call
            ):
                groups.setdefault(id(found.call), []).append(index)
        for members in groups.values():
            outcomes = [self.imported.outcome[i] for i in members]
            if all(o != LEFT_OUT for _, o in outcomes) or all(o == LEFT_OUT for _, o in outcomes):
                continue
            for index in members:
                found, outcome = self.imported.outcome[index]
                if outcome == LEFT_OUT:
                    continue
                name = self.imported.keys.pop(id(found))
                self.warn(found.at, name, "declared by the same statement as a parameter left "
                          "out: left out with it")  # fmt: skip
                self.unplace(name)
                del self.first[name]
                self.imported.outcome[index] = (found, LEFT_OUT)

    def location(self, node: ast.AST) -> Location:
        line = getattr(node, "lineno", 1)
        offset = getattr(node, "col_offset", 0)
        text = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        column = len(text.encode("utf-8")[:offset].decode("utf-8", errors="replace")) + 1
        return Location(self.file, line, column)

    def warn(self, node: ast.AST, key: str, message: str) -> None:
        problem = SchemaProblem(self.location(node), key, f"warning: {message}")
        if problem not in self.imported.warnings:
            self.imported.warnings.append(problem)

    def note(self, node: ast.AST, key: str, message: str) -> None:
        problem = SchemaProblem(self.location(node), key, f"note: {message}")
        if problem not in self.imported.notes:
            self.imported.notes.append(problem)

    def declaration(self, found: Found) -> str:
        at = found.at
        place: ItemPlace | None = None
        name: Any
        if found.name.problem is not None:
            if found.runtime_loop is None:
                what = found.name.problem.what
                self.warn(at, "", f"a name computed at run time ({what}): parameter left out")
                return LEFT_OUT
            place, reason = self.per_item(found)
            if place is None:
                self.warn(at, _written_name(found), f"{reason}: parameter left out")
                return LEFT_OUT
            name = place.key
        else:
            name = found.name.value
        if not isinstance(name, str):
            self.warn(at, "", f"the name {name!r} is not a string: parameter left out")
            return LEFT_OUT
        # a per-item parameter's messages name it as written (``offsets.{joint}``)
        shown = _written_name(found) if place is not None and not place.tail else name
        if found.nested is not None:
            self.warn(at, shown, f"declared inside {found.nested}: parameter left out")
            return LEFT_OUT
        when: dict[str, Any] | None = None
        if found.condition is not None:
            when, reason = self.when(found)
            if when is None:
                self.warn(at, shown, f"declared only under a condition ({found.condition}): "
                          f"{reason}: parameter left out")  # fmt: skip
                return LEFT_OUT
        from_item = place is not None and place.tail and _computed_from_item(found)
        if found.value.problem is not None and not from_item:
            self.warn(at, shown, f"value computed at run time ({found.value.problem.what}): "
                      "parameter left out")  # fmt: skip
            return LEFT_OUT
        if place is not None and place.tail:
            problem = self.entry_problem(place, _key_list(found))
        else:
            problem = self.name_problem(name)
        if problem is not None:
            self.warn(at, shown, f"{problem}: parameter left out")
            return LEFT_OUT
        leaf, problem = _typed_leaf(found)
        if leaf is None:
            self.warn(at, shown, f"{problem}: parameter left out")
            return LEFT_OUT
        if place is not None and leaf.get("optional"):
            self.warn(at, shown, f"one parameter per item of {found.runtime_loop}, with no value: "
                      f"{place.what} needs one: parameter left out")  # fmt: skip
            return LEFT_OUT
        schema_type = leaf["type"]
        exact = True
        if from_item:
            assert found.value_node is not None
            del leaf["default"]
            computed = unparsed(found.value_node)
            self.warn(at, shown, f"a default computed from the item ({computed}): "
                      "one schema default serves every entry: imported with none, so each "
                      "entry must be given a value")  # fmt: skip
            exact = False
        if found.read == "":
            self.warn(at, shown, "read with .value, the params file deciding its type: imported "
                      "as type: any (state its type in the schema)")  # fmt: skip
            exact = False
        if schema_type == "byte_array":
            self.note(
                at, shown, "an empty list: rclpy declares a byte_array, and so does the schema"
            )
        exact = self.descriptor(found, shown, schema_type, leaf) and exact
        if found.ignore_override.problem is not None or found.ignore_override.value:
            self.warn(at, shown, "ignore_override: genparams always applies overrides: imported "
                      "without it")  # fmt: skip
            exact = False
        if place is not None and not place.open:
            key = found.loop_parameter
            assert key is not None
            if not place.tail:
                leaf[FOR_EACH] = key
            self.note(
                self.first[key].at,
                key,
                f"its items name {place.names()}: genparams checks that each can "
                "name one, and says so in its additional_constraints",
            )
        if when is not None:
            leaf["when"] = when
        if place is not None and place.tail:
            self.place_entry(place, _key_list(found), leaf)
        else:
            self.place(name, leaf)
        self.first[name] = found
        self.imported.keys[id(found)] = name
        return EXACT if exact else APPROXIMATE

    def per_item(self, found: Found) -> tuple[ItemPlace | None, str]:
        """A declaration in a loop over a string_array parameter's value, named by the
        item (``joint``, ``f"offsets.{joint}"``) or by the item and more
        (``f"gains.{joint}.p"``, also as ``declare_parameters(f"gains.{joint}", ...)``):
        where the item sits in its name, or why it cannot be imported."""
        loop = found.runtime_loop
        assert found.name.problem is not None and loop is not None
        computed = f"one parameter per item of {loop}, its name computed from the item"
        if found.name_is_item:
            computed = f"one parameter per item of {loop}, named by the item"
        place = item_place(found)
        if place is None:
            variable = found.loop_variable
            if variable is None or not any(_uses(n, variable) for n in _name_nodes(found)):
                return None, f"a name computed at run time ({found.name.problem.what})"
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
        simple = "only == or in against literals of a parameter declared before it translates"
        if found.when is None:
            return None, simple
        name, values = found.when
        leaf = self.leaf(name) if name in self.first else None
        if leaf is None:
            return None, f"{name!r} is not a parameter imported before it"
        kind = leaf.get("type")
        if kind not in _CONDITION_TYPES or "default" not in leaf or "when" in leaf:
            return None, (
                f"{name!r} must be a bool, int, double or string parameter with a value and "
                "no condition of its own"
            )
        kept = [_condition_value(kind, v) for v in values]
        if any(v is None for v in kept):
            return None, f"a value compared with {name!r} is not a {kind}"
        return {name: kept[0] if len(kept) == 1 else kept}, ""

    def leaf(self, name: str) -> dict[str, Any] | None:
        node: Any = self.tree
        for part in name.split("."):
            if not isinstance(node, dict) or part not in node:
                return None
            node = node[part]
        return node if isinstance(node, dict) and "type" in node else None

    def name_problem(self, name: str) -> str | None:
        if name in self.first:
            where = self.location(self.first[name].at)
            return f"declared again (first at {where.line}:{where.column}; rclpy refuses it)"
        if "/" in name and is_ros_name(name.replace("/", ".")):
            return (
                "a name holding '/': rclpy accepts it, a schema names parameters by dotted "
                "tokens (rename it with '.' to keep it)"
            )
        if name != "*" and not is_ros_name(name):
            return "not a name genparams declares (dotted tokens of letters, digits and _)"
        if name in NODE_PARAMETERS:
            return "every node declares it already"
        parts = name.split(".")
        if len(parts) > 1 and parts[-1] == "type":
            return "a namespace cannot hold a parameter named 'type'"
        for index in range(1, len(parts) + 1):
            space = ".".join(parts[:index])
            if space in self.groups:
                return (
                    f"{_where(space)} holds {_entries_of(self.groups[space])}: "
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
            where = self.location(self.first[name].at)
            return f"declared again (first at {where.line}:{where.column}; rclpy refuses it)"
        inner = place.tail.split(".")
        if inner[-1] == "type":
            return "a namespace cannot hold a parameter named 'type'"
        group = place.group
        owner = self.groups.get(group)
        if owner is not None and owner != key_list:
            return f"{_where(group)} already holds {_entries_of(owner)}"
        if owner is None:
            outer = place.head.split(".") if place.head else []
            for index in range(1, len(outer)):
                space = ".".join(outer[:index])
                if space in self.first:
                    return f"{space!r} is a parameter, not a namespace"
                if space in self.groups:
                    return (
                        f"{space!r} holds {_entries_of(self.groups[space])}: a "
                        "mapped group inside it is not written by the import"
                    )
            if group in self.first:
                what = "per-item parameters" if group == ENTRY_KEY else "a parameter"
                return f"{_where(group)} is {what}, not a mapped group"
            if place.head and any(other.startswith(group + ".") for other in self.first):
                return (
                    f"{_where(group)} already holds parameters of its own: a mapped group "
                    "holds only its entries"
                )
        base = name[: -len(place.tail)]
        for index in range(1, len(inner)):
            if base + ".".join(inner[:index]) in self.first:
                return f"{'.'.join(inner[:index])!r} is a parameter, not a namespace"
        if any(other.startswith(name + ".") for other in self.first):
            return f"{place.tail!r} is already a namespace"
        return None

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

    def descriptor(self, found: Found, name: str, schema_type: str, leaf: dict[str, Any]) -> bool:
        """Copy the descriptor's fields into ``leaf``; False when part of it was lost."""
        at = found.at
        if found.descriptor.problem is not None:
            what = found.descriptor.problem.what
            self.warn(at, name, f"descriptor computed at run time ({what}): imported without it")
            return False
        descriptor = descriptor_of(found)
        if found.descriptor.given and descriptor is None and found.descriptor.value is not None:
            self.warn(at, name, "the descriptor is not a ParameterDescriptor: imported without it")
            return False
        if descriptor is None:
            return True
        exact = True
        for field_name, failure in descriptor.failed.items():
            self.warn(at, name, f"descriptor field {field_name} ({failure.what}) could not be "
                      "read: imported without it")  # fmt: skip
            exact = False
        fields = descriptor.fields
        for key in ("description", "additional_constraints"):
            text = fields.get(key)
            if isinstance(text, str) and text:
                leaf[key] = text
            elif text not in (None, ""):
                self.warn(at, name, f"descriptor field {key} is not text: imported without it")
                exact = False
        read_only = fields.get("read_only")
        if read_only:
            leaf["read_only"] = True
        return self.ranges(found, name, schema_type, descriptor, leaf) and exact

    def ranges(
        self,
        found: Found,
        name: str,
        schema_type: str,
        descriptor: DescriptorValue,
        leaf: dict[str, Any],
    ) -> bool:
        exact = True
        for key, integer in (("integer_range", True), ("floating_point_range", False)):
            ranges = descriptor.fields.get(key)
            if not ranges:
                continue
            fits = schema_type == ("int" if integer else "double")
            if not isinstance(ranges, list) or len(ranges) != 1:
                self.warn(found.at, name, f"{key} must hold one range: imported without it")
                exact = False
            elif not isinstance(ranges[0], RangeValue) or ranges[0].integer != integer:
                self.warn(found.at, name, f"{key} holds another kind of range: imported without it")
                exact = False
            elif schema_type == "any":
                self.warn(found.at, name, f"{key} on a dynamically typed parameter: imported "
                          "without it")  # fmt: skip
                exact = False
            elif not fits:
                self.warn(found.at, name, f"{key} on a {schema_type} parameter (rclpy does not "
                          "check it): imported without it")  # fmt: skip
                exact = False
            else:
                limits = ranges[0]
                convert = int if integer else float
                bounds: dict[str, Any] = {
                    "min": convert(limits.from_value),
                    "max": convert(limits.to_value),
                }
                if limits.step:
                    bounds["step"] = convert(limits.step)
                leaf["range"] = bounds
        return exact


def _schema_type(value: Any) -> tuple[str | None, str]:
    """The type rclpy gives a declaration of this value (Parameter.Type.from_parameter_value)."""
    if value is None:
        return None, "a None value: rclpy refuses to declare it without dynamic typing"
    if isinstance(value, bool):
        return "bool", ""
    if isinstance(value, int):
        if not INT64_MIN <= value <= INT64_MAX:
            return None, f"{value} does not fit an int64"
        return "int", ""
    if isinstance(value, float):
        return "double", ""
    if isinstance(value, str):
        return "string", ""
    if isinstance(value, (list, tuple)):
        if all(isinstance(v, bytes) for v in value):
            return ("byte_array", "") if not value else (None, "a list of bytes")
        for kind, schema_type in ((bool, "bool"), (int, "int"), (float, "double"), (str, "string")):
            if all(isinstance(v, kind) for v in value):
                return f"{schema_type}_array", ""
        return None, f"the list {value!r} mixes types: rclpy refuses it"
    if isinstance(value, TypeMarker):  # pragma: no cover (_typed_leaf took it)
        return None, "a type without a value"
    return None, f"{value!r} is not a parameter value"


_CONDITION_TYPES = ("bool", "int", "double", "string")


def _typed_leaf(found: Found) -> tuple[dict[str, Any] | None, str]:
    """The leaf's type, and its default or ``optional``, as rclpy would declare it."""
    if found.read is not None:  # a parameter the node reads: it must be given
        return {"type": found.read or "any"}, ""
    descriptor = descriptor_of(found)
    value = found.value.value
    if found.value.problem is not None and found.item_value is not None:
        value = found.item_value.value  # for a sample item: typed, never kept
    dynamic = descriptor is not None and bool(descriptor.fields.get("dynamic_typing"))
    if isinstance(value, TypeMarker):
        if value.schema_type == "not_set":
            return None, "Parameter.Type.NOT_SET: rclpy refuses it as a static type"
        if dynamic:
            return None, "a type with dynamic_typing=True: rclpy refuses it"
        return {"type": value.schema_type, "optional": True}, ""
    by_name_only = found.descriptor.value is None and found.descriptor.problem is None
    if dynamic or (value is None and by_name_only):
        if value is None:  # declared by name only, or with dynamic_typing and no value
            return {"type": "any", "optional": True}, ""
        schema_type, problem = _schema_type(value)
        if schema_type is None:
            return None, problem
        if schema_type == "byte_array":
            return None, "an empty list as a dynamically typed value: a schema cannot default to it"
        return {"type": "any", "default": _default(value)}, ""
    schema_type, problem = _schema_type(value)
    if schema_type is None:
        return None, problem
    return {"type": schema_type, "default": _default(value)}, ""


def _key_list(found: Found) -> str:
    """What keys the mapped group of a per-item declaration: its key list, or the
    overrides."""
    if found.loop_prefix is not None:
        return OVERRIDES_KEYS
    assert found.loop_parameter is not None
    return found.loop_parameter


def _entries_of(key_list: str) -> str:
    if key_list == OVERRIDES_KEYS:
        return "one entry per key given under it in the overrides"
    return f"one entry per item of {key_list!r}"


def _computed_from_item(found: Found) -> bool:
    """A value computed from the loop's item that a sample item gives a value of."""
    return found.item_value is not None and found.item_value.problem is None


def _where(group: str) -> str:
    return "the top level" if group == ENTRY_KEY else repr(group)


def _tree_path(key: str) -> list[str]:
    """A schema key's place in the tree: ``gains.*.p`` -> gains, p (the entry is the
    group's content); ``*.p`` (a mapped group at the top level) -> ``*``, p."""
    parts = key.split(".")
    return parts[:1] + [p for p in parts[1:] if p != ENTRY_KEY]


def _name_nodes(found: Found) -> list[ast.AST]:
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
    names = [n.id for node in _name_nodes(found) for n in ast.walk(node) if isinstance(n, ast.Name)]
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


def _written_name(found: Found) -> str:
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


def _uses(node: ast.AST | None, variable: str) -> bool:
    """Whether every name in ``node`` is ``variable`` and there is one."""
    names = [n.id for n in ast.walk(node) if isinstance(n, ast.Name)] if node else []
    return bool(names) and all(n == variable for n in names)


def _condition_value(kind: str, value: Any) -> Any:
    """``value`` as a value of the condition's parameter type, or None."""
    if kind == "bool":
        return value if isinstance(value, bool) else None
    if kind == "int":
        return value if isinstance(value, int) and not isinstance(value, bool) else None
    if kind == "double":
        ok = isinstance(value, (int, float)) and not isinstance(value, bool)
        return float(value) if ok else None
    return value if isinstance(value, str) else None


def _default(value: Any) -> Any:
    if isinstance(value, tuple):
        return list(value)
    if isinstance(value, float) and math.isnan(value):
        return float("nan")
    return value
