"""Names of rclpy and its messages the evaluator knows: parameter types, descriptor fields,
QoS policy values, math constants."""

from __future__ import annotations

import ast
import math
import operator
from collections.abc import Callable
from typing import Any

# rclpy's Parameter.Type members (and rcl_interfaces' ParameterType constants) -> schema types.
ROS_TYPES = {
    "BOOL": "bool",
    "INTEGER": "int",
    "DOUBLE": "double",
    "STRING": "string",
    "BYTE_ARRAY": "byte_array",
    "BOOL_ARRAY": "bool_array",
    "INTEGER_ARRAY": "int_array",
    "DOUBLE_ARRAY": "double_array",
    "STRING_ARRAY": "string_array",
    "NOT_SET": "not_set",
}
DESCRIPTOR_FIELDS = (
    "name",
    "type",
    "description",
    "additional_constraints",
    "read_only",
    "dynamic_typing",
    "floating_point_range",
    "integer_range",
)
RANGE_FIELDS = ("from_value", "to_value", "step")
BINARY: dict[type[ast.operator], Callable[[Any, Any], Any]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv,
    ast.Mod: operator.mod,
    ast.Pow: operator.pow,
}
MATH = {"pi": math.pi, "e": math.e, "tau": math.tau, "inf": math.inf, "nan": math.nan}
# rclpy's QoS policy enums, often a parameter's default (an IntEnum: rclpy declares an int).
RCLPY_ENUMS = {
    **{f"QoSReliabilityPolicy.{k}": v for k, v in
       {"SYSTEM_DEFAULT": 0, "RELIABLE": 1, "BEST_EFFORT": 2, "BEST_AVAILABLE": 4}.items()},
    **{f"QoSDurabilityPolicy.{k}": v for k, v in
       {"SYSTEM_DEFAULT": 0, "TRANSIENT_LOCAL": 1, "VOLATILE": 2, "BEST_AVAILABLE": 4}.items()},
    **{f"QoSHistoryPolicy.{k}": v for k, v in
       {"SYSTEM_DEFAULT": 0, "KEEP_LAST": 1, "KEEP_ALL": 2}.items()},
    **{f"QoSLivelinessPolicy.{k}": v for k, v in
       {"SYSTEM_DEFAULT": 0, "AUTOMATIC": 1, "MANUAL_BY_TOPIC": 3, "BEST_AVAILABLE": 5}.items()},
}  # fmt: skip
