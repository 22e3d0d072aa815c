"""Build the frozen model from a checked document, checking what JSON Schema cannot.

Names (ROS tokens, Python attributes, collisions with the generated API),
defaults against type, range, choices and validators, validators against the
parameter type. Every problem is collected; none stops the walk.
"""

from __future__ import annotations

import os
from collections.abc import Collection, Iterable, Iterator
from dataclasses import replace
from typing import Any

from genparams.runtime.core import naming
from genparams.runtime.core.conditions import schema_condition
from genparams.runtime.core.types import TYPES, ValueTypeError
from genparams.runtime.core.validators import Custom
from genparams.schema.errors import SchemaError, SchemaProblem
from genparams.schema.leaf_checks import LeafChecks
from genparams.schema.loader import LoadedDocument, Path, dotted
from genparams.schema.model import Group, OpenNamespace, Parameter, Schema, with_entry_keys
from genparams.schema.references import check_aliases, check_conditions, check_maps
from genparams.schema.rule_builder import build_rules
from genparams.schema.shape import is_parameter

FOR_EACH = "for_each"


def build_schema(document: LoadedDocument) -> Schema:
    builder = _ModelBuilder(document)
    schema = builder.schema()
    if builder.problems:
        raise SchemaError(builder.problems)
    return schema


def model_problems(document: LoadedDocument, known: Iterable[SchemaProblem]) -> list[SchemaProblem]:
    """The model's own problems in the parts of a document the schema check passed.

    Lets one run report every problem of a file, not the JSON Schema ones first
    and the rest after they are fixed. Leaves with a known problem are skipped.
    """
    data = document.data
    if not (
        isinstance(data, dict)
        and isinstance(data.get("name"), str)
        and isinstance(data.get("parameters"), dict)
    ):
        return []
    builder = _ModelBuilder(document, skip={problem.key for problem in known})
    builder.schema()
    return builder.problems


