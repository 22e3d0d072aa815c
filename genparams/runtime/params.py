"""The base class of every generated top-level class: declare, read, snapshot, subscribe."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Any, ClassVar, Self

from genparams.runtime.changes import Changes
from genparams.runtime.entries import flatten, resolve_all
from genparams.runtime.errors import DetachedSnapshotError, ParameterDeclarationError
from genparams.runtime.problems import ParameterProblem
from genparams.runtime.spec import SchemaSpec, compile_schema
from genparams.runtime.tree import Group, build_tree, to_dict

if TYPE_CHECKING:
    from rclpy.node import Node

    from genparams.runtime.binding import Binding
    from genparams.runtime.remote import RemoteParams


class Params(Group):
    """Typed, live view of a node's parameters (after ``declare``), or a frozen snapshot."""

    __slots__ = ("_binding",)
    _binding: Binding[Self] | None
    _DETACHED = ("_binding",)  # a copy or an unpickled value is a snapshot
    _SPEC: ClassVar[SchemaSpec]

    @classmethod
    def declare(cls, node: Node, prefix: str = "", *, publish_schema: bool = True) -> Self:
        """Declare every parameter on ``node`` (under ``prefix``) and return the live view.

        Raises ParameterDeclarationError listing every invalid or missing
        override; in that case nothing is declared. With ``publish_schema`` the
        node describes itself on ``~/genparams/schema`` (a latched std_msgs/String
        of JSON, merged over every class declared on the node).
        """
        from genparams.runtime.binding import Binding

        live = Binding.declare(cls, node, prefix).live
        if publish_schema:
            from genparams.runtime.schema_topic import publish_schema as publish

            publish(node, compile_schema(cls._SPEC), prefix)
        return live

    @classmethod
    def remote(cls, node: Node, target: str, prefix: str = "") -> RemoteParams[Self]:
        """A typed async client for ``target`` (e.g. "/ns/node"), which declares this class.

        ``node`` makes the service calls and must be spun by an executor.
        ``get()``, ``set({...})`` and ``watch(callback)`` return rclpy Futures or a
        handle; ``set`` checks the values against the schema before sending.
        """
        from genparams.runtime.remote import RemoteParams

        return RemoteParams(cls, node, target, prefix)

    @classmethod
    def defaults(cls, overrides: Mapping[str, Any] | None = None) -> Self:
        """A snapshot of the defaults plus ``overrides``, without ROS.

        ``overrides`` maps ROS names to values, dotted (``{"camera.fps": 5.0}``),
        nested as ``to_dict()`` returns them, or both. Values are typed as schema
        defaults are: a double may be given as an int. An old name (alias)
        stands for the current one, as it does in a params file.
        """
        compiled = compile_schema(cls._SPEC)
        given = {compiled.aliases.get(n, n): v for n, v in flatten(overrides or {}).items()}
        parameters, values, problems = resolve_all(
            compiled,
            lambda names: {n: given[n] for n in names if n in given},
            source="value",
            lenient=True,
            given_names=given,
        )
        unknown = sorted(set(given) - set(parameters))
        every = compiled.parameters
        problems.extend(
            ParameterProblem(
                name, every[name].spec.condition_text if name in every else "no such parameter"
            )
            for name in unknown
        )
        if problems:
            raise ParameterDeclarationError(
                cls._SPEC.name, f"{cls.__name__}.defaults()", problems, doing="build"
            )
        spec = cls._SPEC
        return build_tree(cls, spec.groups, values, extra={"_binding": None}, maps=spec.maps)

    def snapshot(self) -> Self:
        """A frozen, consistent view of every value, O(1) whatever the number of parameters."""
        binding = self._binding
        return self if binding is None else binding.current

    def on_change(self, callback: Callable[[Changes[Self]], None]) -> Callable[[], None]:
        """Call ``callback`` after each accepted change of parameters this class owns.

        Returns a function that unsubscribes.
        """
        binding = self._binding
        if binding is None:
            raise DetachedSnapshotError(
                "on_change needs the live view returned by declare(), not a snapshot"
            )
        return binding.subscribe(callback)

    def to_dict(self) -> dict[str, Any]:
        """Every value as a nested dict keyed by ROS names."""
        return to_dict(self)
