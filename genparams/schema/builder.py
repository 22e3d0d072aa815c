"""Build the frozen model from a checked document, checking what JSON Schema cannot.

Names (ROS tokens, Python attributes, collisions with the generated API),
defaults against type, range, choices and validators, validators against the
parameter type. Every problem is collected; none stops the walk.
"""

from __future__ import annotations

import math
import os
from collections.abc import Collection, Iterable, Iterator
from typing import Any

from genparams.runtime import naming
from genparams.runtime.types import INT64_MAX, INT64_MIN, TYPES, ParamType, ValueTypeError
from genparams.runtime.validators import (
    KINDS,
    OneOf,
    RosRange,
    SubsetOf,
    Validator,
    ValidatorArgumentError,
    build_validator,
)
from genparams.schema.errors import SchemaError, SchemaProblem
from genparams.schema.loader import LoadedDocument, Path, dotted
from genparams.schema.model import Group, Parameter, RangeSpec, Schema, ValidatorSpec
from genparams.schema.references import check_aliases, check_maps
from genparams.schema.rule_builder import build_rules
from genparams.schema.schema_check import did_you_mean

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


def _frozen(value: Any) -> Any:
    """Lists become tuples, so the model is hashable and immutable."""
    if isinstance(value, list):
        return tuple(_frozen(v) for v in value)
    if isinstance(value, dict):
        return {k: _frozen(v) for k, v in value.items()}
    return value


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
        self.unbuilt: list[tuple[str, ...]] = []  # paths of names left out for known problems

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
        rules, rule_problems = build_rules(self.document, root.walk_parameters(), self.is_unbuilt)
        self.problems.extend(rule_problems)
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
    ) -> Group:
        parameters: list[Parameter] = []
        groups: list[Group] = []
        attributes: dict[str, str] = {}
        mapped_over = mapping.get(FOR_EACH, "")
        if mapped_over and not path:
            self.problem(
                (*doc_path, FOR_EACH),
                "the top level cannot be mapped: put for_each in a namespace",
                at_key=True,
            )
            mapped_over = ""
        # Below a mapped group, names hold the entry key's place.
        member_path = (*path, naming.ENTRY_KEY) if mapped_over else path
        for key, value in mapping.items():
            if key == FOR_EACH:
                continue
            key_path = (*doc_path, key)
            if not self.check_name(key, key_path, attributes, top_level=not path):
                continue
            child_path = (*member_path, key)
            if self.skipped(key_path, whole_tree=isinstance(value, dict) and "type" in value):
                self.unbuilt.append(child_path)
                continue
            child_attribute = naming.attribute_name(key)
            if isinstance(value, dict) and "type" in value:
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
        )
        if mapped_over:
            self.mapped.append((group, doc_path))
        return group

    def is_unbuilt(self, name: str) -> bool:
        """Whether ``name`` (a ROS name or its attribute spelling) lies in a part of the
        schema left out for a problem of its own: a reference to it is no new problem."""
        parts = tuple(name.split("."))
        for path in self.unbuilt:
            spelled = tuple(map(naming.attribute_name, path))
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
        base = "".join(words) + "Group"
        candidate, number = base, 2
        while candidate in self.class_names:
            candidate, number = f"{base}{number}", number + 1
        self.class_names.add(candidate)
        return candidate

    def check_name(
        self, key: str, key_path: Path, seen: dict[str, str], *, top_level: bool
    ) -> bool:
        if not naming.is_ros_token(key):
            self.problem(
                key_path,
                f"invalid name {key!r}: "
                "use letters, digits and underscores, starting with a letter",
                at_key=True,
            )
            return False
        if top_level and key in naming.RESERVED_TOP_LEVEL:
            self.problem(
                key_path,
                f"name {key!r} is reserved by the generated class's API; "
                "rename it or move it into a namespace",
                at_key=True,
            )
            return False
        if key in naming.SHADOWING:
            self.problem(
                key_path,
                f"name {key!r} would hide the Python name {key} that the generated classes "
                "use; rename it",
                at_key=True,
            )
            return False
        attribute = naming.attribute_name(key)
        if attribute in seen:
            self.problem(
                key_path,
                f"name {key!r} becomes Python attribute {attribute!r}, "
                f"which {seen[attribute]!r} already uses",
                at_key=True,
            )
            return False
        seen[attribute] = key
        return True

    def parameter(
        self, leaf: dict[str, Any], doc_path: Path, path: tuple[str, ...], attribute: str
    ) -> Parameter:
        param_type = TYPES[leaf["type"]]
        required = "default" not in leaf
        default = None
        default_ok = not required
        if not required:
            try:
                default = param_type.coerce_default(leaf["default"])
            except ValueTypeError as exc:
                self.problem((*doc_path, "default"), f"default does not match type: {exc}")
                default_ok = False

        value_range = self.range(leaf, doc_path, param_type)
        choices = self.choices(leaf, doc_path, param_type)
        validators = self.validators(leaf, doc_path, param_type)

        checks: list[tuple[str, Validator]] = []
        if value_range is not None:
            checks.append(("range", self.range_validator(value_range, param_type)))
        if choices is not None:
            checks.append(("choices", SubsetOf(choices) if param_type.is_array else OneOf(choices)))
        checks.extend(
            ("validators", build_validator(spec.rule, spec.argument, param_type.name))
            for spec in validators
            if spec.rule != "custom"
        )
        if default_ok:
            for key, check in checks:
                reason = check(default)
                if reason is not None:
                    self.problem((*doc_path, "default"), f"default violates {key}: {reason}")
        self.check_satisfiable(doc_path, param_type, checks)
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
        )
        self.leaf_paths[parameter.ros_name] = doc_path
        for index, alias in enumerate(parameter.aliases):
            self.aliases.append((alias, (*doc_path, "aliases", index), parameter))
        return parameter

    @staticmethod
    def range_validator(value_range: RangeSpec, param_type: ParamType) -> RosRange:
        return RosRange(
            value_range.min,
            value_range.max,
            value_range.step,
            integer=param_type.scalar_kind == "int",
            each=param_type.is_array,
        )

    def range(
        self, leaf: dict[str, Any], doc_path: Path, param_type: ParamType
    ) -> RangeSpec | None:
        if "range" not in leaf:
            return None
        range_path = (*doc_path, "range")
        if not param_type.is_numeric:
            self.problem(
                range_path,
                f"range applies to int, double, int_array and double_array, not {param_type.name}",
                at_key=True,
            )
            return None
        raw = leaf["range"]
        values: dict[str, int | float] = {}
        ok = True
        for key in ("min", "max", "step"):
            value = raw.get(key, 0)
            if param_type.scalar_kind == "int":
                if isinstance(value, float) and not value.is_integer():
                    self.problem(
                        (*range_path, key), f"{key} must be an integer for {param_type.name}"
                    )
                    ok = False
                    continue
                value = int(value)
                if not INT64_MIN <= value <= INT64_MAX:
                    self.problem((*range_path, key), f"{key} {value} does not fit in int64")
                    ok = False
                    continue
            else:
                try:
                    value = float(value)
                except OverflowError:
                    self.problem((*range_path, key), f"{key} is too large for a double")
                    ok = False
                    continue
                if math.isnan(value) or (key == "step" and math.isinf(value)):
                    self.problem((*range_path, key), f"{key} must be a finite number")
                    ok = False
                    continue
            values[key] = value
        if not ok:
            return None
        if values["min"] > values["max"]:
            self.problem(
                (*range_path, "min"),
                f"min {values['min']!r} is greater than max {values['max']!r}",
            )
            return None
        step = values["step"]
        if step and not math.isfinite((values["max"] - values["min"]) / step):
            # ROS computes (value - min) / step, which must stay a finite double.
            self.problem(
                (*range_path, "step"),
                f"step {step!r} needs finite min and max and (max - min) / step below 1e308",
            )
            return None
        return RangeSpec(values["min"], values["max"], step)

    def choices(
        self, leaf: dict[str, Any], doc_path: Path, param_type: ParamType
    ) -> tuple[Any, ...] | None:
        if "choices" not in leaf:
            return None
        path = (*doc_path, "choices")
        if (
            param_type.scalar_kind not in ("int", "double", "string")
            or param_type.name == "byte_array"
        ):
            self.problem(path, f"choices do not apply to {param_type.name}", at_key=True)
            return None
        element = TYPES[param_type.scalar_kind]
        out = []
        for index, choice in enumerate(leaf["choices"]):
            try:
                out.append(element.coerce_default(choice))
            except ValueTypeError as exc:
                self.problem((*path, index), f"choice does not match type: {exc}")
        if len(set(out)) != len(out):
            self.problem(path, "choices repeat a value")
        return tuple(out)

    def validators(
        self, leaf: dict[str, Any], doc_path: Path, param_type: ParamType
    ) -> tuple[ValidatorSpec, ...]:
        specs = []
        for index, entry in enumerate(leaf.get("validators", [])):
            path = (*doc_path, "validators", index)
            if isinstance(entry, str):
                rule, argument, bare = entry, None, True
            else:
                ((rule, argument),) = entry.items()
                bare = False
            kind = KINDS.get(rule)
            if kind is None:
                self.problem(path, f"unknown validator {rule!r}{did_you_mean(rule, KINDS)}")
                continue
            if param_type.name not in kind.applies_to:
                applies = ", ".join(sorted(kind.applies_to))
                self.problem(
                    path, f"validator {rule!r} does not apply to {param_type.name} (only {applies})"
                )
                continue
            if kind.takes_argument and bare:
                self.problem(path, f"validator {rule!r} needs an argument: {{{rule}: ...}}")
                continue
            if not kind.takes_argument and not bare and argument not in (None, True):
                self.problem(path, f"validator {rule!r} takes no argument: write just {rule}")
                continue
            argument = _frozen(argument) if kind.takes_argument else None
            if rule in ("one_of", "subset_of") and isinstance(argument, tuple):
                argument = self.typed_choices(path, argument, param_type)
            try:
                validator = build_validator(rule, argument, param_type.name)
            except ValidatorArgumentError as exc:
                self.problem(path, str(exc))
                continue
            specs.append(ValidatorSpec(rule, argument, validator.describe()))
        return tuple(specs)

    def typed_choices(
        self, path: Path, argument: tuple[Any, ...], param_type: ParamType
    ) -> tuple[Any, ...]:
        element = TYPES[param_type.scalar_kind]
        out = []
        for index, choice in enumerate(argument):
            try:
                out.append(element.coerce_default(choice))
            except ValueTypeError as exc:
                self.problem((*path, index), f"choice does not match type: {exc}")
        return tuple(out)

    def check_satisfiable(
        self, doc_path: Path, param_type: ParamType, checks: list[tuple[str, Validator]]
    ) -> None:
        """Numeric limits that leave no valid value are a schema error, not a runtime surprise."""
        if param_type.is_array or not param_type.is_numeric:
            return
        low: float = INT64_MIN if param_type.scalar_kind == "int" else -math.inf
        high: float = INT64_MAX if param_type.scalar_kind == "int" else math.inf
        low_open = high_open = False
        for _key, check in checks:
            bounds = _limits(check)
            if bounds is None:
                continue
            lo, lo_open, hi, hi_open = bounds
            if lo > low or (lo == low and lo_open):
                low, low_open = lo, lo_open
            if hi < high or (hi == high and hi_open):
                high, high_open = hi, hi_open
        if low > high or (low == high and (low_open or high_open)):
            self.problem(
                doc_path,
                "range and validators contradict each other: no value satisfies all of them",
                at_key=True,
            )


def _keys(tree: Any) -> Iterator[str]:
    if isinstance(tree, dict):
        for key, value in tree.items():
            yield str(key)
            yield from _keys(value)


def _limits(check: Validator) -> tuple[float, bool, float, bool] | None:
    from genparams.runtime.validators import Bounds, Compare

    if isinstance(check, RosRange) or (isinstance(check, Bounds) and not check.each):
        return (check.low, False, check.high, False)
    if isinstance(check, Compare):
        return {
            "gt": (check.limit, True, math.inf, False),
            "ge": (check.limit, False, math.inf, False),
            "lt": (-math.inf, False, check.limit, True),
            "le": (-math.inf, False, check.limit, False),
        }[check.rule]
    return None