class _ModelBuilder:
    def __init__(self, document: LoadedDocument, skip: Collection[str] = ()) -> None:
        self.document = document
        self.problems: list[SchemaProblem] = []
        self.skip = skip  # dotted keys with problems already known
        # Class names already used, and every key of the tree: a group class named like an
        # attribute would be hidden by it inside the class bodies that mention it.
        self.class_names: set[str] = set(_keys(document.data.get("parameters")))
        self.leaf_paths: dict[str, Path] = {}  # parameter ROS name -> its document path
        self.mapped: list[tuple[Group, Path]] = []
        self.aliases: list[tuple[str, Path, Parameter]] = []  # (alias, where, its parameter)
        self.conditional: list[tuple[Parameter, Path]] = []  # parameters with when:
        self.unbuilt: list[tuple[str, ...]] = []  # paths of names left out for known problems
        self.leaf_checks = LeafChecks(self.problem)

    def problem(self, path: Path, message: str, *, at_key: bool = False) -> None:
        where = self.document.key_location(path) if at_key else self.document.value_location(path)
        self.problems.append(SchemaProblem(where, dotted(path), message))

    def schema(self) -> Schema:
        data = self.document.data
        name = data["name"]
        class_name = naming.class_name(name)
        self.class_names.add(class_name)
        root = self.group(data["parameters"], ("parameters",), (), "", class_name)
        check_maps(root, self.mapped, self.leaf_paths, self.problem, self.is_unbuilt)
        check_aliases(root, self.aliases, self.problem)
        check_conditions(root, self.conditional, self.problem, self.is_unbuilt)
        rules, rule_problems = build_rules(self.document, root.walk_parameters(), self.is_unbuilt)
        self.problems.extend(rule_problems)
        root = with_entry_keys(root)
        return Schema(
            name=name,
            description=data.get("description", ""),
            source_name=os.path.basename(self.document.file),
            class_name=class_name,
            module_name=naming.module_name(name),
            root=root,
            rules=rules,
        )

    def group(
        self,
        mapping: dict[str, Any],
        doc_path: Path,
        path: tuple[str, ...],
        attribute: str,
        class_name: str,
        *,
        in_place: bool = False,
    ) -> Group:
        parameters: list[Parameter] = []
        groups: list[Group] = []
        open_namespaces: list[OpenNamespace] = []
        attributes: dict[str, str] = {}
        mapped_over = mapping.get(FOR_EACH, "")
        if mapped_over and not path and not in_place:
            self.problem(
                (*doc_path, FOR_EACH),
                "the top level cannot be mapped: put for_each in a namespace",
                at_key=True,
            )
            mapped_over = ""
        if mapped_over == naming.FROM_OVERRIDES:
            mapped_over = self.open_group(doc_path, path, in_place=in_place)
        # Below a mapped group, names hold the entry key's place.
        member_path = (*path, naming.ENTRY_KEY) if mapped_over else path
        for key, value in mapping.items():
            if key == FOR_EACH:
                continue
            key_path = (*doc_path, key)
            if key == naming.ENTRY_KEY:
                entries = self.entries_in_place(value, key_path, member_path)
                if entries is not None:
                    groups.append(entries)
                continue
            if not self.check_name(key, value, key_path, attributes, top_level=not member_path):
                continue
            child_path = (*member_path, key)
            if self.skipped(key_path, whole_tree=is_parameter(value)):
                self.unbuilt.append(child_path)
                continue
            child_attribute = naming.attribute_name(key, top_level=not member_path)
            if is_open_namespace(value):
                open_namespaces.append(
                    OpenNamespace(
                        ros_name=".".join(child_path),
                        path=child_path,
                        description=value.get("description", ""),
                        location=self.document.key_location(key_path),
                    )
                )
            elif is_parameter(value) and FOR_EACH in value:
                groups.append(self.per_item(value, key_path, child_path, child_attribute))
            elif is_parameter(value):
                parameters.append(self.parameter(value, key_path, child_path, child_attribute))
            elif isinstance(value, dict):
                child_class = self.group_class_name(child_path)
                groups.append(self.group(value, key_path, child_path, child_attribute, child_class))
        if all(key == FOR_EACH for key in mapping):
            what = "namespace" if path else "schema"
            self.problem(doc_path, f"empty {what}: give it parameters", at_key=True)
        group = Group(
            ros_name=".".join(path),
            path=path,
            attribute=attribute,
            class_name=class_name,
            parameters=tuple(parameters),
            groups=tuple(groups),
            mapped_over=mapped_over,
            open_namespaces=tuple(open_namespaces),
            in_place=in_place,
        )
        if mapped_over:
            self.mapped.append((group, doc_path))
        return group

    def open_group(self, doc_path: Path, path: tuple[str, ...], *, in_place: bool) -> str:
        """``for_each: overrides``: entries keyed by the names the overrides hold below the
        namespace. Only a named namespace outside every mapped group can be one."""
        where = (*doc_path, FOR_EACH)
        if in_place:
            message = (
                'for_each: overrides keys a namespace, not "*": its entries need a name of '
                "their own to be found under"
            )
        elif naming.ENTRY_KEY in path:
            message = (
                "for_each: overrides is not supported inside a mapped group: the keys found "
                "under one entry would differ from another's"
            )
        else:
            return naming.OVERRIDE_KEYS
        self.problem(where, message, at_key=True)
        return ""

    def per_item(
        self,
        leaf: dict[str, Any],
        doc_path: Path,
        path: tuple[str, ...],
        attribute: str,
        *,
        in_place: bool = False,
    ) -> Group:
        """A leaf with ``for_each``: one parameter per item, named by the item itself."""
        item = self.parameter(leaf, doc_path, (*path, naming.ENTRY_KEY), naming.ENTRY_KEY)
        item = replace(item, per_item_of=leaf[FOR_EACH])
        group = Group(
            ros_name=".".join(path),
            path=path,
            attribute=attribute,
            class_name="",
            parameters=(item,),
            groups=(),
            mapped_over=leaf[FOR_EACH],
            in_place=in_place,
            per_item=True,
        )
        self.mapped.append((group, doc_path))
        return group

    def entries_in_place(self, value: Any, key_path: Path, path: tuple[str, ...]) -> Group | None:
        """A ``"*"`` key: a mapped group whose entries sit in this namespace, by key, or,
        with ``type:``, one parameter per item, each named by its item."""
        if not (isinstance(value, dict) and FOR_EACH in value):
            self.problem(
                key_path,
                '"*" stands for the entries of a map: give it for_each, the string_array '
                "parameter whose items key them",
                at_key=True,
            )
            return None
        if self.skipped(key_path, whole_tree=is_parameter(value)):
            self.unbuilt.append((*path, naming.ENTRY_KEY))
            return None
        if is_parameter(value):
            return self.per_item(value, key_path, path, "", in_place=True)
        words = "".join(naming.pascal_case(p) for p in path if p != naming.ENTRY_KEY)
        depth = path.count(naming.ENTRY_KEY) + 1  # "Entry" once per map level
        entry_class = self.unique_class_name(f"{words}{'Entry' * depth}Group")
        return self.group(value, key_path, path, "", entry_class, in_place=True)

    def is_unbuilt(self, name: str) -> bool:
        """Whether ``name`` (a ROS name or its attribute spelling) lies in a part of the
        schema left out for a problem of its own: a reference to it is no new problem."""
        parts = tuple(name.split("."))
        for path in self.unbuilt:
            spelled = naming.attribute_parts(".".join(path))
            if parts[: len(path)] in (path, spelled):
                return True
        return False

    def skipped(self, path: Path, *, whole_tree: bool) -> bool:
        """Whether a known problem sits at ``path`` (or, for a leaf, anywhere inside it)."""
        key = dotted(path)
        if key in self.skip or f"{key}.{FOR_EACH}" in self.skip:
            return True
        return whole_tree and any(k.startswith((f"{key}.", f"{key}[")) for k in self.skip)

    def group_class_name(self, path: tuple[str, ...]) -> str:
        words = (naming.pascal_case(part) for part in path if part != naming.ENTRY_KEY)
        return self.unique_class_name("".join(words) + "Group")

    def unique_class_name(self, base: str) -> str:
        candidate, number = base, 2
        while candidate in self.class_names:
            candidate, number = f"{base}{number}", number + 1
        self.class_names.add(candidate)
        return candidate

    def check_name(
        self, key: str, value: Any, key_path: Path, seen: dict[str, str], *, top_level: bool
    ) -> bool:
        if not naming.is_ros_token(key):
            self.problem(
                key_path,
                f"invalid name {key!r}: use {naming.NAME_RULE}",
                at_key=True,
            )
            return False
        if top_level and key in naming.NODE_PARAMETERS and not _adopts(value):
            self.problem(
                key_path,
                f"every node declares {key!r} already: leave it out, or give it adopt: true "
                "to take over checking it",
                at_key=True,
            )
            return False
        attribute = naming.attribute_name(key, top_level=top_level)
        if attribute in seen:
            self.problem(
                key_path,
                f"name {key!r} becomes Python attribute {attribute!r}, which "
                f"{seen[attribute]!r} already uses: two names of one namespace need two "
                "attributes ('-' and '/' become '_', a keyword takes a trailing '_')",
                at_key=True,
            )
            return False
        seen[attribute] = key
        return True

    def parameter(
        self, leaf: dict[str, Any], doc_path: Path, path: tuple[str, ...], attribute: str
    ) -> Parameter:
        param_type = TYPES[leaf["type"]]
        optional = leaf.get("optional", False)
        required = "default" not in leaf and not optional
        default = None
        default_ok = "default" in leaf
        if optional and "default" in leaf:
            self.problem(
                (*doc_path, "optional"),
                "an optional parameter has no default (it is not set until an override or a "
                "set gives it a value): remove default, or optional",
                at_key=True,
            )
            default_ok = False
        elif default_ok:
            try:
                default = param_type.coerce_default(leaf["default"])
            except ValueTypeError as exc:
                self.problem((*doc_path, "default"), f"default does not match type: {exc}")
                default_ok = False

        value_range = self.leaf_checks.range(leaf, doc_path, param_type)
        choices = self.leaf_checks.choices(leaf, doc_path, param_type)
        validators = self.leaf_checks.validators(leaf, doc_path, param_type)

        parameter = Parameter(
            ros_name=".".join(path),
            path=path,
            attribute=attribute,
            type=param_type,
            default=default,
            required=required,
            description=leaf.get("description", ""),
            read_only=leaf.get("read_only", False),
            unit=leaf.get("unit", ""),
            range=value_range,
            choices=choices,
            validators=validators,
            additional_constraints=leaf.get("additional_constraints", ""),
            deprecated=leaf.get("deprecated", ""),
            aliases=tuple(leaf.get("aliases", ())),
            location=self.document.key_location(doc_path),
            configure_only=leaf.get("configure_only", False),
            adopt=leaf.get("adopt", False),
            optional=optional,
            when=schema_condition(leaf.get("when", {})),
        )
        # The runtime's own checks, compiled once: they judge the default here, and the
        # model keeps them to word each constraint in every output.
        kinds = ["range"] * (value_range is not None) + ["choices"] * (choices is not None)
        kinds += ["validators"] * len(validators)
        checks = [
            (key, check)
            for key, check in zip(kinds, parameter.compiled.checks, strict=True)
            if not isinstance(check, Custom)  # user code runs on a node, not in the generator
        ]
        if default_ok:
            for key, check in checks:
                reason = check(default)
                if reason is not None:
                    self.problem((*doc_path, "default"), f"default violates {key}: {reason}")
        self.leaf_checks.check_satisfiable(doc_path, param_type, checks)
        if parameter.adopt and naming.ENTRY_KEY in path:
            self.problem(
                (*doc_path, "adopt"),
                "adopt is not supported inside a mapped group: entries come and go with "
                "their keys, which other code does not follow",
                at_key=True,
            )
        if optional:
            self.check_optional(parameter, doc_path)
        if parameter.when:
            self.conditional.append((parameter, doc_path))
        self.leaf_paths[parameter.ros_name] = doc_path
        for index, alias in enumerate(parameter.aliases):
            self.aliases.append((alias, (*doc_path, "aliases", index), parameter))
        return parameter

    def check_optional(self, parameter: Parameter, doc_path: Path) -> None:
        """What an optional parameter cannot be combined with."""
        if parameter.aliases:
            self.problem(
                (*doc_path, "optional"),
                "an optional parameter cannot have aliases: an old name would need a value "
                "to mirror",
                at_key=True,
            )


def _adopts(value: Any) -> bool:
    return isinstance(value, dict) and value.get("adopt") is True


def is_open_namespace(value: Any) -> bool:
    """``{open: true}``: a namespace other code fills (``open`` with a mapping is a name)."""
    return isinstance(value, dict) and value.get("open") is True and not is_parameter(value)


def _keys(tree: Any) -> Iterator[str]:
    if isinstance(tree, dict):
        for key, value in tree.items():
            yield str(key)
            yield from _keys(value)
