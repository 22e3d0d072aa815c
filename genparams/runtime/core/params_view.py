"""What a generated top-level class is without ROS: defaults, snapshots, subscriptions, dicts.

``genparams.runtime.Params`` adds what needs a node (``declare``, ``remote``); the
node binding and the remote client build and type views against this class.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any, ClassVar, Protocol, Self, TypeVar

from genparams.runtime.core.changes import Changes
from genparams.runtime.core.entries import flatten, resolve_all
from genparams.runtime.core.errors import DetachedSnapshotError, ParameterDeclarationError
from genparams.runtime.core.problems import ParameterProblem
from genparams.runtime.core.spec import SchemaSpec, compile_schema
from genparams.runtime.core.tree import Group, build_tree, to_dict

P = TypeVar("P")


class LiveSource(Protocol[P]):
    """What keeps a live view current (the class declared on a node)."""

    @property
    def current(self) -> P:
        """The newest consistent snapshot."""

    def subscribe(self, callback: Callable[[Changes[P]], None]) -> Callable[[], None]:
        """Call ``callback`` after each accepted change; returns a function that unsubscribes."""


class ParamsView(Group):
    """``Params`` less what needs a node: a live view (after ``declare``) or a frozen snapshot."""

    __slots__ = ("_binding",)
    _binding: LiveSource[Self] | None
    _DETACHED = ("_binding",)  # a copy or an unpickled value is a snapshot
    _SPEC: ClassVar[SchemaSpec]

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
