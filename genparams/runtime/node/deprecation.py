"""Deprecation warnings: a deprecated parameter or an old name, reported once each."""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping, Sequence

from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime.core.spec import CompiledParam, CompiledSchema


class Notices:
    """Warns on the node's logger, once per parameter name for the life of the binding."""

    def __init__(self, node: Node) -> None:
        self.node = node
        self.warned: set[str] = set()
        self.lock = threading.Lock()

    def _once(self, name: str, message: str) -> None:
        with self.lock:
            if name in self.warned:
                return
            self.warned.add(name)
        self.node.get_logger().warning(message)

    def deprecated(self, full_name: str, reason: str) -> None:
        self._once(full_name, f"parameter {full_name!r} is deprecated: {reason}")

    def renamed(self, old_name: str, full_name: str) -> None:
        self._once(
            old_name,
            f"parameter {old_name!r} is deprecated: it was renamed to {full_name!r}; "
            f"use {full_name!r}",
        )


def report_overrides(
    notices: Notices,
    parameters: Mapping[str, CompiledParam],
    given: Sequence[str],
    renamed: Sequence[tuple[str, str]],
    full_name: Callable[[str], str],
) -> None:
    """Warn for the deprecated parameters and old names a node was started with."""
    for name in given:
        reason = parameters[name].spec.deprecated
        if reason:
            notices.deprecated(full_name(name), reason)
    for old_name, current in renamed:
        notices.renamed(old_name, current)


class DeprecationWatch:
    """A post-set callback: warns when an accepted change sets a deprecated parameter."""

    def __init__(self, notices: Notices, owned: Mapping[str, CompiledParam]) -> None:
        self.notices = notices
        self.owned = owned  # the binding's table, which grows and shrinks with mapped groups

    @classmethod
    def attach(
        cls,
        node: Node,
        notices: Notices,
        owned: Mapping[str, CompiledParam],
        schema: CompiledSchema,
    ) -> None:
        every = (*schema.parameters.values(), *schema.templates.values())
        if any(param.spec.deprecated for param in every):
            node.add_post_set_parameters_callback(cls(notices, owned).on_post_set)

    def on_post_set(self, parameters: Sequence[Parameter]) -> None:
        for parameter in parameters:
            param = self.owned.get(parameter.name)
            if param is not None and param.spec.deprecated:
                self.notices.deprecated(parameter.name, param.spec.deprecated)
