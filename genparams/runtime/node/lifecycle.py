"""Parameters that change only while a lifecycle node is unconfigured or inactive.

A serial port, an image size or a controller's joint list are read when the
node configures; changing them while it runs would leave the node using the old
value. ``configure_only: true`` in the schema refuses such sets while the node
is active (or on its way there), with a reason that names the state. The
transitions between unconfigured and inactive (configuring, cleaning up) count
as configuration time, so ``on_configure`` may set them. Plain nodes have no
lifecycle state and are unaffected.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Any

from genparams.runtime.core.param_checks import CONFIGURE_ONLY_TEXT
from genparams.runtime.core.problems import ParameterProblem
from genparams.runtime.node.rclpy_internals import lifecycle_state

if TYPE_CHECKING:
    from rclpy.node import Node

    from genparams.runtime.core.spec import CompiledParam

    # The type of ``mutability_problem``, for those that hold it.
    MutabilityCheck = Callable[
        [Node, Mapping[CompiledParam, Any], Callable[[str], str]], list[ParameterProblem]
    ]

CONFIGURE_STATES = frozenset({"unconfigured", "inactive", "configuring", "cleaningup"})


def mutability_problem(
    node: Node, typed: Mapping[CompiledParam, Any], full_name: Callable[[str], str]
) -> list[ParameterProblem]:
    """A problem per configure-only parameter of ``typed`` the node's state forbids setting."""
    names = [param.name for param in typed if param.spec.configure_only]
    if not names:
        return []
    state = lifecycle_state(node)
    if state is None or state in CONFIGURE_STATES:
        return []
    return [
        ParameterProblem(
            full_name(name), f"{CONFIGURE_ONLY_TEXT}; the node is {state} (deactivate it first)"
        )
        for name in names
    ]
