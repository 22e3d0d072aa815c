"""Hypothesis strategies for random valid genparams schemas.

A drawn :class:`SchemaCase` holds the YAML text and, computed independently of
genparams, the value every parameter must read back as (its default, or the
override a required parameter is given). Schemas cover the nine types, deep
namespaces, every validator with a consistent default, Unicode and hostile
text, long names, Python keywords and names of the generated API.
"""

from __future__ import annotations

import keyword
import math
import re
from dataclasses import dataclass, field
from typing import Any

from hypothesis import strategies as st

from tests.yaml_text import Flow, block

INT64_MIN, INT64_MAX = -(2**63), 2**63 - 1
SCALAR_TYPES = ("bool", "int", "double", "string")
ARRAY_TYPES = ("byte_array", "bool_array", "int_array", "double_array", "string_array")
ALL_TYPES = SCALAR_TYPES + ARRAY_TYPES

# Names the contract rejects (docs/schema.md); valid schemas never use them.
RESERVED_TOP_LEVEL = {
    "declare",
    "defaults",
    "snapshot",
    "on_change",
    "to_dict",
    "remote",
    "changes",
}
REJECTED = {"bool", "bytes", "float", "int", "str", "tuple", "ClassVar", "for_each"}

# docs/schema.md#names, restated for the oracle: '-' and '/' inside names, spelt '_'.
ROS_TOKEN = re.compile(r"[A-Za-z][A-Za-z0-9_-]*(?:/[A-Za-z][A-Za-z0-9_-]*)*")

HOSTILE_TEXT = (
    '"',
    "'",
    '"""',
    "'''",
    "\\",
    "\\n",
    "\\x00",
    "{{ 7 * 7 }}",
    "{% if true %}x{% endif %}",
    "{# c #}",
    "# comment",
    "\u2028",
    "\u2029",
    "\x85",
    "\r\n",
    "\t",
    "\ufeff",
    "\u202e",
    '"); import os; os.system("touch PWNED") #',
    "'''); import os; os.system('touch PWNED') #",
    '\\"; raise SystemExit #',
    "${HOME} %s {0}",
    "]]></x>",
    "",
    " ",
)

SPECIAL_NAMES = (
    *keyword.kwlist,
    *keyword.softkwlist,
    "list",
    "dict",
    "type",
    "id",
    "len",
    "print",
    "object",
    "property",
    "range",
    "super",
    "self",
    "cls",
    "annotations",
    "l",
    "I",
    "O",
    "slots",
    "Group",
    "Params",
    "ParamSpec",
    "on",
    "off",
    "yes",
    "no",
    "y",
    "n",
    "null",
    "Null",
    "NULL",
    "true",
    "FALSE",
    "inf",
    "nan",
    *sorted(RESERVED_TOP_LEVEL),
)


def python_attribute(name: str) -> str:
    spelt = name.replace("-", "_").replace("/", "_")
    return spelt + "_" if keyword.iskeyword(spelt) else spelt


def texts(max_size: int = 30) -> st.SearchStrategy[str]:
    """Any text ROS can carry (UTF-8, no NUL), with hostile fragments mixed in."""
    plain = st.text(
        st.characters(exclude_categories=["Cs"], exclude_characters="\x00"), max_size=max_size
    )
    return st.one_of(
        plain,
        st.sampled_from(HOSTILE_TEXT),
        st.lists(st.one_of(plain, st.sampled_from(HOSTILE_TEXT)), max_size=4).map("".join),
    )


def names(*, top_level: bool) -> st.SearchStrategy[str]:
    tokens = st.one_of(
        st.from_regex(r"[A-Za-z][A-Za-z0-9_]{0,12}", fullmatch=True),
        st.sampled_from(SPECIAL_NAMES),
        st.from_regex(r"[a-z][a-z0-9_]{60,120}", fullmatch=True),
        st.from_regex(r"[A-Za-z][A-Za-z0-9_-]{0,8}(/[A-Za-z][A-Za-z0-9_-]{0,4})?", fullmatch=True),
    )
    excluded = REJECTED | (RESERVED_TOP_LEVEL if top_level else set())
    return tokens.filter(
        lambda name: (
            name not in excluded
            and python_attribute(name) not in excluded
            and ROS_TOKEN.fullmatch(name) is not None
            and not name.startswith("zz_")
        )
    )


