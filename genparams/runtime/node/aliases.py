"""Old parameter names (``aliases:``) kept working after a rename.

An old name is declared next to the current one, with the same type and
descriptor. genparams' set path mirrors every set of either name onto the
other (``mirrored``), so both are validated, stored and announced in one atomic
change and always read the same; a set under the old name warns once.

Why in the set path, not in a pre-set callback: rclpy joins what its pre-set
callbacks return, so a callback of genparams handing back the request would
turn an application's refusal (its pre-set callback returning ``[]``) into a
set, and it would read ``.name`` of every item before rclpy refuses one that is
no Parameter (``TypeError``). In the set path the mirror sees the request the
application's pre-set callbacks made, once rclpy checked its items; a set with
no old name in it goes through untouched.
"""

from __future__ import annotations

import array
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from rclpy.parameter import Parameter

from genparams.runtime.core.problems import ParameterProblem
from genparams.runtime.core.spec import CompiledParam
from genparams.runtime.node.declaring import Declaration, descriptor_for, ros_parameter
from genparams.runtime.node.deprecation import Notices


def old_names_by_current(aliases: Mapping[str, str]) -> dict[str, tuple[str, ...]]:
    """Relative current name -> its old names, from old name -> current name."""
    out: dict[str, tuple[str, ...]] = {}
    for old, current in aliases.items():
        out[current] = (*out.get(current, ()), old)
    return out


class Aliases:
    def __init__(
        self,
        notices: Notices,
        aliases: Mapping[str, str],
        full_name: Callable[[str], str],
    ) -> None:
        self.notices = notices
        self.current_of = {full_name(old): full_name(cur) for old, cur in aliases.items()}
        self.old_of = {
            full_name(cur): tuple(full_name(o) for o in olds)
            for cur, olds in old_names_by_current(aliases).items()
        }

    def declarations(
        self, parameters: Mapping[str, CompiledParam], values: Mapping[str, Any]
    ) -> list[Declaration]:
        """The old names, declared like the current names (by full name) with equal values."""
        out = []
        for old, current in self.current_of.items():
            param = parameters[current]
            descriptor = descriptor_for(param, old)
            descriptor.description = f"Deprecated: old name of {current}; use that. " + (
                descriptor.description
            )
            out.append((ros_parameter(param, old, values[current]), descriptor))
        return out

    def mirrored(self, parameters: list[Parameter]) -> list[Parameter]:
        """The request plus the other name of every renamed parameter it sets."""
        old_of, current_of = self.old_of, self.current_of
        for parameter in parameters:  # a plain loop: most sets name no renamed parameter
            if parameter.name in current_of or parameter.name in old_of:
                break
        else:
            return parameters
        requested = {parameter.name for parameter in parameters}
        mirrored = []
        for parameter in parameters:
            current = current_of.get(parameter.name)
            if current is not None:
                self.notices.renamed(parameter.name, current)
                others: tuple[str, ...] = (current, *old_of[current])
            else:
                others = old_of.get(parameter.name, ())
            for other in others:
                if other not in requested and other != parameter.name:
                    requested.add(other)
                    mirrored.append(Parameter(other, parameter.type_, parameter.value))
        return [*parameters, *mirrored]

    def problems(self, parameters: Sequence[Parameter]) -> list[ParameterProblem]:
        """Both names of one parameter must change together, to one value."""
        values = {parameter.name: parameter.value for parameter in parameters}
        reasons = []
        for old, current in self.current_of.items():
            if old not in values and current not in values:
                continue
            if old not in values or current not in values:
                given, missing = (old, current) if old in values else (current, old)
                reasons.append(
                    ParameterProblem(given, f"must be set together with {missing}, its other name")
                )
            elif not _same(values[old], values[current]):
                reasons.append(
                    ParameterProblem(
                        old, f"is the old name of {current}, but was given a different value"
                    )
                )
        return reasons


def _same(a: Any, b: Any) -> bool:
    sequences = (list, tuple, array.array)
    if isinstance(a, sequences) and isinstance(b, sequences):
        return list(a) == list(b)  # a request may carry a list and an array.array
    return bool(a == b)
