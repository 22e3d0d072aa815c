"""The Markdown table of ``bench.import_rates``: one row per node, totals per sample."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from bench.import_rates import Measured, Row

HEADER = (
    "| repository | node file | commit | params file | file by file: exact | whole: declared "
    "| exact | of them checked | approximate | left out (warned) | the node's own run |\n"
    "|---|---|---|---|---|---|---|---|---|---|---|\n"
)


def share_text(part: int, whole: int) -> str:
    """``245 of 258 (94.9%)``: the percentage cut to one decimal, never rounded up, so a
    share below a target never reads as meeting it."""
    return f"{part} of {whole} ({1000 * part // whole / 10:.1f}%)" if whole else "0 of 0"


def _node_run(row: Row) -> str:
    declared = len(row.node.get("declared", {}))
    stopped = row.node.get("stopped", "")
    run = f"{declared} declared"
    if stopped == "Stopped: timer":
        run += ", still running at its time limit"
    elif stopped and stopped != "spin":  # the exception's kind; --details gives it whole
        run += f", stopped by {stopped.partition(':')[0]}"
    return run


def _by_file(measured: Measured) -> str:
    if measured.crash:
        return f"crash: {measured.crash}"
    if measured.refused:
        return f"0 of 0 ({measured.refused.partition(' (')[0]})"  # the import refused
    return f"{measured.exact} of {measured.parameters}"


def _line(row: Row) -> str:
    entry, whole = row.entry, row.whole
    file = f"`{entry.file}`" + (f" `--class {entry.cls}`" if entry.cls else "")
    params = f"`{entry.params}`" if entry.params else ""
    cells = [entry.repo, file, f"`{entry.commit[:10]}`", params, _by_file(row.by_file)]
    if whole.crash:
        cells += [f"crash: {whole.crash}", "", "", "", ""]
    else:
        cells += [str(whole.parameters), str(whole.exact), str(whole.checked),
                  str(whole.approximate), str(whole.left_out)]  # fmt: skip
    cells.append(_node_run(row))
    return "| " + " | ".join(cells) + " |\n"


def _total(label: str, rows: Sequence[Row]) -> str:
    file_exact = sum(r.by_file.exact for r in rows)
    file_all = sum(r.by_file.parameters for r in rows)
    whole_all = sum(r.whole.parameters for r in rows)
    cells = [
        f"**{label}: {len(rows)} nodes**", "", "", "",
        f"**{share_text(file_exact, file_all)}**", f"**{whole_all}**",
        f"**{share_text(sum(r.whole.exact for r in rows), whole_all)}**",
        f"**{sum(r.whole.checked for r in rows)}**",
        f"**{sum(r.whole.approximate for r in rows)}**",
        f"**{sum(r.whole.left_out for r in rows)}**",
        f"**{sum(len(r.node.get('declared', {})) for r in rows)} declared**",
    ]  # fmt: skip
    return "| " + " | ".join(cells) + " |\n"


def _details(rows: Sequence[Row]) -> str:
    lines = []
    for row in rows:
        stopped = row.node.get("stopped", "")
        if stopped and stopped not in ("spin", "Stopped: timer"):
            lines.append(f"- {row.entry.file}: the node's own run stopped: {stopped}\n")
        for kind, measured in (("file by file", row.by_file), ("whole", row.whole)):
            if measured.differ:
                lines.append(f"- {row.entry.file} ({kind}): declared otherwise on a real "
                             f"node: {', '.join(measured.differ)}\n")  # fmt: skip
            if measured.class_only:
                names = ", ".join(measured.class_only)
                lines.append(f"- {row.entry.file} ({kind}): declared by the class only, not "
                             f"by the node's finished run: {names}\n")  # fmt: skip
            if measured.node_only:
                lines.append(f"- {row.entry.file} ({kind}): declared by the node's own run "
                             f"only: {', '.join(measured.node_only)}\n")  # fmt: skip
    return "".join(lines)


def report(rows: Sequence[Row], *, details: bool = False) -> str:
    out = []
    for sample in dict.fromkeys(r.entry.sample for r in rows):
        chosen = [r for r in rows if r.entry.sample == sample]
        out.append(f"\n### sample: {sample}\n\n{HEADER}")
        out.extend(_line(r) for r in chosen)
        out.append(_total("total", chosen))
        rest = [r for r in chosen if "joy_teleop/" not in r.entry.file]
        if len(rest) != len(chosen):
            out.append(_total("without joy_teleop", rest))
        if details:
            out.append("\n" + _details(chosen))
    crashes = sum(bool(r.by_file.crash) + bool(r.whole.crash) for r in rows)
    out.append(f"\ncrashes: {crashes}\n")
    return "".join(out)