int64s = st.one_of(st.integers(INT64_MIN, INT64_MAX), st.sampled_from([INT64_MIN, INT64_MAX, 0]))
doubles = st.one_of(
    st.floats(allow_nan=False, allow_infinity=False),
    st.sampled_from([0.0, -0.0, 5e-324, 1.7976931348623157e308, math.inf, -math.inf, math.nan]),
)


def values(type_name: str) -> st.SearchStrategy[Any]:
    """Typed-view values: tuples for arrays, bytes for byte_array."""
    element = {
        "bool": st.booleans(),
        "int": int64s,
        "double": doubles,
        "string": texts(),
    }
    if type_name in element:
        return element[type_name]
    if type_name == "byte_array":
        return st.binary(max_size=8)
    return st.lists(element[type_name.removesuffix("_array")], max_size=5).map(tuple)


def written(type_name: str, value: Any, integral_doubles: bool) -> Any:
    """How a default is written in YAML; a whole double may be written as an integer."""
    if type_name == "byte_array":
        return list(value)
    if type_name == "double" and integral_doubles and _whole(value):
        return int(value)
    if isinstance(value, tuple):
        return list(value)
    return value


def _whole(value: float) -> bool:
    return math.isfinite(value) and value.is_integer() and abs(value) < 2**53 and value != 0


def _finite_numbers(value: Any) -> list[Any]:
    items = list(value) if isinstance(value, tuple) else [value]
    return [v for v in items if not (isinstance(v, float) and not math.isfinite(v))]


@st.composite
def numeric_constraints(draw: st.DrawFn, type_name: str, value: Any) -> dict[str, Any]:
    """range / gt / ge / lt / le / bounds / element_bounds that ``value`` satisfies."""
    is_int = type_name.startswith("int")
    items = _finite_numbers(value)
    if not items or len(items) != (len(value) if isinstance(value, tuple) else 1):
        return {}
    low, high = min(items), max(items)
    gap = st.integers(0, 1000) if is_int else st.floats(0, 1e6)
    below, above = low - draw(gap), high + draw(gap)
    if is_int:
        below, above = max(below, INT64_MIN), min(above, INT64_MAX)
    if not (below <= low and high <= above and math.isfinite(above - below)):
        return {}
    out: dict[str, Any] = {}
    validators: list[Any] = []
    if draw(st.booleans()):
        value_range = {"min": below, "max": above}
        if is_int and not isinstance(value, tuple) and draw(st.booleans()):
            step = draw(st.integers(1, 50))
            value_range["min"] = max(value - step * draw(st.integers(0, 5)), INT64_MIN)
            if (value - value_range["min"]) % step == 0:
                value_range["step"] = step
        elif not is_int and not isinstance(value, tuple) and draw(st.booleans()):
            value_range["min"] = value  # on the edge: every step is fine there
            value_range["step"] = draw(st.floats(0.001, 1000))
            if not math.isfinite((above - value) / value_range["step"]):
                del value_range["step"]
        out["range"] = value_range
    if isinstance(value, tuple):
        if draw(st.booleans()):
            validators.append({"element_bounds": [below, above]})
    else:
        if draw(st.booleans()):
            validators.append({"bounds": [below, above]})
        for rule in draw(st.lists(st.sampled_from(["gt", "ge", "lt", "le"]), max_size=2)):
            limit = {"gt": below - 1, "ge": below, "lt": above + 1, "le": above}[rule]
            if is_int and not INT64_MIN <= limit <= INT64_MAX:
                continue
            if not is_int and (limit == value):  # below - 1 may round back to value
                continue
            validators.append({rule: limit})
    if validators:
        out["validators"] = validators
    return out


@st.composite
def choice_constraints(draw: st.DrawFn, type_name: str, value: Any) -> dict[str, Any]:
    """choices / one_of / subset_of lists that hold ``value`` (or all of its items)."""
    scalar = type_name.removesuffix("_array")
    if scalar not in ("int", "double", "string") or type_name == "byte_array":
        return {}
    items = list(value) if isinstance(value, tuple) else [value]
    if any(isinstance(v, float) and math.isnan(v) for v in items):
        return {}
    extra = draw(st.lists(values(scalar), max_size=3))
    pool: list[Any] = []
    for item in [*items, *extra]:
        if isinstance(item, float) and math.isnan(item):
            continue
        if not any(_same(item, seen) for seen in pool):
            pool.append(item)
    if not pool:
        return {}
    pool = draw(st.permutations(pool))
    rule = "subset_of" if isinstance(value, tuple) else "one_of"
    if draw(st.booleans()):
        return {"choices": pool}
    return {"validators": [{rule: pool}]}


