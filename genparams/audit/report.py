"""An audit as text for people or JSON for tools."""

from __future__ import annotations

from genparams.audit.walk import AuditResult
from genparams.runtime.core.json_codec import dumps


def text_report(result: AuditResult) -> str:
    lines = [finding.text() for finding in result.findings]
    failing = sum(finding.failing for finding in result.findings)
    lines.append(
        f"audited {len(result.audited)} node(s) with a schema, {len(result.plain)} without;"
        f" {failing} violation(s), {len(result.findings) - failing} other finding(s)"
        f" in {result.seconds:.2f} s"
    )
    return "\n".join(lines) + "\n"


def json_report(result: AuditResult) -> str:
    document = {
        "ok": not result.failing,
        "audited": result.audited,
        "without_schema": result.plain,
        "seconds": round(result.seconds, 3),
        "findings": [finding.as_json() for finding in result.findings],
    }
    return dumps(document, indent=2, sort_keys=True) + "\n"
