"""From what a launch file starts to what the deployment checks need: each node's params
documents in the order launch passes them, and its schemas.

A node's schemas are its manifest entry's, when the manifest has one; else its package's:
``share/<package>/genparams/<executable>.yaml`` (for a composable node, the plugin's class
name, the text after its last ``::``), found through the ament index or
``--package-path``. A node neither gives is checked only for what rcl refuses.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from genparams.launch.model import InlineParameters, LaunchNode, ParamsFileRef
from genparams.launch.packages import Packages
from genparams.paramsfile.params_reader import ParamEntry, ParamsDocument, Section, read_params_file
from genparams.schema.errors import SchemaError, SchemaProblem
from genparams.schema.input_file import read_input_file

SCHEMA_FOLDER = "genparams"


def node_documents(node: LaunchNode) -> tuple[list[ParamsDocument], list[SchemaProblem]]:
    """The node's parameters as rcl gets them: each params file, each set of values given
    in the launch file (a section for this node alone, placed where it was written)."""
    documents: list[ParamsDocument] = []
    problems: list[SchemaProblem] = []
    for source in node.parameters:
        if isinstance(source, ParamsFileRef):
            try:
                text = read_input_file(Path(source.path), "params file")
            except SchemaError as exc:
                problems.extend(
                    SchemaProblem(source.location, node.full_name, f"params file: {p.message}")
                    for p in exc.problems
                )
                continue
            documents.append(read_params_file(text, source.path))
        elif isinstance(source, InlineParameters) and source.values:
            entries = tuple(
                ParamEntry(name, value, where, where, written_empty=value in ([], None))
                for name, value, where in source.values
            )
            first = source.values[0][2]
            section = Section(node.full_name, first, first, entries)
            documents.append(ParamsDocument(first.file, (section,), ()))
    return documents, problems


def package_schema(node: LaunchNode, packages: Packages) -> Path | None:
    """The schema the node's package installs for it, or None."""
    share = packages.share(node.package)
    if share is None:
        return None
    stem = (
        node.executable.rsplit("::", 1)[-1] if node.kind == "composable_node" else node.executable
    )
    candidate = share / SCHEMA_FOLDER / f"{stem}.yaml"
    return candidate if candidate.is_file() else None


def for_node(documents: Sequence[ParamsDocument], node: str) -> list[ParamsDocument]:
    """Only the sections that reach ``node``, named for it: an audit compares each node
    with what its own launch entry gave it."""
    from genparams.paramsfile.ros_yaml import node_matches

    kept = []
    for document in documents:
        sections = tuple(
            Section(node, s.node_location, s.params_location, s.entries)
            for s in document.sections
            if node_matches(s.node, node)
        )
        if sections:
            kept.append(ParamsDocument(document.file, sections, ()))
    return kept