def _same(a: Any, b: Any) -> bool:
    return bool(a == b)


@st.composite
def size_constraints(draw: st.DrawFn, type_name: str, value: Any) -> dict[str, Any]:
    """not_empty / unique / length / pattern that ``value`` satisfies."""
    if type_name not in ("string", *ARRAY_TYPES):
        return {}
    size = len(value)
    validators: list[Any] = []
    if size and draw(st.booleans()):
        validators.append("not_empty")
    hashable = [v for v in value if not (isinstance(v, float) and math.isnan(v))]
    if type_name != "string" and len(set(hashable)) == size and draw(st.booleans()):
        validators.append("unique")
    if draw(st.booleans()):
        validators.append(
            draw(
                st.sampled_from(
                    [
                        {"length": size},
                        {"length": {"exact": size}},
                        {"length": {"min": max(0, size - 1)}},
                        {"length": {"max": size + 2}},
                        {"length": {"min": size, "max": size + 1}},
                    ]
                )
            )
        )
    if type_name in ("string", "string_array") and draw(st.booleans()):
        items = [value] if type_name == "string" else list(value)
        alternatives = "|".join(re.escape(item) for item in items) if items else "x"
        validators.append({"pattern": f"\\A(?:{alternatives})\\Z"})
    return {"validators": validators} if validators else {}


@dataclass
class Leaf:
    type: str
    value: Any  # what it must read back as
    required: bool
    body: dict[str, Any]


@st.composite
def leaves(draw: st.DrawFn) -> Leaf:
    type_name = draw(st.sampled_from(ALL_TYPES))
    value = draw(values(type_name))
    required = draw(st.integers(0, 9)) == 0
    body: dict[str, Any] = {"type": type_name}
    if not required:
        body["default"] = written(type_name, value, draw(st.booleans()))
    for key in draw(st.sets(st.sampled_from(["description", "unit", "constraints", "deprecated"]))):
        text = draw(texts(60))
        if key == "constraints":
            body["additional_constraints"] = text
        elif key == "deprecated":
            body["deprecated"] = text or "deprecated"
        else:
            body[key] = text
    if draw(st.integers(0, 4)) == 0:
        body["read_only"] = True
    constraints = [
        draw(numeric_constraints(type_name, value))
        if type_name.startswith(("int", "double"))
        else {},
        draw(choice_constraints(type_name, value)),
        draw(size_constraints(type_name, value)),
    ]
    validators: list[Any] = []
    for found in constraints:
        validators.extend(found.pop("validators", []))
        body.update(found)
    if type_name == "int" and value % 2 == 0 and draw(st.booleans()):
        validators.append({"custom": "tests.custom_checks:is_even"})
    if validators:
        body["validators"] = draw(st.permutations(validators))
    return Leaf(type_name, value, required, body)


@dataclass
class SchemaCase:
    name: str
    text: str
    document: dict[str, Any] = field(default_factory=dict)  # what text says, as data
    values: dict[str, Any] = field(default_factory=dict)  # dotted ROS name -> typed value
    types: dict[str, str] = field(default_factory=dict)
    required: set[str] = field(default_factory=set)
    entries: set[str] = field(default_factory=set)  # names of mapped entries' parameters
    paths: dict[str, tuple[str, ...]] = field(default_factory=dict)  # where cfg holds a value

    def path(self, name: str) -> tuple[str, ...]:
        """The attribute path of ``name`` in the typed view (an entry's key stays as it is)."""
        return self.paths.get(name) or tuple(python_attribute(p) for p in name.split("."))


@st.composite
def namespace(
    draw: st.DrawFn, case: SchemaCase, path: tuple[str, ...], depth: int
) -> dict[str, Any]:
    count = draw(st.integers(1, 4 if depth < 3 else 2))
    keys = draw(
        st.lists(
            names(top_level=not path), min_size=count, max_size=count, unique_by=python_attribute
        )
    )
    out: dict[str, Any] = {}
    for key in keys:
        if depth < 6 and draw(st.integers(0, 3)) == 0:
            out[key] = draw(namespace(case, (*path, key), depth + 1))
            continue
        leaf = draw(leaves())
        ros_name = ".".join((*path, key))
        case.values[ros_name] = leaf.value
        case.types[ros_name] = leaf.type
        if leaf.required:
            case.required.add(ros_name)
        out[key] = Flow(leaf.body) if draw(st.booleans()) else leaf.body
    return out


