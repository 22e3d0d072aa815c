"""Typed access to the parameters of another node that follows the same schema.

Built on rclpy's AsyncParameterClient (the parameter services) and the
``/parameter_events`` topic. Every call returns an rclpy Future, so it can be
awaited in a coroutine run by an executor, or waited on with
``executor.spin_until_future_complete``. Results are typed snapshots, the same
frozen values ``snapshot()`` returns on the node itself.
"""

from __future__ import annotations

import difflib
import threading
import time
import traceback
from collections.abc import Callable, Generator, Mapping
from typing import Any, Generic, TypeVar, cast

from rcl_interfaces.msg import ParameterEvent
from rclpy.node import Node
from rclpy.parameter import Parameter, parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from rclpy.subscription import Subscription
from rclpy.task import Future
from rclpy.timer import Timer

from genparams.naming import join_prefix
from genparams.runtime.binding import check_prefix
from genparams.runtime.changes import Change, Changes
from genparams.runtime.errors import RemoteParameterError, RemoteSetError
from genparams.runtime.params import Params
from genparams.runtime.spec import CompiledParam, compile_schema
from genparams.runtime.tree import build_tree, get_path, replace_values
from genparams.types import ValueTypeError

P = TypeVar("P", bound=Params)
T = TypeVar("T")


class TypedFuture(Future, Generic[T]):
    """An rclpy Future that says what it resolves to."""

    def result(self) -> T | None:
        """The result once done (None before); raises the failure if there was one."""
        return cast("T | None", super().result())

    def __await__(self) -> Generator[None, None, T]:
        result = yield from super().__await__()
        return cast(T, result)


def _fully_qualified(node: Node, target: str) -> str:
    if target.startswith("/"):
        return target
    namespace = node.get_namespace().rstrip("/")
    return f"{namespace}/{target}"


class RemoteParams(Generic[P]):
    """A typed client for the parameters of ``target``, declared there from the same schema.

    ``set`` checks values with the schema's validators and rules before anything is
    sent; the remote node checks them again (it runs the same schema), so rules
    that also read values not being set are left to it.
    """

    def __init__(self, params_cls: type[P], node: Node, target: str, prefix: str = "") -> None:
        self.params_cls = params_cls
        self.node = node
        self.prefix = check_prefix(prefix)
        self.target = _fully_qualified(node, target)
        self.compiled = compile_schema(params_cls._SPEC)
        self.full_names = {name: join_prefix(prefix, name) for name in self.compiled.parameters}
        self.relative_names = {full: name for name, full in self.full_names.items()}
        self.client = AsyncParameterClient(node, self.target)

    def __repr__(self) -> str:
        prefix = f", prefix={self.prefix!r}" if self.prefix else ""
        return f"{self.params_cls.__name__}.remote({self.target!r}{prefix})"

    def wait_for_services(self, timeout_sec: float | None = None) -> bool:
        """Block until the target's parameter services answer; False after ``timeout_sec``."""
        return bool(self.client.wait_for_services(timeout_sec=timeout_sec))

    def get(self) -> TypedFuture[P]:
        """Every parameter of the schema, read in one request, as a frozen snapshot."""
        result: TypedFuture[P] = TypedFuture()

        def answered(response_future: Future) -> None:
            try:
                response = response_future.result()
                if len(response.values) != len(self.full_names):
                    # The service answers nothing at all when one name is not declared.
                    self.client.list_parameters([], 0, report_missing)
                    return
                values = self.typed_values(zip(self.full_names, response.values, strict=True))
                result.set_result(self.snapshot(values))
            except Exception as exc:  # handed to whoever waits on the future
                result.set_exception(exc)

        def report_missing(response_future: Future) -> None:
            try:
                declared = set(response_future.result().result.names)
                missing = [full for full in self.full_names.values() if full not in declared]
                result.set_exception(
                    self.not_following([f"{full}: not declared" for full in missing])
                )
            except Exception as exc:
                result.set_exception(exc)

        self.client.get_parameters(list(self.full_names.values()), answered)
        return result

    def not_following(self, problems: list[str]) -> RemoteParameterError:
        return RemoteParameterError(
            f"{self.target} does not follow {self.compiled.spec.name}: " + "; ".join(problems)
        )

    def typed_values(self, pairs: Any) -> dict[str, Any]:
        values: dict[str, Any] = {}
        problems: list[str] = []
        for name, message in pairs:
            full = self.full_names[name]
            try:
                values[name] = self.compiled.parameters[name].type.from_ros(
                    parameter_value_to_python(message)
                )
            except ValueTypeError as exc:
                problems.append(f"{full}: {exc}")
        if problems:
            raise self.not_following(problems)
        return values

    def snapshot(self, values: Mapping[str, Any]) -> P:
        return build_tree(
            self.params_cls, self.compiled.spec.groups, values, extra={"_binding": None}
        )

    def set(self, values: Mapping[str, Any]) -> TypedFuture[None]:
        """Set ``values`` (relative ROS names -> values) atomically: all of them or none.

        A value the schema rejects fails the future at once, with nothing sent
        (``RemoteSetError.sent`` is False). A rejection by the node fails it with
        the node's reason. Doubles may be given as ints, arrays as lists.
        """
        result: TypedFuture[None] = TypedFuture()
        typed, reasons = self.check(values)
        if reasons:
            result.set_exception(RemoteSetError("; ".join(reasons), sent=False))
            return result
        parameters = []
        for name, value in typed.items():
            param = self.compiled.parameters[name]
            parameters.append(
                Parameter(
                    self.full_names[name],
                    Parameter.Type(param.type.ros_type),
                    param.type.to_ros(value),
                )
            )

        def answered(response_future: Future) -> None:
            try:
                outcome = response_future.result().result
            except Exception as exc:
                result.set_exception(exc)
                return
            if outcome.successful:
                result.set_result(None)
            else:
                result.set_exception(RemoteSetError(outcome.reason, sent=True))

        self.client.set_parameters_atomically(parameters, answered)
        return result

    def check(self, values: Mapping[str, Any]) -> tuple[dict[str, Any], list[str]]:
        """Typed values and the reasons the schema rejects them, worded as the node words them."""
        typed: dict[str, Any] = {}
        reasons: list[str] = []
        for name, value in values.items():
            param = self.compiled.parameters.get(name)
            if param is None:
                close = difflib.get_close_matches(name, sorted(self.compiled.parameters), n=1)
                hint = f" (did you mean {close[0]!r}?)" if close else ""
                reasons.append(f"{name}: no such parameter in {self.compiled.spec.name}{hint}")
                continue
            reason = _check_one(param, value)
            if isinstance(reason, str):
                reasons.append(f"{self.full_names[name]}: {reason}")
            else:
                typed[name] = reason[0]
        if reasons:
            return typed, reasons
        for rule in self.compiled.rules:
            if all(name in typed for name in rule.parameters):
                broken = rule.violation(typed, self.full_names.__getitem__)
                if broken is not None:
                    reasons.append(broken)
        return typed, reasons

    def watch(self, callback: Callable[[Changes[P]], None]) -> RemoteWatch[P]:
        """Call ``callback`` with the typed changes of each accepted set on the target.

        Returns a handle: ``ready`` resolves to the first snapshot (every change
        from there on is reported), ``latest`` is the newest known snapshot, and
        ``cancel()`` stops watching. The client node must be spun by an executor.
        """
        return RemoteWatch(self, callback)


