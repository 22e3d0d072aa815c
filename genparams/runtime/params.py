"""The base class of every generated top-level class: declare, read, snapshot, subscribe.

What needs no node is in ``core.params_view``; ``declare`` and ``remote`` import
rclpy on first use, so a generated module imports without ROS.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Self

from genparams.runtime.core.params_view import ParamsView
from genparams.runtime.core.spec import compile_schema

if TYPE_CHECKING:
    from rclpy.node import Node

    from genparams.runtime.remote.client import RemoteParams


class Params(ParamsView):
    """Typed, live view of a node's parameters (after ``declare``), or a frozen snapshot."""

    __slots__ = ()

    @classmethod
    def declare(
        cls, node: Node, prefix: str = "", *, publish_schema: bool = True, warn_unknown: bool = True
    ) -> Self:
        """Declare every parameter on ``node`` (under ``prefix``) and return the live view.

        Raises ParameterDeclarationError listing every invalid or missing
        override; in that case nothing is declared. With ``publish_schema`` the
        node describes itself on ``~/genparams/schema`` (a latched std_msgs/String
        of JSON, merged over every class declared on the node). With ``warn_unknown``
        the node warns for what rclpy would ignore in silence (runtime/node/ignored.py).
        """
        from genparams.runtime.node.binding import Binding

        binding = Binding.declare(cls, node, prefix)
        live = binding.live
        if warn_unknown:
            from genparams.runtime.node.ignored import warn_ignored

            warn_ignored(node, prefix, sorted(binding.owned), binding.declares)
        if publish_schema:
            from genparams.runtime.node.schema_topic import publish_schema as publish

            publish(node, compile_schema(cls._SPEC), prefix)
        return live

    @classmethod
    def remote(cls, node: Node, target: str, prefix: str = "") -> RemoteParams[Self]:
        """A typed async client for ``target`` (e.g. "/ns/node"), which declares this class.

        ``node`` makes the service calls and must be spun by an executor.
        ``get()``, ``set({...})`` and ``watch(callback)`` return rclpy Futures or a
        handle; ``set`` checks the values against the schema before sending.
        """
        from genparams.runtime.remote.client import RemoteParams

        return RemoteParams(cls, node, target, prefix)
