"""The table of the nine ROS 2 parameter types, and ``any``: one row per type.

Everything that depends on a parameter's type (the Python annotation of the
typed view, the ROS ``ParameterType`` number, how a schema default or a ROS
value is checked and converted) is read from this table. The module is pure
Python so both the code generator and the runtime can use it.

``any`` is a dynamically typed parameter (``dynamic_typing`` in its descriptor):
each value carries its own type, one of the nine, which a set may change.
"""

from __future__ import annotations

from typing import Any, ClassVar, TypeAlias

from genparams.runtime.core.errors import GenparamsError
from genparams.runtime.core.records import Record, store

RosValue: TypeAlias = (
    bool
    | int
    | float
    | str
    | bytes
    | tuple[bool, ...]
    | tuple[int, ...]
    | tuple[float, ...]
    | tuple[str, ...]
)
"""The typed-view value of a parameter of type ``any``: any of the nine types' values."""

INT64_MIN = -(2**63)
INT64_MAX = 2**63 - 1


class ValueTypeError(GenparamsError, ValueError):
    """A value does not have the parameter's type."""


class ParamType(Record):
    _fields = ("name", "ros_type", "ros_type_name", "annotation", "element", "json_type")
    __slots__ = (*_fields, "is_array", "ready")
    name: str  # schema spelling, e.g. "double_array"
    ros_type: int  # rcl_interfaces/msg/ParameterType constant
    ros_type_name: str  # e.g. "PARAMETER_DOUBLE_ARRAY"
    annotation: str  # Python type of the typed view
    element: str | None  # element kind for arrays: bool | int | double | string | byte
    json_type: str  # JSON Schema type of a value
    is_dynamic: ClassVar[bool] = False  # ``any``: the type is the value's own (dynamic_typing)
    # Read on every set, so stored rather than computed: whether values are arrays, and
    # the one Python type whose values ROS hands over already in typed-view form.
    is_array: bool
    ready: type | None

    def __init__(
        self,
        name: str,
        ros_type: int,
        ros_type_name: str,
        annotation: str,
        element: str | None,
        json_type: str,
    ) -> None:
        store(self, "name", name)
        store(self, "ros_type", ros_type)
        store(self, "ros_type_name", ros_type_name)
        store(self, "annotation", annotation)
        store(self, "element", element)
        store(self, "json_type", json_type)
        store(self, "is_array", element is not None)
        store(self, "ready", _READY.get(name))

    def of_value(self, value: Any) -> ParamType:
        """The type a typed-view value has under this parameter type: its own for ``any``."""
        return self

    @property
    def scalar_kind(self) -> str:
        """The kind of a scalar, or of an array's elements."""
        return self.element if self.element is not None else self.name

    @property
    def is_numeric(self) -> bool:
        return self.scalar_kind in ("int", "double")

    def coerce_default(self, value: Any) -> Any:
        """Check a schema default and return it in typed-view form.

        Schema defaults may spell a double as an integer (``30`` for ``30.0``);
        values that reach the node follow ROS's stricter rules instead (see
        :meth:`from_ros`).
        """
        return self._convert(value, lenient_double=True)

    def from_json(self, value: Any) -> Any:
        """Check a JSON value (a tuning page's edit) and return it in typed-view form.

        Refused, never converted: a bool for an int, a string for a number, a
        fraction for an int. JSON has one number type, so a double may be
        written without a fraction (``2`` for ``2.0``), as in a schema default.
        """
        return self._convert(value, lenient_double=True)

    def from_ros(self, value: Any) -> Any:
        """Convert a ROS parameter value to typed-view form, exactly as ROS types it."""
        if type(value) is self.ready:  # a bool or a double: nothing to convert or check
            return value
        # An empty list carries no element type (rclpy calls it BYTE_ARRAY), and rcl's
        # params-file parser reads `[]` as NOT_SET (None): both mean "empty" for an array.
        if self.is_array and (value is None or (isinstance(value, (list, tuple)) and not value)):
            return b"" if self.element == "byte" else ()
        return self._convert(value, lenient_double=False)

    def to_ros(self, value: Any) -> Any:
        """Convert a typed-view value to what ``rclpy.parameter.Parameter`` accepts."""
        if self.element == "byte":
            return [bytes((b,)) for b in value]
        if self.is_array:
            return list(value)
        return value

    def _convert(self, value: Any, *, lenient_double: bool) -> Any:
        if self.element is None:
            return _convert_scalar(self.name, value, lenient_double)
        if self.element == "byte":
            return _convert_bytes(value)
        if not isinstance(value, (list, tuple)) and type(value).__name__ != "array":
            raise ValueTypeError(f"expected {self.name}, got {_describe(value)}")
        items = []
        for index, item in enumerate(value):
            try:
                items.append(_convert_scalar(self.element, item, lenient_double))
            except ValueTypeError as exc:
                raise ValueTypeError(f"item {index}: {exc}") from None
        return tuple(items)


# Types whose ROS values need neither conversion nor a check beyond their exact type
# (an int must fit in int64 and a string must travel as UTF-8, so those are checked).
_READY: dict[str, type] = {"bool": bool, "double": float}


def _describe(value: Any) -> str:
    kind = {bool: "bool", int: "integer", float: "double", str: "string"}.get(type(value))
    if kind is None:
        kind = type(value).__name__
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{kind} {text}"


