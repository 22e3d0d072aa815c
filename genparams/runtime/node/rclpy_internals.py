"""Every private rclpy attribute or behaviour genparams relies on, in one place.

Checked against rclpy 7.1 (ROS 2 Jazzy). rclpy offers no public hook for what
follows; each use says why it is needed. ``tests/runtime/test_rclpy_internals.py``
checks every one of them against the installed rclpy, so an rclpy release that
changes one fails there, loudly, rather than as a silent desync elsewhere.

Behaviours relied on (rclpy 7.1, ``rclpy/node.py``):

- ``Node._set_parameters_atomically_common(parameter_list, descriptors=None,
  allow_not_set_type=False)`` is the one path every set, atomic set, parameter
  service request and declaration goes through. It runs the on-set callbacks,
  stores the values, publishes the parameter event, then calls
  ``Node._call_post_set_parameters_callback(parameter_list)`` once.
- ``Node._on_set_parameters_callbacks`` is a list run front to back;
  ``add_on_set_parameters_callback`` inserts at the front, so newer callbacks
  run first and a callback appended at the end runs after every other one.
- ``Node._post_set_parameters_callbacks`` likewise: newest first.
- Pre-set callbacks run in ``Node._set_parameters_atomically`` before the
  common path, so outside genparams' per-node lock; then
  ``Node._check_undeclared_parameters(parameter_list)`` raises ``TypeError`` for
  an item that is no Parameter and ``ParameterNotDeclaredException`` for an
  undeclared name, before the common path.
- ``Node._descriptors``: the node's descriptors by name, which the common path
  checks each value against first (``_apply_descriptor``), refusing at the first
  value that fails.
- ``Node.undeclare_parameter`` deletes from ``_parameters`` and ``_descriptors``
  without calling any callback (and refuses a read-only parameter).
- ``Node._parameter_event_publisher`` publishes the node's ParameterEvents.
- ``Node._declare_parameter_common`` runs one whole set round per parameter;
  ``_set_parameters_atomically_common(parameters, descriptors,
  allow_not_set_type=True)`` is that same round for many parameters at once.
- ``Node._parameter_overrides``: the values a node was started with.
- ``Node._check_undeclared_parameters(parameter_list)`` refuses a set naming
  undeclared parameters; it reads ``_parameters`` and
  ``_allow_undeclared_parameters`` only (its message leaves out the first name).
- ``Node._apply_descriptor(parameter, descriptor, check_read_only)`` is rclpy's
  check of a value against a descriptor (read-only, type, range and step), the
  first check of every set; given a descriptor it reads nothing of the node.
- ``rclpy.lifecycle.Node._state_machine.current_state`` is ``(id, label)``.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping, Sequence
from types import SimpleNamespace
from typing import Any

from rcl_interfaces.msg import ParameterDescriptor, ParameterEvent, SetParametersResult
from rclpy.exceptions import ParameterNotDeclaredException
from rclpy.node import Node
from rclpy.parameter import Parameter

RCLPY_CHECKED = "7.1"  # the rclpy release (Jazzy) these internals were read in

SetPath = Callable[..., SetParametersResult]
PostSet = Callable[[Sequence[Parameter]], None]
OnSet = Callable[[list[Parameter]], SetParametersResult]


def set_path(node: Node) -> SetPath:
    """The node's common set path (bound method, or a wrapper already installed)."""
    return node._set_parameters_atomically_common


def replace_set_path(node: Node, wrapper: SetPath) -> None:
    """Route every set of ``node`` through ``wrapper``; an instance attribute shadows the method."""
    node._set_parameters_atomically_common = wrapper  # type: ignore[method-assign]


def post_set_caller(node: Node) -> PostSet:
    """What the set path calls once the node stored the values: it runs the post-set callbacks."""
    return node._call_post_set_parameters_callback


def replace_post_set_caller(node: Node, wrapper: PostSet) -> None:
    node._call_post_set_parameters_callback = wrapper  # type: ignore[method-assign, assignment]


def add_last_on_set_callback(node: Node, callback: OnSet) -> None:
    """Run ``callback`` after every other on-set callback, including ones added later."""
    node._on_set_parameters_callbacks.append(callback)


def on_set_callbacks(node: Node) -> tuple[OnSet, ...]:
    callbacks: list[OnSet] = list(node._on_set_parameters_callbacks)
    return tuple(callbacks)


