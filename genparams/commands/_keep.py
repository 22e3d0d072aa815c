"""Keep the values an audit read: write them back into the params files they came from."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from genparams.audit.findings import DRIFT_DEFAULT
from genparams.audit.walk import AuditResult
from genparams.commands._common import report
from genparams.errors import CommandError
from genparams.integration.writing import write_all
from genparams.launch.reader import is_launch_file
from genparams.outputs.keep_values import KeepError, NodeValues, apply, plan, read_texts
from genparams.paramsfile.params_reader import ParamsDocument, read_params_file


def keep_audited(
    result: AuditResult, documents: Sequence[ParamsDocument], new_values: Path | None
) -> None:
    """Write every value that differs from the files (and, to ``new_values``, every value
    off its default that no file gave); each change is reported as ``kept: ...``."""
    nodes = [
        NodeValues(
            node,
            values,
            {
                f.parameter: f.expected
                for f in result.findings
                if f.node == node and f.kind == DRIFT_DEFAULT
            },
        )
        for node, values in result.values.items()
    ]
    documents = list(documents)
    if new_values is not None and new_values.is_file():
        text = new_values.read_text(encoding="utf-8")
        documents.append(read_params_file(text, str(new_values)))
    planned = plan(nodes, documents, None if new_values is None else str(new_values))
    # A launch file's own values (a dict in parameters=[...], a <param value=/>) are code:
    # they are named, never rewritten.
    changes = [c for c in planned if not is_launch_file(Path(c.file))]
    report(
        *(f"kept: not written, a launch file's own value: {c}" for c in planned if c not in changes)
    )
    if not nodes:
        report("kept: no node was read, nothing to write")
        return
    if not changes:
        report("kept: nothing to write, the files hold every value")
        return
    try:
        texts = apply(changes, read_texts(sorted({c.file for c in changes})))
    except KeepError as exc:
        raise CommandError(exc) from None
    write_all({Path(file): text for file, text in texts.items()})
    report(*(f"kept: {change}" for change in changes))
