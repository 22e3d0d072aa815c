"""Drift from deployment files: what the params files say a node should run with."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from genparams.audit.findings import DRIFT_FILE, Finding
from genparams.errors import GenparamsError
from genparams.paramsfile.params_reader import ParamsDocument, read_params_file
from genparams.paramsfile.ros_yaml import node_matches
from genparams.runtime.core.changes import same_value as runtime_same_value
from genparams.schema.errors import SchemaError
from genparams.schema.input_file import read_input_file


class DeploymentError(GenparamsError, ValueError):
    """A params file that cannot be read: bad input, exit 2."""


def read_deployment(paths: Sequence[Path]) -> list[ParamsDocument]:
    documents = []
    for path in paths:
        try:
            text = read_input_file(path, "params file")
        except SchemaError as exc:
            raise DeploymentError(str(exc)) from None
        document = read_params_file(text, str(path))
        if document.problems:
            raise DeploymentError("\n".join(str(p) for p in document.problems))
        documents.append(document)
    return documents


def expected_values(documents: Sequence[ParamsDocument], node: str) -> dict[str, tuple[Any, str]]:
    """Name -> (value, FILE:LINE:COL) for ``node``; later sections and files win, as in ROS."""
    expected: dict[str, tuple[Any, str]] = {}
    for document in documents:
        for section in document.sections:
            if not node_matches(section.node, node):
                continue
            for entry in section.entries:
                if entry.value is not None:
                    expected[entry.name] = (entry.value, str(entry.value_location))
    return expected


def same_value(wanted: Any, actual: Any) -> bool:
    """The runtime's equality (NaN equals NaN); a file's ``true`` is not ``1``."""
    if isinstance(wanted, list | tuple) and isinstance(actual, list | tuple):
        return len(wanted) == len(actual) and all(map(same_value, wanted, actual))
    if isinstance(wanted, bool) or isinstance(actual, bool):
        return wanted is actual
    return runtime_same_value(wanted, actual)


def file_drift(
    node: str, documents: Sequence[ParamsDocument], values: Mapping[str, Any]
) -> list[Finding]:
    found = []
    for name, (wanted, where) in sorted(expected_values(documents, node).items()):
        if name not in values:
            found.append(
                Finding(node, DRIFT_FILE, name, f"set in {where}, not on the node", wanted)
            )
        elif not same_value(wanted, values[name]):
            detail = f"differs from {where}"
            found.append(Finding(node, DRIFT_FILE, name, detail, wanted, values[name]))
    return found