def replace_undeclare(node: Node, wrapper: Callable[[str], None]) -> Callable[[str], None]:
    """Shadow ``node.undeclare_parameter`` (which runs no callback); returns the original."""
    original: Callable[[str], None] = node.undeclare_parameter
    node.undeclare_parameter = wrapper  # type: ignore[method-assign, assignment]
    return original


def declare_with_descriptors(
    node: Node, parameters: Sequence[Parameter], descriptors: Mapping[str, ParameterDescriptor]
) -> SetParametersResult:
    """Declare new parameters with exact types in one atomic round of the common set path:
    rclpy's ``_declare_parameter_common`` runs this same round once per parameter, and
    ``Node.declare_parameters`` infers the type from the value (an empty list becomes
    BYTE_ARRAY); this path keeps the declared one. The round's result, not an exception."""
    return set_path(node)(list(parameters), dict(descriptors), True)


def forget_declared(node: Node, names: Collection[str]) -> None:
    """Undeclare ``names`` as ``Node.undeclare_parameter`` does (no callback runs; read-only
    ones too, which that refuses), and announce them deleted in one ParameterEvent, as the
    set path announces a parameter it undeclares. Names the node does not hold are skipped."""
    stored, descriptors = node._parameters, node._descriptors
    event = ParameterEvent(node=node.get_fully_qualified_name())
    for name in names:
        parameter = stored.pop(name, None)
        descriptors.pop(name, None)
        if parameter is not None:
            event.deleted_parameters.append(parameter.to_parameter_msg())
    publisher = node._parameter_event_publisher
    if event.deleted_parameters and publisher is not None:
        event.stamp = node.get_clock().now().to_msg()
        publisher.publish(event)


def set_with_descriptors(
    node: Node, parameters: Sequence[Parameter], descriptors: Mapping[str, ParameterDescriptor]
) -> SetParametersResult:
    """One atomic change that may declare (new descriptors) and undeclare (NOT_SET) together."""
    return set_path(node)(list(parameters), dict(descriptors))


def declared_check(node: Node) -> Callable[[list[Parameter]], None]:
    """rclpy's check, before the common set path, that a set names declared parameters."""
    check: Callable[[list[Parameter]], None] = node._check_undeclared_parameters
    return check


def replace_declared_check(node: Node, wrapper: Callable[[list[Parameter]], None]) -> None:
    node._check_undeclared_parameters = wrapper  # type: ignore[method-assign, assignment]


def first_descriptor_refusal(node: Node, parameters: Sequence[Parameter]) -> str | None:
    """The name of the first value of a set the common path's descriptor check refuses, as
    it runs it (the node's descriptors, read-only checked); None if it refuses none."""
    descriptors = node._descriptors
    for parameter in parameters:
        descriptor = descriptors.get(parameter.name)
        if descriptor is not None and not descriptor_check(node, parameter, descriptor).successful:
            name: str = parameter.name
            return name
    return None


def descriptor_check(
    node: Node, parameter: Parameter, descriptor: ParameterDescriptor, read_only: bool = True
) -> SetParametersResult:
    """rclpy's own verdict on setting ``parameter`` under ``descriptor``, without setting it.

    The tuning page checks a value as the node would; any rclpy node runs the
    check, since with a descriptor given it reads nothing of its own state.
    """
    result: SetParametersResult = node._apply_descriptor(parameter, descriptor, True)
    return result


def undeclared_check(parameters: Sequence[Parameter], declared: Collection[str]) -> str | None:
    """rclpy's refusal, in its own words, of a set naming parameters not in ``declared``
    (on a node that allows no undeclared parameters), or None."""
    holder = SimpleNamespace(
        _parameters=dict.fromkeys(declared), _allow_undeclared_parameters=False
    )
    try:
        Node._check_undeclared_parameters(holder, list(parameters))  # type: ignore[arg-type]
    except ParameterNotDeclaredException as exc:
        return str(exc)
    return None


def parameter_overrides(node: Node) -> dict[str, Parameter]:
    """The values the node was started with (-p, params files, launch)."""
    overrides: dict[str, Parameter] = getattr(node, "_parameter_overrides", {})
    return overrides


def lifecycle_state(node: Node) -> str | None:
    """The label of a lifecycle node's current state ("inactive", ...); None for a plain node."""
    machine: Any = getattr(node, "_state_machine", None)
    if machine is None:
        return None
    return str(machine.current_state[1])
