"""A node's declarations -> a genparams schema, as plain data, with what could not be kept.

Each declaration is imported *exactly* (every descriptor field and the value
kept), *approximately* (imported, but part of it could not be read: a warning
or note says which) or *left out* (a warning says why). Nothing is dropped without a
warning at its FILE:LINE:COL.

A declaration by type only is ``optional``; ``dynamic_typing`` (or a name alone)
is ``type: any``; one in a loop over a string_array parameter's value, named by the
item, is a ``for_each`` leaf, and one named by the item and more
(``f"gains.{joint}.p"``) a parameter of a mapped group keyed by that list; one under
``if <parameter> == <literal>`` (or ``in``, ``!=``, ``not in``, a bool's truth) has a
``when``, and one in its ``else`` the negated ``when``. A node that declares what its
params file names takes the parameters of the file's section (overrides_in.py).
"""

from __future__ import annotations

import ast
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from genparams.importing import APPROXIMATE, EXACT, LEFT_OUT, Fate, Imported, Outcome, schema_name
from genparams.rclpy_import.features import (
    ALLOW_UNDECLARED,
    AUTOMATIC,
    kept_by_the_node,
    what_it_needs,
)
from genparams.rclpy_import.found import Found, Unit
from genparams.rclpy_import.from_file import entry_values, file_type, undeclared
from genparams.rclpy_import.leaves import DescriptorCopy, default_of, typed_leaf
from genparams.rclpy_import.placing import (
    FOR_EACH,
    ItemPlace,
    SchemaTree,
    item_place,
    key_list,
    written_name,
)
from genparams.rclpy_import.scope import SharePath, run_time_problem, unparsed
from genparams.schema.errors import Location, SchemaProblem


@dataclass(frozen=True)
class Declared:
    """One declaration's fate, and its schema key when imported (a per-item one's is its
    for_each leaf, ``offsets`` or ``*``; a mapped group's parameter's its place,
    ``gains.*.p``)."""

    found: Found | None  # None: a parameter of the params file the node declares as given
    fate: Fate
    key: str | None = None
    given_name: str = ""  # a parameter of the params file left out: its name there


@dataclass(frozen=True)
class RclpyImported(Imported):
    """A node's import: each declaration's fate (the patch rewrites by them)."""

    declared: tuple[Declared, ...] = ()
    # the node declares what its overrides name, and the schema every parameter it reads:
    # the patch takes the option out
    replaces_automatic: bool = False

    @property
    def imported_names(self) -> set[str]:
        """The names of the imported declarations; a per-item one's its schema key."""
        return {d.key for d in self.declared if d.fate != LEFT_OUT and d.key is not None}


def node_schema_name(unit_name: str, file_stem: str) -> str:
    """``KeyTeleopNode`` -> ``key_teleop``; a file's own functions take the file's name."""
    base = unit_name or file_stem
    if unit_name.endswith("Node") and len(unit_name) > len("Node"):
        base = unit_name[: -len("Node")]
    return schema_name(base, "node")


def convert(
    unit: Unit, name: str, overrides: Mapping[str, Any] | None = None, given_by: str = ""
) -> RclpyImported:
    """The schema of ``unit``; ``overrides`` are the parameters its params files give it
    (``given_by`` names them for notes)."""
    return _Converter(unit, name, overrides or {}, given_by).run()