def _convert_scalar(kind: str, value: Any, lenient_double: bool) -> Any:
    if kind == "bool":
        if isinstance(value, bool):
            return value
    elif kind == "int":
        if isinstance(value, int) and not isinstance(value, bool):
            if not INT64_MIN <= value <= INT64_MAX:
                shown = str(value)
                shown = shown if len(shown) <= 60 else shown[:57] + "..."
                raise ValueTypeError(f"integer {shown} does not fit in int64")
            return value
    elif kind == "double":
        if isinstance(value, float):
            return value
        if lenient_double and isinstance(value, int) and not isinstance(value, bool):
            try:
                return float(value)
            except OverflowError:
                raise ValueTypeError(f"{_describe(value)} is too large for a double") from None
        if isinstance(value, int) and not isinstance(value, bool):
            raise ValueTypeError(
                f"expected double, got integer {value} (ROS does not convert: write {value}.0)"
            )
    elif kind == "string":
        if isinstance(value, str):
            problem = ros_text_problem(value)
            if problem is not None:
                raise ValueTypeError(problem)
            return value
    raise ValueTypeError(f"expected {_SCALAR_NAMES[kind]}, got {_describe(value)}")


def ros_text_problem(text: str) -> str | None:
    """Why ROS cannot carry ``text`` unchanged, or None.

    ROS sends strings as NUL-terminated UTF-8: a NUL would silently cut the
    string in the parameter services, and a lone surrogate cannot be encoded
    at all (rclpy fails after the node already stored the value).
    """
    if "\x00" in text:
        return "text cannot contain NUL (\\x00): ROS strings end at the first NUL"
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return "text must be valid UTF-8 (it contains a lone surrogate)"
    return None


def _convert_bytes(value: Any) -> bytes:
    if isinstance(value, (bytes, bytearray)):
        return bytes(value)
    if isinstance(value, (list, tuple)):
        out = bytearray()
        for index, item in enumerate(value):
            if isinstance(item, (bytes, bytearray)) and len(item) == 1:
                out += item
            elif isinstance(item, int) and not isinstance(item, bool) and 0 <= item <= 255:
                out.append(item)
            else:
                raise ValueTypeError(
                    f"item {index}: expected a byte (0..255), got {_describe(item)}"
                )
        return bytes(out)
    raise ValueTypeError(f"expected byte_array, got {_describe(value)}")


_SCALAR_NAMES = {"bool": "bool", "int": "integer", "double": "double", "string": "string"}


class DynamicType(ParamType):
    """``any``: a value of any of the nine types, typed by what it is (as rclpy infers
    ``Parameter.Type.from_parameter_value``). A list takes the type of its items, which
    must share one; a list of ints and doubles is a double_array in a schema default.
    An empty list is a byte_array, as rclpy infers it; a schema default cannot be one."""

    __slots__ = ()
    is_dynamic: ClassVar[bool] = True

    def of_value(self, value: Any) -> ParamType:
        return TYPES[_kind_of(value)]

    def coerce_default(self, value: Any) -> Any:
        return TYPES[_kind_of(value, lenient_double=True)].coerce_default(value)

    def from_ros(self, value: Any) -> Any:
        return TYPES[_kind_of(value)].from_ros(value)

    def to_ros(self, value: Any) -> Any:
        return TYPES[_kind_of(value)].to_ros(value)


_SCALAR_KINDS = {bool: "bool", int: "int", float: "double", str: "string"}


def _kind_of(value: Any, lenient_double: bool = False) -> str:
    """The type name of a value of ``any``, or ValueTypeError."""
    kind = _SCALAR_KINDS.get(type(value))
    if kind is not None:
        return kind
    if isinstance(value, (bytes, bytearray)):
        return "byte_array"
    if isinstance(value, (list, tuple)) or type(value).__name__ == "array":
        if not value and lenient_double:  # a schema default
            raise ValueTypeError("an empty list has no type: give an item, or a typed parameter")
        if all(isinstance(item, bytes) and len(item) == 1 for item in value):
            return "byte_array"  # rclpy's form of a byte array
        kinds = {_SCALAR_KINDS.get(type(item)) for item in value}
        if lenient_double and kinds == {"int", "double"}:
            kinds = {"double"}
        if len(kinds) == 1 and None not in kinds:
            return f"{kinds.pop()}_array"
        raise ValueTypeError(f"the items of a list must share one type, got {_describe(value)}")
    raise ValueTypeError(f"expected a value of a ROS parameter type, got {_describe(value)}")


TYPES: dict[str, ParamType] = {
    t.name: t
    for t in (
        ParamType("bool", 1, "PARAMETER_BOOL", "bool", None, "boolean"),
        ParamType("int", 2, "PARAMETER_INTEGER", "int", None, "integer"),
        ParamType("double", 3, "PARAMETER_DOUBLE", "float", None, "number"),
        ParamType("string", 4, "PARAMETER_STRING", "str", None, "string"),
        ParamType("byte_array", 5, "PARAMETER_BYTE_ARRAY", "bytes", "byte", "array"),
        ParamType("bool_array", 6, "PARAMETER_BOOL_ARRAY", "tuple[bool, ...]", "bool", "array"),
        ParamType("int_array", 7, "PARAMETER_INTEGER_ARRAY", "tuple[int, ...]", "int", "array"),
        ParamType(
            "double_array", 8, "PARAMETER_DOUBLE_ARRAY", "tuple[float, ...]", "double", "array"
        ),
        ParamType(
            "string_array", 9, "PARAMETER_STRING_ARRAY", "tuple[str, ...]", "string", "array"
        ),
        DynamicType("any", 0, "PARAMETER_NOT_SET", "_RosValue", None, "any"),
    )
}

TYPES_BY_ROS_TYPE: dict[int, ParamType] = {
    t.ros_type: t for t in TYPES.values() if not t.is_dynamic
}