def _check_one(param: CompiledParam, value: Any) -> str | tuple[Any]:
    if param.spec.read_only:
        return "read-only: set it when the node starts (-p, a params file or launch)"
    try:
        typed = param.type.coerce_default(value)
    except ValueTypeError as exc:
        return str(exc)
    reason = param.check(typed)
    return reason if reason is not None else (typed,)


class RemoteWatch(Generic[P]):
    """Mirrors the target's parameters from its parameter events; see ``RemoteParams.watch``.

    Parameter events are not replayed to late subscribers, so the first snapshot is
    read only once the event subscription is connected (or after ``CONNECT_TIMEOUT``):
    from ``ready`` on, no change goes unreported.
    """

    CONNECT_TIMEOUT = 5.0

    def __init__(self, remote: RemoteParams[P], callback: Callable[[Changes[P]], None]) -> None:
        self.remote = remote
        self.callback = callback
        self.lock = threading.Lock()  # events and the first snapshot may arrive on two threads
        self.latest: P | None = None
        self.early: list[ParameterEvent] = []  # events that came before the first snapshot
        self.ready: TypedFuture[P] = TypedFuture()
        self.subscription: Subscription | None = remote.client.on_parameter_event(self.on_event)
        self.connect_deadline = time.monotonic() + self.CONNECT_TIMEOUT
        self.connecting: Timer | None = remote.node.create_timer(0.02, self.read_when_connected)

    def cancel(self) -> None:
        """Stop watching; the callback is not called again."""
        with self.lock:
            self.stop_connecting()
            if self.subscription is not None:
                self.remote.node.destroy_subscription(self.subscription)
                self.subscription = None

    def stop_connecting(self) -> None:
        if self.connecting is not None:
            self.remote.node.destroy_timer(self.connecting)
            self.connecting = None

    def read_when_connected(self) -> None:
        with self.lock:
            if self.connecting is None or self.subscription is None:
                return
            publishers = self.remote.node.count_publishers(self.subscription.topic_name)
            connected = self.subscription.get_publisher_count() >= publishers
            if not connected and time.monotonic() < self.connect_deadline:
                return
            self.stop_connecting()
        self.remote.get().add_done_callback(self.on_first_snapshot)

    def on_first_snapshot(self, future: Future) -> None:
        with self.lock:
            try:
                self.latest = future.result()
            except Exception as exc:
                self.ready.set_exception(exc)
                return
            early, self.early = self.early, []
            for event in early:
                self.apply(event)
        self.ready.set_result(self.latest)

    def on_event(self, event: ParameterEvent) -> None:
        if event.node != self.remote.target:
            return
        with self.lock:
            if self.latest is None:
                self.early.append(event)
            else:
                self.apply(event)

    def apply(self, event: ParameterEvent) -> None:
        before = self.latest
        assert before is not None  # guarded by the callers
        remote = self.remote
        changed: list[Change] = []
        paths: dict[tuple[str, ...], Any] = {}
        for message in (*event.new_parameters, *event.changed_parameters):
            name = remote.relative_names.get(message.name)
            if name is None:
                continue
            param = remote.compiled.parameters[name]
            try:
                new = param.type.from_ros(parameter_value_to_python(message.value))
            except ValueTypeError as exc:
                remote.node.get_logger().warning(f"{remote!r}: ignoring {message.name}: {exc}")
                continue
            old = get_path(before, param.attribute_path)
            if old != new:
                changed.append(Change(name, old, new))
                paths[param.attribute_path] = new
        if not changed:
            return
        after = replace_values(before, paths, extra=("_binding",))
        self.latest = after
        try:
            self.callback(Changes(before, after, tuple(changed)))
        except Exception:  # a subscriber's bug must not stop the watch
            remote.node.get_logger().error(
                f"watch callback {self.callback!r} raised:\n{traceback.format_exc()}"
            )
