"""A generate_parameter_library (GPL) YAML file -> a genparams schema, as plain data.

GPL's file holds one top-level key (the C++ namespace) over a tree of
parameters (mappings with ``type:``) and namespaces. Every construct maps to
its genparams form; whatever cannot be mapped becomes a warning naming its
FILE:LINE:COL, and is left out of the result, never silently dropped.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

from genparams.errors import GenparamsError
from genparams.gpl.validation import (
    Translated,
    arguments,
    combination_refused,
    descriptor_range,
    element_bounds,
    translate,
)
from genparams.importing import EXACT, LEFT_OUT, Imported, Outcome, schema_name
from genparams.runtime.core.types import TYPES, ValueTypeError
from genparams.runtime.core.validator_kinds import KINDS, ValidatorArgumentError, checked_validator
from genparams.schema.errors import SchemaProblem
from genparams.schema.loader import LoadedDocument, Path, dotted
from genparams.schema.shape import is_parameter

MAP_PREFIX = "__map_"
OPEN_TYPE = "none"  # GPL's type of a namespace whose parameters other code declares
_FIXED = re.compile(r"(?P<base>[a-z_]+?)_fixed_(?P<size>\d+)")
_LEAF_KEYS = ("type", "default_value", "description", "read_only", "validation",
              "additional_constraints")  # fmt: skip


class GplError(GenparamsError):
    """The file is not a GPL parameter file at all."""


@dataclass(frozen=True)
class CustomUse:
    """A custom validator the user writes in Python, and where the schema uses it."""

    function: str
    gpl_name: str
    used_by: tuple[tuple[str, tuple[Any, ...]], ...] = ()  # (parameter, args)

    def also_by(self, parameter: str, args: tuple[Any, ...]) -> CustomUse:
        return replace(self, used_by=(*self.used_by, (parameter, args)))


@dataclass(frozen=True)
class GplImported(Imported):
    """A GPL file's import: errors are what GPL itself refuses; ``customs`` the custom
    validators to write in Python, by function name."""

    customs: Mapping[str, CustomUse] = field(default_factory=dict)


def import_gpl(
    document: LoadedDocument, checks_module: str | None = None, adopt: Collection[str] = ()
) -> GplImported:
    """Convert one GPL file. ``adopt``: dotted names other code of the node declares first."""
    data = document.data
    if not isinstance(data, dict) or len(data) != 1:
        raise GplError("a GPL file holds exactly one top-level key (the parameters' namespace)")
    ((top, tree),) = data.items()
    if not isinstance(tree, dict):
        raise GplError(f"{top!r} does not hold parameters")
    name = schema_name(str(top), "gpl")
    importer = _Importer(document, checks_module or f"{name}_checks", adopt)
    parameters = importer.namespace(tree, (top,), (), [tree])
    parameters = {**importer.added, **parameters}
    importer.empty_key_lists(parameters, top)
    for name in sorted(importer.adopt):
        importer.warn((top,), f"--adopt {name}: the file declares no such parameter")
    return GplImported(
        name=name,
        data={"genparams": 1, "name": name, "parameters": parameters},
        outcomes=tuple(importer.outcomes),
        warnings=tuple(importer.warnings),
        notes=tuple(importer.notes),
        errors=tuple(importer.errors),
        customs=importer.customs,
    )


class _Importer:
    def __init__(
        self, document: LoadedDocument, checks_module: str, adopt: Collection[str]
    ) -> None:
        self.document = document
        self.adopt = set(adopt)
        self.checks_module = checks_module
        self.warnings: list[SchemaProblem] = []
        self.errors: list[SchemaProblem] = []
        self.notes: list[SchemaProblem] = []
        self.customs: dict[str, CustomUse] = {}
        self.outcomes: list[Outcome] = []  # each GPL parameter's, open namespaces aside
        self.added: dict[str, dict[str, Any]] = {}  # key lists the GPL file lacks
        # the dotted name of each parameter keying maps: whether one of its maps holds a
        # parameter without a default
        self.key_lists: dict[str, bool] = {}

    def warn(self, doc_path: Path, message: str) -> None:
        where = self.document.key_location(doc_path)
        self.warnings.append(SchemaProblem(where, dotted(doc_path), f"warning: {message}"))

    def note(self, doc_path: Path, message: str) -> None:
        where = self.document.key_location(doc_path)
        self.notes.append(SchemaProblem(where, dotted(doc_path), f"note: {message}"))

    def namespace(
        self,
        tree: dict[str, Any],
        doc_path: Path,
        ros_path: tuple[str, ...],
        scopes: list[dict[str, Any]],
    ) -> dict[str, Any]:
        """Convert one GPL namespace; ``scopes`` are the enclosing GPL mappings, outermost first."""
        out: dict[str, Any] = {}
        maps = [key for key in tree if key.startswith(MAP_PREFIX)]
        plain = [key for key in tree if not key.startswith(MAP_PREFIX)]
        for key in plain:
            value = tree[key]
            key_path = (*doc_path, key)
            if is_parameter(value):  # GPL too: a mapping whose first value is one is a namespace
                leaf = self.leaf(value, key_path, (*ros_path, key))
                if leaf is not None:
                    out[key] = leaf
            elif isinstance(value, dict):
                out[key] = self.namespace(value, key_path, (*ros_path, key), [*scopes, value])
            else:
                self.warn(key_path, "neither a parameter (no type:) nor a namespace: left out")
        for index, key in enumerate(maps):
            if index:
                self.all_lost(tree[key], (*ros_path, "*"))
                self.warn(
                    (*doc_path, key),
                    "a second map in one namespace: ROS names could not tell the two maps' "
                    "entries apart; its parameters are left out",
                )
                continue
            entry = self.mapped(tree[key], (*doc_path, key), ros_path, scopes)
            if entry is None:
                continue
            if not plain and ros_path and not self.in_entry(ros_path):
                # GPL's common shape, a namespace that is nothing but a map: genparams'
                # mapped group (``gains: {for_each: joints, ...}``).
                out.update(entry)
            else:  # beside other names, at the top level, or directly in another map
                out["*"] = entry
        return out

    @staticmethod
    def in_entry(ros_path: tuple[str, ...]) -> bool:
        """Whether the namespace at ``ros_path`` is itself one entry of a map."""
        return bool(ros_path) and ros_path[-1] == "*"

    def mapped(
        self,
        tree: Any,
        doc_path: Path,
        ros_path: tuple[str, ...],
        scopes: list[dict[str, Any]],
    ) -> dict[str, Any] | None:
        key = str(doc_path[-1])
        if not isinstance(tree, dict):
            self.warn(doc_path, "a map must hold parameters: left out")
            return None
        wanted = key[len(MAP_PREFIX) :]
        key_name = self.key_parameter(wanted, ros_path, scopes)
        if key_name is None and wanted not in scopes[0]:
            # GPL's generated code reads the keys from a parameter of that name; a file
            # naming none could not build. The import declares it, empty by default.
            self.added[wanted] = {
                "type": "string_array",
                "default": [],
                "description": f"Keys of the map {key} (the GPL file declares no {wanted}).",
            }
            self.note(doc_path, f"no parameter {wanted!r} keys this map: added it, a string_array")
            key_name = wanted
        if key_name is None:
            self.all_lost(tree, (*ros_path, "*"))
            self.warn(
                doc_path,
                f"{wanted!r} is not a string_array parameter in this namespace or an enclosing "
                "one: this map's parameters are left out",
            )
            return None
        inner = self.namespace(tree, doc_path, (*ros_path, "*"), [*scopes, tree])
        self.key_lists[key_name] = self.key_lists.get(key_name, False) or _unset_inside(inner)
        return {"for_each": key_name, **inner}

    def empty_key_lists(self, parameters: dict[str, Any], top: str) -> None:
        """GPL users write a key list's "no keys" as ``[""]``: genparams writes ``[]``.

        GPL itself declares the map's parameters for the key ``""`` (``.first``); when one
        has no default, its listener refuses every section that leaves the list unset. The
        list is then required, so genparams refuses the same sections."""
        for name, unset_inside in sorted(self.key_lists.items()):
            leaf: Any = parameters
            for part in name.split("."):
                leaf = leaf.get(part) if isinstance(leaf, dict) else None
            if not isinstance(leaf, dict) or leaf.get("default") != [""]:
                continue
            where = (top, *name.split("."), "default_value")
            if unset_inside:
                del leaf["default"]
                self.note(
                    where,
                    'a key list of [""] over a map whose parameters are not all set by '
                    'default: GPL declares them for the key "" and refuses to start with '
                    "them unset; imported as a required parameter",
                )
            else:
                leaf["default"] = []
                self.note(where, 'a key list of [""] means no keys: imported as []')

    def key_parameter(
        self, name: str, ros_path: tuple[str, ...], scopes: list[dict[str, Any]]
    ) -> str | None:
        """The dotted name of the key list, looked up from the innermost namespace outward."""
        fixed = [part for part in ros_path]
        for depth in range(len(scopes) - 1, -1, -1):
            leaf = scopes[depth].get(name)
            prefix = fixed[:depth]
            if isinstance(leaf, dict) and leaf.get("type") == "string_array" and "*" not in prefix:
                return ".".join([*prefix, name])
        return None

    def all_lost(self, tree: dict[str, Any], ros_path: tuple[str, ...]) -> None:
        """Every parameter under ``tree``: left out."""
        for key, value in tree.items():
            if is_parameter(value) and value["type"] != OPEN_TYPE:
                self.outcomes.append(Outcome(".".join((*ros_path, str(key))), LEFT_OUT))
            elif isinstance(value, dict) and not is_parameter(value):
                inner = "*" if str(key).startswith(MAP_PREFIX) else str(key)
                self.all_lost(value, (*ros_path, inner))

    def leaf(
        self, leaf: dict[str, Any], doc_path: Path, ros_path: tuple[str, ...]
    ) -> dict[str, Any] | None:
        gpl_type = leaf["type"]
        for key in leaf:
            if key not in _LEAF_KEYS:
                self.warn((*doc_path, key), f"unknown GPL key {key!r}: left out")
        if gpl_type == OPEN_TYPE:
            out: dict[str, Any] = {"open": True}
            if leaf.get("description"):
                out["description"] = leaf["description"]
            return out
        name = ".".join(ros_path)
        base, capacity = _base_type(str(gpl_type))
        if base not in TYPES:
            self.warn((*doc_path, "type"), f"unknown type {gpl_type!r}: parameter left out")
            self.outcomes.append(Outcome(name, LEFT_OUT))
            return None
        out = {"type": base}
        if "default_value" in leaf:
            out["default"] = leaf["default_value"]
            try:
                TYPES[base].coerce_default(out["default"])
            except ValueTypeError as exc:
                where = (*doc_path, "default_value")
                location = self.document.value_location(where)
                self.errors.append(SchemaProblem(location, dotted(where), f"wrong default: {exc}"))
        if leaf.get("description"):
            out["description"] = leaf["description"]
        if leaf.get("read_only"):
            out["read_only"] = True
        if ".".join(ros_path) in self.adopt:
            out["adopt"] = True
            self.adopt.discard(".".join(ros_path))
        validators = self.validators(leaf, doc_path, ros_path, base, out)
        if capacity is not None:
            validators.insert(0, {"length": {"max": capacity}})
        if validators:
            out["validators"] = validators
        if leaf.get("additional_constraints"):
            out["additional_constraints"] = leaf["additional_constraints"]
        self.must_be_set(out, doc_path)
        self.outcomes.append(Outcome(name, EXACT, name))
        return out

    def validators(
        self,
        leaf: dict[str, Any],
        doc_path: Path,
        ros_path: tuple[str, ...],
        base: str,
        out_leaf: dict[str, Any],
    ) -> list[Any]:
        validation = leaf.get("validation") or {}
        if not isinstance(validation, dict):
            self.warn((*doc_path, "validation"), "validation must be a mapping: left out")
            return []
        refused = combination_refused(validation)
        if refused:
            self.note(
                (*doc_path, "validation"),
                f"GPL 1.0 and later refuse {refused} (earlier ones warn): imported with each "
                "validation setting its side of the range in file order, as they did",
            )
        out: list[Any] = []
        low: float | None = None
        high: float | None = None
        for key, raw in validation.items():
            where = (*doc_path, "validation", key)
            translated: Translated = translate(str(key), raw, base, self.checks_module)
            if translated.problem:
                self.warn(where, f"{translated.problem}: validator left out")
                continue
            out.extend(translated.validators)
            if translated.element_low is not None:
                low = translated.element_low
            if translated.element_high is not None:
                high = translated.element_high
            if translated.custom:
                use = self.customs.get(translated.custom, CustomUse(translated.custom, str(key)))
                use = use.also_by(".".join(ros_path), tuple(arguments(raw)))
                self.customs[translated.custom] = use
                self.note(where, f"custom validator: write {self.checks_module}.{use.function}")
        limits = descriptor_range(validation, base)
        if limits is not None and not base.endswith("_array"):
            # GPL puts scalar bounds in the descriptor's range, where ROS enforces them.
            out_leaf["range"] = {"min": limits[0], "max": limits[1]}
        if limits is not None and (low is not None or high is not None):
            # On an array, GPL's descriptor carries the same range; genparams checks each item.
            out.append(element_bounds(*limits, base))
        return out

    def must_be_set(self, out: dict[str, Any], doc_path: Path) -> None:
        """GPL's idiom for "must be set": a default its own validators refuse -> required."""
        if "default" not in out:
            return
        param_type = TYPES[out["type"]]
        try:
            value = param_type.coerce_default(out["default"])
        except ValueTypeError:
            return  # a wrong default stays, so genparams reports it at its place
        limits = out.get("range")
        if limits is not None and not limits["min"] <= value <= limits["max"]:
            self.note(
                (*doc_path, "default_value"),
                f"default {out.pop('default')!r} lies outside its own bounds: "
                "imported as a required parameter",
            )
            return
        for entry in out.get("validators", []):
            rule, argument = (entry, None) if isinstance(entry, str) else next(iter(entry.items()))
            if rule == "custom" or rule not in KINDS:
                continue
            try:
                check = checked_validator(rule, _frozen(argument), param_type.name)
            except (ValidatorArgumentError, KeyError):
                continue
            reason = check(value)
            if reason is not None:
                self.note(
                    (*doc_path, "default_value"),
                    f"default {out.pop('default')!r} breaks its own validator ({reason}): "
                    "imported as a required parameter",
                )
                return


def _unset_inside(namespace: dict[str, Any]) -> bool:
    """Whether a converted namespace holds a parameter without a default."""
    for key, value in namespace.items():
        if not isinstance(value, dict) or key == "for_each" or value.get("open"):
            continue
        if not is_parameter(value) and _unset_inside(value):
            return True
        if is_parameter(value) and "default" not in value and not value.get("optional"):
            return True
    return False


def _frozen(value: Any) -> Any:
    if isinstance(value, list):
        return tuple(_frozen(v) for v in value)
    return value


def _base_type(gpl_type: str) -> tuple[str, int | None]:
    """``string_fixed_25`` -> (string, 25): a fixed size is a capacity, as in GPL."""
    match = _FIXED.fullmatch(gpl_type)
    if match is None:
        return gpl_type, None
    return match["base"], int(match["size"])
