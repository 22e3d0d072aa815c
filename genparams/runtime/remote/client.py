"""Typed access to the parameters of another node that follows the same schema.

Built on rclpy's AsyncParameterClient (the parameter services) and the
``/parameter_events`` topic. Every call returns an rclpy Future, so it can be
awaited in a coroutine run by an executor, or waited on with
``executor.spin_until_future_complete``. Results are typed snapshots, the same
frozen values ``snapshot()`` returns on the node itself.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Any, Generic, TypeVar

from rcl_interfaces.msg import ParameterType
from rclpy.node import Node
from rclpy.parameter import parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from rclpy.task import Future

from genparams.runtime.core.changes import Changes
from genparams.runtime.core.entries import (
    expand,
    instantiate,
    open_maps,
    override_keys,
    template_keys,
)
from genparams.runtime.core.errors import RemoteParameterError, RemoteSetError
from genparams.runtime.core.naming import check_prefix, is_entry_key, join_prefix, strip_prefix
from genparams.runtime.core.params_view import ParamsView
from genparams.runtime.core.problems import READ_ONLY, ParameterProblem, render_problems
from genparams.runtime.core.spec import CompiledParam, compile_schema
from genparams.runtime.core.suggest import did_you_mean
from genparams.runtime.core.tree import build_tree
from genparams.runtime.core.types import ValueTypeError
from genparams.runtime.node.declaring import ros_parameter
from genparams.runtime.remote.typed_future import TypedFuture

if TYPE_CHECKING:
    from genparams.runtime.remote.watch import RemoteWatch

P = TypeVar("P", bound=ParamsView)
_NOT_SET = ParameterType.PARAMETER_NOT_SET


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
        self.client = AsyncParameterClient(node, self.target)

    def __repr__(self) -> str:
        prefix = f", prefix={self.prefix!r}" if self.prefix else ""
        return f"{self.params_cls.__name__}.remote({self.target!r}{prefix})"

    def full_name(self, name: str) -> str:
        return join_prefix(self.prefix, name)

    def relative_name(self, full_name: str) -> str | None:
        return strip_prefix(self.prefix, full_name)

    def wait_for_services(self, timeout_sec: float | None = None) -> bool:
        """Block until the target's parameter services answer; False after ``timeout_sec``."""
        return bool(self.client.wait_for_services(timeout_sec=timeout_sec))

    def get(self) -> TypedFuture[P]:
        """Every parameter of the schema as a frozen snapshot: the fixed ones in one request,
        then (for mapped groups) the entries their key lists name and the parameters whose
        condition (``when``) holds, in a second."""
        result: TypedFuture[P] = TypedFuture()
        parameters = self.compiled.parameters
        conditional = {n: p for n, p in parameters.items() if p.spec.when}
        fixed = {n: p for n, p in parameters.items() if n not in conditional}

        def fixed_read(values: dict[str, Any]) -> None:
            opened = open_maps(self.compiled)
            if opened:  # open groups: their keys are the names declared under them
                prefixes = [self.full_name(path) for path in opened]
                self.client.list_parameters(prefixes, 0, lambda found: listed(values, found))
            else:
                entries_read(values, {})

        def listed(values: dict[str, Any], response_future: Future) -> None:
            try:
                names = (self.relative_name(n) for n in response_future.result().result.names)
                keys, _ = override_keys(self.compiled, [n for n in names if n], self.full_name)
                entries_read(values, keys)
            except Exception as exc:  # handed to whoever waits on the future
                result.set_exception(exc)

        def entries_read(values: dict[str, Any], keys: Mapping[str, Any]) -> None:
            more = {n: p for n, p in conditional.items() if p.spec.declared_with(values)}
            values.update((n, None) for n in conditional if n not in more)
            if self.compiled.templates:
                more.update(expand(self.compiled, {**values, **keys}))
            if not more:
                result.set_result(self.snapshot(values))
                return
            self.read(
                more, lambda extra: result.set_result(self.snapshot({**values, **extra})), result
            )

        self.read(fixed, fixed_read, result)
        return result

    def read(
        self,
        parameters: Mapping[str, CompiledParam],
        then: Callable[[dict[str, Any]], None],
        result: Future,
    ) -> None:
        """Read ``parameters``, hand their typed values to ``then``; failures go to ``result``."""
        names = list(parameters)
        full_names = [self.full_name(name) for name in names]

        def answered(response_future: Future) -> None:
            try:
                messages = response_future.result().values
                if len(messages) != len(names):
                    # The service answers nothing at all when one name is not declared, or
                    # not set (an optional parameter): the types tell which.
                    if any(param.spec.optional for param in parameters.values()):
                        self.client.get_parameter_types(full_names, typed)
                    else:
                        self.client.list_parameters([], 0, report_missing)
                    return
                values: dict[str, Any] = {}
                problems: list[ParameterProblem] = []
                for name, full, message in zip(names, full_names, messages, strict=True):
                    try:
                        python = parameter_value_to_python(message)
                        values[name] = parameters[name].from_ros(python)
                    except ValueTypeError as exc:
                        problems.append(ParameterProblem(full, str(exc)))
                if problems:
                    raise self.not_following(problems)
                then(values)
            except Exception as exc:  # handed to whoever waits on the future
                result.set_exception(exc)

        def typed(response_future: Future) -> None:
            try:
                types = response_future.result().types
                if len(types) != len(names):
                    self.client.list_parameters([], 0, report_missing)
                    return
                unset = [n for n, t in zip(names, types, strict=True) if t == _NOT_SET]
                refused = [self.full_name(n) for n in unset if not parameters[n].spec.optional]
                if refused:
                    raise self.not_following(
                        [ParameterProblem(full, "not set") for full in refused]
                    )
                rest = {n: p for n, p in parameters.items() if n not in unset}
                nones = dict.fromkeys(unset)
                if rest:
                    self.read(rest, lambda values: then({**nones, **values}), result)
                else:
                    then(nones)
            except Exception as exc:
                result.set_exception(exc)

        def report_missing(response_future: Future) -> None:
            try:
                declared = set(response_future.result().result.names)
                missing = [
                    ParameterProblem(full, "not declared")
                    for full in full_names
                    if full not in declared
                ]
                result.set_exception(self.not_following(missing))
            except Exception as exc:
                result.set_exception(exc)

        self.client.get_parameters(full_names, answered)

    def not_following(self, problems: list[ParameterProblem]) -> RemoteParameterError:
        return RemoteParameterError(
            f"{self.target} does not follow {self.compiled.spec.name}: " + render_problems(problems)
        )

    def snapshot(self, values: Mapping[str, Any]) -> P:
        spec = self.compiled.spec
        return build_tree(
            self.params_cls, spec.groups, values, extra={"_binding": None}, maps=spec.maps
        )

    def parameter(self, name: str) -> CompiledParam | None:
        """The fixed parameter ``name`` (or an old name of it), or the mapped entry it names
        (``gains.elbow.p``)."""
        param = self.compiled.parameters.get(self.compiled.aliases.get(name, name))
        if param is not None:
            return param
        for template in self.compiled.templates.values():
            keys = template_keys(template.name, name)
            if keys is not None and all(is_entry_key(key) for key in keys):
                return instantiate(template, keys)
        return None

    def set(self, values: Mapping[str, Any]) -> TypedFuture[None]:
        """Set ``values`` (relative ROS names -> values) atomically: all of them or none.

        A value the schema rejects fails the future at once, with nothing sent
        (``RemoteSetError.sent`` is False). A rejection by the node fails it with
        the node's reason (a ``configure_only`` parameter of an active lifecycle
        node, a rule that reads values not being set). Doubles may be given as
        ints, arrays as lists; an old name (alias) sets the current one.
        """
        result: TypedFuture[None] = TypedFuture()
        typed, reasons = self.check(values)
        if reasons:
            result.set_exception(RemoteSetError.before_sending(reasons))
            return result
        parameters = [
            ros_parameter(param, self.full_name(param.name), value)
            for param, value in typed.values()
        ]

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

    def check(
        self, values: Mapping[str, Any]
    ) -> tuple[dict[str, tuple[CompiledParam, Any]], list[ParameterProblem]]:
        """Typed values and the problems the schema finds with them, worded as the node words
        them."""
        typed: dict[str, tuple[CompiledParam, Any]] = {}
        reasons: list[ParameterProblem] = []
        for name, value in values.items():
            param = self.parameter(name)
            if param is None:
                known = sorted([*self.compiled.parameters, *self.compiled.templates])
                hint = did_you_mean(name, known)
                reasons.append(
                    ParameterProblem(name, f"no such parameter in {self.compiled.spec.name}{hint}")
                )
                continue
            reason = _check_one(param, value)
            if isinstance(reason, str):
                reasons.append(ParameterProblem(self.full_name(name), reason))
            else:
                typed[param.name] = (param, reason[0])
        if reasons:
            return typed, reasons
        proposed = {name: value for name, (_, value) in typed.items()}
        for rule in self.compiled.rules:
            if all(name in proposed for name in rule.parameters):
                broken = rule.violation(proposed, self.full_name)
                if broken is not None:
                    reasons.append(ParameterProblem("", broken))
        return typed, reasons

    def watch(self, callback: Callable[[Changes[P]], None]) -> RemoteWatch[P]:
        """Call ``callback`` with the typed changes of each accepted set on the target.

        Returns a handle: ``ready`` resolves to the first snapshot (every change
        from there on is reported), ``latest`` is the newest known snapshot, and
        ``cancel()`` stops watching. The client node must be spun by an executor.
        """
        from genparams.runtime.remote.watch import RemoteWatch

        return RemoteWatch(self, callback)


def _check_one(param: CompiledParam, value: Any) -> str | tuple[Any]:
    if param.spec.read_only:
        return READ_ONLY
    try:
        typed = param.type.coerce_default(value)
    except ValueTypeError as exc:
        return str(exc)
    reason = param.check(typed)
    return reason if reason is not None else (typed,)
