"""One commit discipline per node: sets serialized, validated last, committed once, in order.

rclpy takes no lock around setting parameters, and its callbacks may set parameters
themselves. ``Node._set_parameters_atomically_common`` runs every on-set callback
(validation), stores the values, publishes the parameter event and then calls the
post-set callbacks, newest first. Whatever a callback does, genparams keeps four promises:

- Sets on one node run one after the other. One re-entrant lock per node is taken
  around the common set path and released in the same frame, so a veto, an
  exception or a callback that sets parameters (same thread, re-entrant) can never
  leave it held. Two threads can no longer both validate against the same state and
  then both store a pair of values that breaks a rule together.
- Validation sees the node's current state. genparams' check is one on-set callback
  that runs after every other one (even ones added later): a set that another
  on-set callback starts from inside the round has been stored and committed
  before genparams checks the outer request.
- Each accepted set is committed exactly once, with its own values, right after the
  node stored them and before any post-set callback runs. Every set is one *frame*
  on a stack: the check records its typed values in the frame, and the commit reads
  them from the frame of the request being committed. A set nested in a post-set
  callback or an ``on_change`` subscriber is a frame of its own, committed when the
  node stores it, so the outer commit, which already happened, can never overwrite it.
- ``on_change`` deliveries follow the node's order of changes. Commits append their
  deliveries to one queue per node; the outermost set drains it before it returns,
  and a set started by a subscriber appends behind the delivery being made.

Hence: when the outermost set returns, every parameter a class owns equals its
typed view, and each subscriber has seen every change, in order. Reads
(``get_parameter``, the typed view, snapshots) never wait. ``declare`` holds the
lock from reading the overrides to registering its class, so no set slips in
between a parameter's declaration and its validation. Holding
``parameter_set_lock(node)`` gives a moment where no change is in progress.
"""

from __future__ import annotations

import collections
import threading
from collections.abc import Callable, MutableMapping, Sequence
from typing import TYPE_CHECKING, Any, Protocol

from rcl_interfaces.msg import SetParametersResult
from rclpy.exceptions import ParameterImmutableException, ParameterNotDeclaredException
from rclpy.parameter import Parameter

from genparams.runtime.core.errors import GenparamsError
from genparams.runtime.core.problems import ParameterProblem, render_problem, render_problems
from genparams.runtime.node import rclpy_internals as internals
from genparams.runtime.node.rewrites import Rewrite, typed_empty_arrays

if TYPE_CHECKING:
    from rclpy.node import Node

    from genparams.runtime.core.spec import CompiledParam

_ATTRIBUTE = "_genparams_sets"
_INSTALLING = threading.Lock()
_ACCEPTED = SetParametersResult(successful=True)


class DeclaredClass(Protocol):
    """What the coordinator asks of each class declared on the node (``binding.Binding``)."""

    @property
    def schema_name(self) -> str: ...
    @property
    def prefix(self) -> str: ...
    @property
    def live(self) -> object:
        """The view its user holds."""

    def declares(self, full_name: str) -> bool:
        """``full_name`` is one of its parameters, or an old name of one."""

    def check(
        self, parameters: Sequence[Parameter], declaring: bool
    ) -> dict[CompiledParam, Any] | list[ParameterProblem]:
        """Its part of a request, typed, or the problems it is refused for."""

    def commit(self, updates: dict[CompiledParam, Any]) -> bool:
        """Commit values the node stored; False (nothing done) when they change its shape."""

    def reshape(self, updates: dict[CompiledParam, Any]) -> None:
        """Commit values that change its shape (mapped keys), once every class committed."""

    def refusals(self, parameters: Sequence[Parameter]) -> list[ParameterProblem]:
        """Why it refuses each of its values in a request on its own: read-only, type, rules."""

    def undeclared_entries(self, parameters: Sequence[Parameter]) -> list[ParameterProblem]:
        """A problem per entry of its mapped groups the request names that is not declared."""