# The mapped group and its key list: names() never draws a name starting "zz_".
MAP_KEYS = "zz_keys"
MAPPED = "zz_entries"
ENTRY_KEYS = st.lists(
    st.from_regex(r"[A-Za-z0-9_-]{1,10}", fullmatch=True), max_size=4, unique=True
)
RULE_WORDS = frozenset({"abs", "len", "min", "max", "true", "false", "and", "or", "not", "if"})
RULE_OPERATORS = {
    "<=": lambda a, b: a <= b,
    ">=": lambda a, b: a >= b,
    "<": lambda a, b: a < b,
    ">": lambda a, b: a > b,
    "==": lambda a, b: a == b,
    "!=": lambda a, b: a != b,
}


@st.composite
def mapped_group(draw: st.DrawFn, case: SchemaCase) -> dict[str, Any]:
    """A top-level mapped group over a key list: one entry per key, leaves with defaults."""
    keys = draw(ENTRY_KEYS)
    case.values[MAP_KEYS] = tuple(keys)
    case.types[MAP_KEYS] = "string_array"
    leaves_by_name = {
        leaf_name: draw(leaves().filter(lambda leaf: not leaf.required))
        for leaf_name in draw(
            st.lists(names(top_level=False), min_size=1, max_size=3, unique_by=python_attribute)
        )
    }
    for key in keys:
        for leaf_name, leaf in leaves_by_name.items():
            ros_name = f"{MAPPED}.{key}.{leaf_name}"
            case.values[ros_name] = leaf.value
            case.types[ros_name] = leaf.type
            case.entries.add(ros_name)
            case.paths[ros_name] = (MAPPED, key, python_attribute(leaf_name))
    group: dict[str, Any] = {"for_each": MAP_KEYS}
    group.update({leaf_name: leaf.body for leaf_name, leaf in leaves_by_name.items()})
    return group


def _rule_operand(case: SchemaCase, name: str) -> bool:
    value = case.values[name]
    return (
        name not in case.required
        and name not in case.entries
        and case.types[name] in ("int", "double")
        and not (isinstance(value, float) and not math.isfinite(value))
        and not any(keyword.iskeyword(p) or p in RULE_WORDS for p in name.split("."))
    )


def _rule_name(name: str) -> str:
    """How a rule refers to a parameter: keywords take a trailing underscore."""
    return ".".join(python_attribute(part) for part in name.split("."))


@st.composite
def rules(draw: st.DrawFn, case: SchemaCase) -> list[dict[str, Any]]:
    """Rules over numeric parameters that their values satisfy."""
    operands = sorted(name for name in case.values if _rule_operand(case, name))
    if not operands:
        return []
    out = []
    for index in range(draw(st.integers(0, 3))):
        left, right = draw(st.sampled_from(operands)), draw(st.sampled_from(operands))
        a, b = case.values[left], case.values[right]
        holding = [op for op, holds in RULE_OPERATORS.items() if holds(a, b)]
        op = draw(st.sampled_from(holding))
        check = f"{_rule_name(left)} {op} {_rule_name(right)}"
        if draw(st.booleans()):
            check = f"abs({_rule_name(left)}) >= 0 and {check}"
        out.append({"name": f"rule_{index}", "check": check})
    return out


@st.composite
def schemas(draw: st.DrawFn) -> SchemaCase:
    name = draw(st.from_regex(r"[a-z][a-z0-9_]{0,20}", fullmatch=True))
    case = SchemaCase(name, "")
    document: dict[str, Any] = {"genparams": 1, "name": name}
    if draw(st.booleans()):
        document["description"] = draw(texts(80))
    document["parameters"] = draw(namespace(case, (), 0))
    if draw(st.integers(0, 2)) == 0:
        document["parameters"][MAPPED] = draw(mapped_group(case))
        document["parameters"][MAP_KEYS] = {
            "type": "string_array",
            "default": list(case.values[MAP_KEYS]),
        }
    drawn_rules = draw(rules(case))
    if drawn_rules:
        document["rules"] = drawn_rules
    case.document = document
    case.text = block(document, quote_keys=draw(st.booleans()))
    return case
