"""Values a node was started with (-p, --params-file, launch files), read by relative name."""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable, Mapping
from typing import Any

from rclpy.node import Node
from rclpy.parameter import Parameter

from genparams.runtime.core.problems import ParameterProblem
from genparams.runtime.node.rclpy_internals import parameter_overrides

_MISSING = object()


class OverrideReader:
    """Reads overrides for parameters about to be declared, and collects what it finds.

    An override under an old name (an alias) applies to the current name.
    Parameters the node already declared from overrides
    (``automatically_declare_parameters_from_overrides``) count as overrides and
    are listed in ``predeclared``, to be re-declared with their descriptors.
    So are parameters the schema adopts (``adopt: true``) that other code of
    the node declared first: their current value is read and checked like an
    override, and genparams declares them again with its descriptor.
    """

    def __init__(
        self,
        node: Node,
        full_name: Callable[[str], str],
        old_names: Mapping[str, tuple[str, ...]] | None = None,
        adopted: Collection[str] = (),
    ) -> None:
        self.node = node
        self.adopted = {full_name(name) for name in adopted}
        self.full_name = full_name
        self.old_names = old_names or {}
        # rclpy exposes overrides only through a private attribute.
        self.overrides: dict[str, Parameter] = parameter_overrides(node)
        self.problems: list[ParameterProblem] = []
        self.predeclared: list[str] = []  # full names
        self.renamed: list[tuple[str, str]] = []  # (old full name, full name) an override used
        self.given: list[str] = []  # relative names an override was found for
        self.taken: list[str] = []  # full names other code declared first

    def read(self, names: Iterable[str]) -> dict[str, Any]:
        """ROS-form values given for relative ``names`` (absent when none was given)."""
        given: dict[str, Any] = {}
        for name in names:
            full_name = self.full_name(name)
            value = self._value(full_name)
            for old in self.old_names.get(name, ()):
                old_full = self.full_name(old)
                old_value = self._value(old_full)
                if old_value is _MISSING:
                    continue
                if value is _MISSING:
                    value = old_value
                    self.renamed.append((old_full, full_name))
                elif old_value != value:
                    self.problems.append(
                        ParameterProblem(
                            full_name,
                            f"given as {value!r} and under its old name {old_full} "
                            f"as {old_value!r}; keep only {full_name}",
                        )
                    )
            if value is not _MISSING:
                given[name] = value
        self.given.extend(given)
        return given

    def _value(self, full_name: str) -> Any:
        if self.node.has_parameter(full_name):
            if full_name not in self.overrides and full_name not in self.adopted:
                self.problems.append(
                    ParameterProblem(full_name, "already declared on this node by other code")
                )
                self.taken.append(full_name)
                return _MISSING
            self.predeclared.append(full_name)
            return self.node.get_parameter(full_name).value
        if full_name in self.overrides:
            return self.overrides[full_name].value
        return _MISSING

    def with_problems(self, problems: list[ParameterProblem]) -> list[ParameterProblem]:
        """This reader's problems, then ``problems`` less what they repeat.

        A parameter other code declared first is reported once, as that: it is
        not also "required parameter is not set".
        """
        taken = set(self.taken)
        return [*self.problems, *(p for p in problems if p.key not in taken)]

    def release_predeclared(self) -> None:
        """Undeclare what rclpy declared from overrides, so it is declared again, fully."""
        for full_name in self.predeclared:
            if self.node.has_parameter(full_name):
                self.node.undeclare_parameter(full_name)