class UndeclareRefusedError(ParameterImmutableException, GenparamsError):
    """``node.undeclare_parameter`` of a parameter a genparams class declares.

    A ParameterImmutableException, as rclpy raises for a read-only parameter, so
    code that handles rclpy's refusal handles this one.
    """

    def __init__(self, name: str, schema: str) -> None:
        refusal = ParameterProblem(
            name,
            f"cannot be undeclared: {schema} declares it and its typed view would "
            "keep the value (parameter services refuse it the same way)",
        )
        Exception.__init__(self, render_problem(refusal))
        self.name = name


class UndeclaredEntryError(ParameterNotDeclaredException, GenparamsError):
    """A set naming an entry of a mapped group whose key is not in its key list.

    rclpy's ``ParameterNotDeclaredException`` (the parameter services answer it as a
    refused set, as they answer rclpy's), with genparams' reason naming each entry.
    """

    def __init__(self, reason: str) -> None:
        Exception.__init__(self, reason)


# One set in progress on the node: whether it declares (declarations and entry changes
# carry new descriptors), and what genparams' check accepted, per binding. A tuple, not
# a class: one is made on every set, and a class's __init__ costs about four times more.
Frame = tuple[bool, dict[DeclaredClass, dict["CompiledParam", Any]]]


Delivery = Callable[[], None]


