"""One parameter change at a time per node: validation, storage and commit as one step.

rclpy takes no lock around setting parameters. ``Node._set_parameters_atomically_common``
runs every on-set callback (validation), stores the values, publishes the parameter
event and then runs the post-set callbacks (where genparams commits to the typed view).
Two threads (a MultiThreadedExecutor serving the parameter services, application
threads calling ``set_parameters``) can both validate against the same state and then
both store: each change alone keeps a rule such as ``min_speed <= max_speed``, the two
together break it, and the view could commit them in another order than the node
stored them.

Three designs were weighed:

- Lock in the on-set callback, unlock in the post-set callback. rclpy runs the post-set
  callbacks only when every on-set callback accepted. An on-set callback that runs after
  ours (rclpy runs later-added callbacks first, so one added before ``declare``) and
  vetoes means post-set never runs: the lock stays held and the next set deadlocks.
- Validate optimistically and check again at commit. By then the node has stored the
  values; a commit that finds a rule broken can no longer refuse them.
- Serialize the whole call (chosen). ``_set_parameters_atomically_common`` is the one
  path that every ``set_parameters``, ``set_parameters_atomically``, parameter service
  request and declaration goes through. Each node gets one re-entrant lock around it,
  taken and released in the same frame, so a veto, an exception or a callback that sets
  parameters itself (same thread, re-entrant) can never leave it held.

What follows from it:

- Sets on one node run one after the other. They are short (callbacks, a dict update,
  one publish); reads (``get_parameter``, the typed view, snapshots) never wait.
- When a set returns, the node and every view agree; ``on_change`` subscribers run
  inside the set, so they are called one at a time, in commit order. A subscriber may
  set parameters itself, but must not wait for another thread that sets parameters on
  the same node.
- ``declare`` holds the lock from reading the overrides to registering its callbacks,
  so no set can slip in between a parameter's declaration and its validation.
- Holding ``parameter_set_lock(node)`` gives a moment where no change is in progress:
  node values and views can be read together consistently.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rclpy.node import Node

_ATTRIBUTE = "_genparams_set_lock"
_INSTALLING = threading.Lock()


def parameter_set_lock(node: Node) -> threading.RLock:
    """The lock that serializes parameter changes on ``node``; installed on first use."""
    lock: threading.RLock | None = getattr(node, _ATTRIBUTE, None)
    if lock is not None:
        return lock
    with _INSTALLING:
        lock = getattr(node, _ATTRIBUTE, None)
        if lock is None:
            lock = threading.RLock()
            _serialize_sets(node, lock)
            setattr(node, _ATTRIBUTE, lock)
    return lock


def _serialize_sets(node: Node, lock: threading.RLock) -> None:
    unlocked = node._set_parameters_atomically_common

    # rclpy's own signature, spelled out: packing *args and **kwargs costs on every set.
    def set_parameters_serialized(
        parameter_list: Any, descriptors: Any = None, allow_not_set_type: bool = False
    ) -> Any:
        with lock:
            return unlocked(parameter_list, descriptors, allow_not_set_type)

    # An instance attribute shadows the method for this node only.
    node._set_parameters_atomically_common = set_parameters_serialized  # type: ignore[method-assign]