class _Converter:
    def __init__(self, unit: Unit, name: str, overrides: Mapping[str, Any], given_by: str) -> None:
        self.unit = unit
        self.name = name
        self.overrides = overrides
        self.given_by = given_by
        self.from_file: list[str] = []  # parameters only the params file names
        self.file_left_out: list[str] = []  # names of the params file no schema can hold
        self.schema = SchemaTree()
        self.fates: list[tuple[Found, Fate]] = []
        self.keys: dict[Found, str] = {}
        self.warnings: list[SchemaProblem] = []
        self.notes: list[SchemaProblem] = []

    def run(self) -> RclpyImported:
        for found in self.unit.found:
            self.fates.append((found, self.declaration(found)))
        self.keep_groups_whole()
        automatic = any(o.option == AUTOMATIC for o in self.unit.options)
        reads = [r for r in self.unit.reads if automatic and not self.declared(r)]
        for read in reads:
            self.fates.append((read, self.declaration(read)))
        every_read = bool(reads) and all(o != LEFT_OUT for _, o in self.fates[-len(reads) :])
        used = [*self.unit.found, *reads]
        if automatic and self.overrides:
            prefixes = {f.loop_prefix for f in used if f.loop_prefix is not None}
            self.take_from_file(prefixes)
            every_read = every_read or not reads
        read_by_loops = [f.loop_source for f in used if f.loop_source is not None]
        for option in self.unit.options:
            if any(option.at is source for source in read_by_loops):
                continue  # the keys of an open group: its declarations say the rest
            if self.from_file and option.option != ALLOW_UNDECLARED:
                self.note(option.where, "", f"{option.construct}: the schema holds what the "
                          f"params file gives the node ({self.given_by}); a name another "
                          "file brings is not declared")  # fmt: skip
            elif kept_by_the_node(option, every_read):
                self.note(option.where, "", what_it_needs(option, every_read))
            else:
                self.warn(option.where, "", what_it_needs(option))
        for change in self.unit.afterwards:
            self.warn(change.where, "", f"{change.construct}: the schema keeps the declared one")
        if self.unit.files:
            self.note(
                Location(self.unit.file, 1, 1), "",
                f"read {len(self.unit.files)} other file(s) of the node's package, never run: "
                + ", ".join(self.unit.files),
            )  # fmt: skip
        if self.unit.skipped:
            self.note(
                Location(self.unit.file, 1, 1), "",
                "files of the package not read (what they declare is not in the schema): "
                + "; ".join(self.unit.skipped),
            )  # fmt: skip
        data: dict[str, Any] = {"genparams": 1, "name": self.name}
        if self.unit.docstring:
            data["description"] = " ".join(self.unit.docstring.strip().split("\n\n")[0].split())
        data["parameters"] = self.schema.tree
        declared = [Declared(f, o, self.keys.get(f)) for f, o in self.fates]
        declared += [Declared(None, EXACT, n) for n in self.from_file]
        declared += [Declared(None, LEFT_OUT, None, n) for n in self.file_left_out]
        return RclpyImported(
            name=self.name,
            data=data,
            outcomes=tuple(_outcome(d) for d in declared),
            warnings=tuple(self.warnings),
            notes=tuple(self.notes),
            declared=tuple(declared),
            replaces_automatic=every_read,
        )

    def take_from_file(self, open_prefixes: set[str]) -> None:
        """The params file's parameters no declaration or read names: the node declares
        them as the file gives them (automatically_declare_parameters_from_overrides)."""
        where = next(o.where for o in self.unit.options if o.option == AUTOMATIC)
        placed = set(self.schema.first) | set(self.from_file)
        placed |= {n for n in self.overrides if self.schema.per_entry(n)}
        for name, leaf, reason in undeclared(self.overrides, placed, open_prefixes):
            problem = reason if leaf is None else self.schema.name_problem(name)
            if leaf is None or problem is not None:
                self.warn(where, name, f"given by the params file: {problem}: left out")
                self.file_left_out.append(name)
                continue
            self.schema.place(name, leaf)
            self.from_file.append(name)
        if self.from_file:
            self.note(where, "", f"{len(self.from_file)} parameter(s) the node declares as "
                      f"the params file {self.given_by} gives them, with that type and "
                      "default")  # fmt: skip

    def from_params_file(self, found: Found, name: str, place: ItemPlace | None) -> list[Any]:
        """The values the params file gives what ``found`` reads."""
        if place is not None:
            return entry_values(self.overrides, place)
        return [self.overrides[name]] if name in self.overrides else []

    def declared(self, read: Found) -> bool:
        """Whether a read is of a parameter the schema holds already."""
        if read.name.problem is None:
            return read.name.value in self.schema.first
        place = item_place(read)
        return place is not None and place.key in self.schema.first

    def keep_groups_whole(self) -> None:
        """One statement declaring several parameters (a loop over literal items, a
        declare_parameters list whose result is used) stays in the node whole when any
        of them is left out: the others are left out with it, or the node would declare
        them twice."""
        groups: dict[ast.AST, list[int]] = {}
        for index, (found, _) in enumerate(self.fates):
            if found.read is not None:
                continue  # reads stay in the node
            if found.literal_loop is not None:
                groups.setdefault(found.literal_loop, []).append(index)
            elif found.in_list and not (
                isinstance(found.statement, ast.Expr) and found.statement.value is found.call
            ):
                groups.setdefault(found.call, []).append(index)
        for members in groups.values():
            fates = [self.fates[i][1] for i in members]
            if LEFT_OUT not in fates or all(o == LEFT_OUT for o in fates):
                continue
            for index in members:
                found, fate = self.fates[index]
                if fate == LEFT_OUT:
                    continue
                name = self.keys.pop(found)
                self.warn(found.where, name, "declared by the same statement as a parameter "
                          "left out: left out with it")  # fmt: skip
                self.schema.unplace(name)
                del self.schema.first[name]
                self.fates[index] = (found, LEFT_OUT)

    def warn(self, where: Location, key: str, message: str) -> None:
        problem = SchemaProblem(where, key, f"warning: {message}")
        if problem not in self.warnings:
            self.warnings.append(problem)

    def note(self, where: Location, key: str, message: str) -> None:
        problem = SchemaProblem(where, key, f"note: {message}")
        if problem not in self.notes:
            self.notes.append(problem)

    def value_notes(self, found: Found, at: Location, shown: str) -> bool:
        """Notes on a default kept in another form than the node's; False if one is."""
        value = found.value.value
        exact = True
        if isinstance(value, SharePath):
            self.note(at, shown, f"a path in a package's share directory, found at run time: "
                      f"kept as the string default {str(value)!r}, which the node does not "
                      "expand (give the path in the params file)")  # fmt: skip
            exact = False
        if found.value.reads:
            names = ", ".join(repr(n) for n in found.value.reads)
            written = unparsed(found.value_node) if found.value_node else "it"
            self.note(at, shown, f"a default computed from the parameter(s) {names} "
                      f"({written}): imported as {value!r}, worked out from their defaults; "
                      "the node computes it from the values it is given")  # fmt: skip
            exact = False
        if found.via is not None:
            self.note(at, shown, f"declared by {found.via}")
        if found.late is not None:
            self.note(at, shown, f"declared when {found.late} runs, which no file read calls "
                      "(a callback, or a method called from outside): the schema declares it "
                      "with the others")  # fmt: skip
            exact = False
        return exact

    def declaration(self, found: Found) -> Fate:
        """Place one declaration (or read) in the schema; its fate."""
        named = self.named(found)
        if named is None:
            return LEFT_OUT
        name, place = named
        # a per-item parameter's messages name it as written (``offsets.{joint}``)
        shown = written_name(found) if place is not None and not place.tail else name
        checked = self.checked(found, name, place, shown)
        if checked is None:
            return LEFT_OUT
        leaf, when, from_item = checked
        return self.placed(found, name, place, shown, leaf, when, from_item)

    @cached_property
    def item_groups(self) -> frozenset[str]:
        """The keys whose items also name mapped groups of the node's declarations:
        ``*`` for ``f"{goal}.positions"``, ``gains`` for ``f"gains.{joint}.p"``."""
        places = (item_place(f) for f in self.unit.found if f.runtime_loop is not None)
        return frozenset(p.group for p in places if p is not None and p.tail)

    def named(self, found: Found) -> tuple[str, ItemPlace | None] | None:
        """The schema key of a declaration, and where a loop's item sits in it; None (with
        a warning) when it has none."""
        at = found.where
        if found.name.problem is None:
            name = found.name.value
            if isinstance(name, str):
                return name, None
            self.warn(at, "", f"the name {name!r} is not a string: parameter left out")
            return None
        if found.runtime_loop is None:
            what = run_time_problem(found.name.problem, "a name")
            self.warn(at, "", f"{what}: parameter left out")
            return None
        place, reason = self.schema.per_item(found)
        if place is None:
            self.warn(at, written_name(found), f"{reason}: parameter left out")
            return None
        return place.key, place

    def checked(
        self, found: Found, name: str, place: ItemPlace | None, shown: str
    ) -> tuple[dict[str, Any], dict[str, Any] | None, bool] | None:
        """The leaf, the ``when`` and whether the default is computed from the loop's
        item; None (with a warning) when the declaration cannot be one."""
        at = found.where
        if found.nested is not None:
            self.warn(at, shown, f"declared inside {found.nested}: parameter left out")
            return None
        when: dict[str, Any] | None = None
        if found.condition is not None:
            when, reason = self.schema.when(found)
            if when is None:
                self.warn(at, shown, f"declared only under a condition ({found.condition}): "
                          f"{reason}: parameter left out")  # fmt: skip
                return None
        from_item = place is not None and place.tail and _computed_from_item(found)
        if found.value.problem is not None and not from_item:
            what = run_time_problem(found.value.problem, "value")
            self.warn(at, shown, f"{what}: parameter left out")
            return None
        if place is not None and place.tail:
            problem = self.schema.entry_problem(place, key_list(found))
        else:
            problem = self.schema.name_problem(name)
        if problem is not None:
            self.warn(at, shown, f"{problem}: parameter left out")
            return None
        leaf, problem = typed_leaf(found)
        if leaf is None:
            self.warn(at, shown, f"{problem}: parameter left out")
            return None
        if place is not None and not place.tail and place.group in self.item_groups:
            self.warn(at, shown, f"its schema key {place.key!r} also holds a mapped group "
                      "the node declares: a schema key is a parameter or a group, not both: "
                      "parameter left out")  # fmt: skip
            return None
        return leaf, when, bool(from_item)

    def placed(
        self,
        found: Found,
        name: str,
        place: ItemPlace | None,
        shown: str,
        leaf: dict[str, Any],
        when: dict[str, Any] | None,
        from_item: bool,
    ) -> Fate:
        """Put the leaf in the tree, with the notes on how it was read; its fate."""
        at = found.where
        schema_type = leaf["type"]
        exact = True
        if from_item:
            del leaf["default"]
            computed = unparsed(found.value_node) if found.value_node else "the item"
            self.warn(at, shown, f"a default computed from the item ({computed}): "
                      "one schema default serves every entry: imported with none, so each "
                      "entry must be given a value")  # fmt: skip
            exact = False
        given = self.from_params_file(found, name, place) if found.read is not None else []
        kind = file_type(given)
        if kind is not None and leaf["type"] in ("any", kind):
            leaf["type"] = schema_type = kind
            if place is None:
                leaf["default"] = default_of(given[0])
        elif found.read == "":
            self.warn(at, shown, "read with .value, the params file deciding its type: imported "
                      "as type: any (state its type in the schema)")  # fmt: skip
            exact = False
        exact = self.value_notes(found, at, shown) and exact
        if schema_type == "byte_array":
            self.note(
                at, shown, "an empty list: rclpy declares a byte_array, and so does the schema"
            )
        copy = DescriptorCopy()
        exact = copy.descriptor(found, schema_type, leaf) and exact
        for lost in copy.lost:
            self.warn(at, shown, lost)
        if found.ignore_override.problem is not None or found.ignore_override.value:
            self.warn(at, shown, "ignore_override: genparams always applies overrides: imported "
                      "without it")  # fmt: skip
            exact = False
        key = found.loop_parameter
        if place is not None and not place.open and key is not None:
            if not place.tail:
                leaf[FOR_EACH] = key
            self.note(
                self.schema.first[key].where,
                key,
                f"its items name {place.names()}: genparams checks that each can "
                "name one, and says so in its additional_constraints",
            )
        if when is not None:
            leaf["when"] = when
        if place is not None and place.tail:
            self.schema.place_entry(place, key_list(found), leaf)
        else:
            self.schema.place(name, leaf)
        self.schema.first[name] = found
        self.keys[found] = name
        return EXACT if exact else APPROXIMATE


def _computed_from_item(found: Found) -> bool:
    """A value computed from the loop's item that a sample item gives a value of."""
    return found.item_value is not None and found.item_value.problem is None


def _outcome(declared: Declared) -> Outcome:
    """A declaration's fate, as the importers report it: by the name the node gives it."""
    found, key = declared.found, declared.key or ""
    if found is None:
        return Outcome(key or declared.given_name, declared.fate, key)
    name = found.name.value if isinstance(found.name.value, str) else written_name(found)
    return Outcome(name or key or unparsed(found.at), declared.fate, key)