class NodeSets:
    """The per-node coordinator: lock, frames, the bindings in declaration order, deliveries."""

    def __init__(self, node: Node) -> None:
        self.node = node
        self.lock = threading.RLock()
        self.bindings: list[DeclaredClass] = []
        self.frames: list[Frame] = []
        self.deliveries: collections.deque[Delivery] = collections.deque()
        self.draining = False
        # Full names -> array parameters, of every class that has any: an empty array in
        # a request takes its declared type before rclpy checks it (rewrites.py).
        self.arrays: collections.ChainMap[str, CompiledParam] = collections.ChainMap()
        self.retype: Rewrite | None = None
        self.renames: tuple[Rewrite, ...] = ()  # old names mirrored, one per class that has any
        self.explaining = False  # undeclared mapped entries are refused by name
        self.unlocked_set = internals.set_path(node)
        self.run_post_set = internals.post_set_caller(node)
        self.undeclare = internals.replace_undeclare(node, self.undeclare_checked)
        internals.replace_set_path(node, self.set_serialized)
        internals.replace_post_set_caller(node, self.commit_then_post_set)
        internals.add_last_on_set_callback(node, self.check)

    # rclpy's own signature, spelled out: packing *args and **kwargs costs on every set.
    def set_serialized(
        self, parameter_list: Any, descriptors: Any = None, allow_not_set_type: bool = False
    ) -> SetParametersResult:
        with self.lock:
            retype = self.retype
            if retype is not None:
                parameter_list = retype(parameter_list)
            declaring = descriptors is not None
            requested = parameter_list
            if self.renames and not declaring:
                for rename in self.renames:
                    parameter_list = rename(parameter_list)
            frames = self.frames
            frames.append((declaring, {}))
            try:
                result: SetParametersResult = self.unlocked_set(
                    parameter_list, descriptors, allow_not_set_type
                )
                if not result.successful and not declaring:
                    result = self.in_own_words(requested, parameter_list, result)
            finally:
                frames.pop()
                if not frames and self.deliveries and not self.draining:
                    self.drain()
            return result

    def add_renames(self, rename: Rewrite) -> None:
        """Pass every set (not declarations) through ``rename`` once rclpy checked its items."""
        self.renames = (*self.renames, rename)

    def in_own_words(
        self, requested: list[Parameter], checked: list[Parameter], refused: SetParametersResult
    ) -> SetParametersResult:
        """A set rclpy's descriptor check refused for a value a class owns: the classes'
        reasons instead (parameter, rule and value) for the values as requested (an old
        name, not the current name it was mirrored onto), found by the checks of their
        on-set callback. Any other refusal is passed on as it came."""
        first = internals.first_descriptor_refusal(self.node, checked)
        if first is None or self.owner_of(first) is None:
            return refused
        problems = [problem for b in self.bindings for problem in b.refusals(requested)]
        if not problems:  # cannot happen (tests compare both verdicts); rclpy's word holds
            return refused
        return SetParametersResult(successful=False, reason=render_problems(problems))

    def retype_empty_arrays(self, declared: MutableMapping[str, CompiledParam]) -> None:
        """Give an empty array set on any of ``declared`` (full name -> parameter, read at
        each set) the parameter's declared array type."""
        self.arrays.maps.append(declared)
        self.retype = typed_empty_arrays(self.arrays)

    def check(self, parameters: Sequence[Parameter]) -> SetParametersResult:
        """genparams' on-set callback, run after every other one: each class checks its part."""
        declaring, accepted = self.frames[-1]
        reasons: list[ParameterProblem] = []
        for binding in self.bindings:
            outcome = binding.check(parameters, declaring)
            if isinstance(outcome, list):
                reasons.extend(outcome)
            elif outcome:
                accepted[binding] = outcome
        if reasons:
            return SetParametersResult(successful=False, reason=render_problems(reasons))
        return _ACCEPTED

    def commit_then_post_set(self, parameters: Sequence[Parameter]) -> None:
        """The node stored ``parameters``: commit each class's part, then run post-set callbacks."""
        accepted = self.frames[-1][1]
        if accepted:
            reshaping = []
            for binding, updates in accepted.items():
                if not binding.commit(updates):
                    reshaping.append((binding, updates))
            # Entries are declared and undeclared in a set of their own, once every
            # class holds what the node stored.
            for binding, updates in reshaping:
                binding.reshape(updates)
        self.run_post_set(parameters)

    def deliver(self, delivery: Delivery) -> None:
        self.deliveries.append(delivery)

    def drain(self) -> None:
        self.draining = True
        try:
            while self.deliveries:
                self.deliveries.popleft()()
        finally:
            self.draining = False

    def owner_of(self, full_name: str) -> DeclaredClass | None:
        for binding in self.bindings:
            if binding.declares(full_name):
                return binding
        return None

    def explain_undeclared_entries(self) -> None:
        """Refuse a set of an undeclared mapped entry naming it, not in rclpy's words only.

        rclpy checks that a set names declared parameters after its pre-set callbacks,
        outside the lock, and its message names none of them (it consumes the names it
        reports); its check still runs first and decides, genparams words its refusal.
        """
        if self.explaining:
            return
        self.explaining = True
        rclpy_check = internals.declared_check(self.node)

        def check_declared(parameter_list: list[Parameter]) -> None:
            try:
                rclpy_check(parameter_list)
            except ParameterNotDeclaredException as exc:
                entries = [p for b in self.bindings for p in b.undeclared_entries(parameter_list)]
                if not entries:
                    raise
                named = {problem.key for problem in entries}
                reason = render_problems(entries)
                node = self.node
                if any(
                    p.name not in named and not node.has_parameter(p.name) for p in parameter_list
                ):
                    reason = f"{reason}; {exc}"  # other undeclared names, in rclpy's words
                raise UndeclaredEntryError(reason) from None

        internals.replace_declared_check(self.node, check_declared)

    def undeclare_checked(self, name: str) -> None:
        """``node.undeclare_parameter``, refused for what a class declares, as the services are."""
        with self.lock:
            owner = self.owner_of(name)
            if owner is not None:
                raise UndeclareRefusedError(name, owner.schema_name)
            self.undeclare(name)


def node_sets(node: Node) -> NodeSets:
    """The coordinator of ``node``; installed on first use."""
    sets: NodeSets | None = getattr(node, _ATTRIBUTE, None)
    if sets is not None:
        return sets
    with _INSTALLING:
        sets = getattr(node, _ATTRIBUTE, None)
        if sets is None:
            sets = NodeSets(node)
            setattr(node, _ATTRIBUTE, sets)
    return sets


def parameter_set_lock(node: Node) -> threading.RLock:
    """The lock that serializes parameter changes on ``node``."""
    return node_sets(node).lock
