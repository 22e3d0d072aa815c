"""The rclpy glue: declare with full descriptors, validate every set, commit after acceptance.

Values reach the typed view only from the post-set callback, which rclpy calls
after every on-set callback accepted the change and the node stored it. A veto
anywhere leaves the view untouched.
"""

from __future__ import annotations

import threading
import traceback
from collections.abc import Callable, Sequence
from typing import Any, Generic, TypeVar

from rcl_interfaces.msg import (
    FloatingPointRange,
    IntegerRange,
    ParameterDescriptor,
    SetParametersResult,
)
from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.naming import is_ros_token, join_prefix
from genparams.runtime.changes import Change, Changes
from genparams.runtime.errors import ParameterDeclarationError
from genparams.runtime.params import Params
from genparams.runtime.resolve import resolve_values
from genparams.runtime.spec import CompiledParam, compile_schema
from genparams.runtime.tree import build_tree, copy_node, get_path, replace_values

P = TypeVar("P", bound=Params)

_ACCEPTED = SetParametersResult(successful=True)


def descriptor_for(param: CompiledParam, full_name: str) -> ParameterDescriptor:
    descriptor = ParameterDescriptor(
        name=full_name,
        type=param.type.ros_type,
        description=param.descriptor_description,
        additional_constraints=param.constraints_text,
        read_only=param.spec.read_only,
        dynamic_typing=False,
    )
    ros_range = param.ros_range
    if ros_range is not None:
        if ros_range.integer:
            descriptor.integer_range = [
                IntegerRange(
                    from_value=int(ros_range.low),
                    to_value=int(ros_range.high),
                    step=int(ros_range.step),
                )
            ]
        else:
            descriptor.floating_point_range = [
                FloatingPointRange(
                    from_value=float(ros_range.low),
                    to_value=float(ros_range.high),
                    step=float(ros_range.step),
                )
            ]
    return descriptor


def check_prefix(prefix: str) -> str:
    if prefix and not all(is_ros_token(part) for part in prefix.split(".")):
        raise ValueError(
            f"invalid parameter prefix {prefix!r}: dot-separated names of letters, "
            "digits and underscores, each starting with a letter"
        )
    return prefix


class Binding(Generic[P]):
    """One generated class declared on one node under one prefix."""

    def __init__(self, node: Node, prefix: str, owned: dict[str, CompiledParam]) -> None:
        self.node = node
        self.prefix = prefix
        self.owned = owned  # full ROS name -> parameter
        self.lock = threading.RLock()
        self.subscribers: list[Callable[[Changes[P]], None]] = []
        self.current: P  # the frozen root: snapshots hand this out
        self.live: P  # the root users hold: top-level attributes follow `current`

    @classmethod
    def declare(cls, params_cls: type[P], node: Node, prefix: str = "") -> Binding[P]:
        prefix = check_prefix(prefix)
        spec = params_cls._SPEC
        compiled = compile_schema(spec)
        full = {name: join_prefix(prefix, name) for name in compiled.parameters}

        # rclpy exposes overrides (-p, --params-file, launch) only through this attribute.
        overrides: dict[str, Parameter] = getattr(node, "_parameter_overrides", {})
        given: dict[str, Any] = {}
        problems: list[str] = []
        predeclared: list[str] = []
        for name, full_name in full.items():
            if node.has_parameter(full_name):
                if full_name not in overrides:
                    problems.append(f"{full_name}: already declared on this node by other code")
                    continue
                # Declared automatically from an override: re-declare it with its descriptor.
                predeclared.append(full_name)
                given[name] = node.get_parameter(full_name).value
            elif full_name in overrides:
                given[name] = overrides[full_name].value
        values, resolve_problems = resolve_values(compiled, given, full.__getitem__)
        problems.extend(resolve_problems)
        if problems:
            raise ParameterDeclarationError(spec.name, node.get_fully_qualified_name(), problems)

        for full_name in predeclared:
            node.undeclare_parameter(full_name)
        parameters = []
        descriptors = {}
        for name, value in values.items():
            param, full_name = compiled.parameters[name], full[name]
            parameters.append(
                Parameter(full_name, Parameter.Type(param.type.ros_type), param.type.to_ros(value))
            )
            descriptors[full_name] = descriptor_for(param, full_name)
        # Node.declare_parameters infers the type from the value, which turns an empty list
        # into BYTE_ARRAY; this path keeps the declared type of every parameter.
        node._declare_parameter_common(parameters, descriptors)

        binding: Binding[P] = cls(
            node, prefix, {full[name]: p for name, p in compiled.parameters.items()}
        )
        binding.current = build_tree(params_cls, spec.groups, values, extra={"_binding": None})
        live = copy_node(binding.current)
        object.__setattr__(live, "_binding", binding)
        binding.live = live
        node.add_on_set_parameters_callback(binding.on_set)
        node.add_post_set_parameters_callback(binding.on_post_set)
        return binding

    def on_set(self, parameters: Sequence[Parameter]) -> SetParametersResult:
        reasons = []
        for parameter in parameters:
            param = self.owned.get(parameter.name)
            if param is None:
                continue
            if parameter.type_ == Parameter.Type.NOT_SET:
                reasons.append(f"{parameter.name}: cannot be undeclared")
                continue
            try:
                value = param.type.from_ros(parameter.value)
            except ValueError as exc:
                reasons.append(f"{parameter.name}: {exc}")
                continue
            reason = param.check(value)
            if reason is not None:
                reasons.append(f"{parameter.name}: {reason}")
        if reasons:
            return SetParametersResult(successful=False, reason="; ".join(reasons))
        return _ACCEPTED

    def on_post_set(self, parameters: Sequence[Parameter]) -> None:
        updates = {}
        for parameter in parameters:
            param = self.owned.get(parameter.name)
            if param is not None:
                updates[param] = param.type.from_ros(parameter.value)
        if updates:
            self.commit(updates)

    def commit(self, updates: dict[CompiledParam, Any]) -> None:
        with self.lock:
            before = self.current
            changed = []
            paths = {}
            for param, value in updates.items():
                old = get_path(before, param.attribute_path)
                if old != value:
                    changed.append(Change(param.name, old, value))
                    paths[param.attribute_path] = value
            if not changed:
                return
            after = replace_values(before, paths, extra=("_binding",))
            self.current = after
            for head in {path[0] for path in paths}:
                object.__setattr__(self.live, head, getattr(after, head))
            self.notify(Changes(before, after, tuple(changed)))

    def notify(self, changes: Changes[P]) -> None:
        for callback in tuple(self.subscribers):
            try:
                callback(changes)
            except Exception:  # a subscriber's bug must not break the parameter service
                self.node.get_logger().error(
                    f"on_change callback {callback!r} raised:\n{traceback.format_exc()}"
                )

    def subscribe(self, callback: Callable[[Changes[P]], None]) -> Callable[[], None]:
        with self.lock:
            self.subscribers.append(callback)

        def unsubscribe() -> None:
            with self.lock:
                if callback in self.subscribers:
                    self.subscribers.remove(callback)

        return unsubscribe
