"""Reading a file genparams was given: bounded, decoded, and named in every error.

Schemas, params files, manifests and generate_parameter_library files are all
read here. The size limit is enforced while reading (at most one byte past it
is read), never by asking the file system first: ``/dev/zero``, a FIFO, a pipe
from ``<(...)`` or a file under ``/proc`` reports a size of 0 and reads on.
"""

from __future__ import annotations

import os

from genparams.schema.errors import Location, SchemaError, SchemaProblem
from genparams.schema.loader import MAX_BYTES


def read_input_file(path: str | os.PathLike[str], what: str) -> str:
    """The text of ``path`` (``what`` it is: "schema", "params file"...), as UTF-8.

    Line ends are read as Python's text files read them (``\\r\\n`` and ``\\r``
    become ``\\n``). Raises SchemaError with one problem naming the file when it
    cannot be opened or read, is larger than MAX_BYTES, or is not UTF-8.
    """
    file = os.fsdecode(path)
    try:
        with open(path, "rb") as handle:
            data = handle.read(MAX_BYTES + 1)
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        raise _problem(file, 1, 1, f"cannot read {what}: {reason}") from None
    if len(data) > MAX_BYTES:
        raise _problem(file, 1, 1, f"cannot read {what}: file is larger than {MAX_BYTES} bytes")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line_start = data.rfind(b"\n", 0, exc.start) + 1
        line = data.count(b"\n", 0, exc.start) + 1
        column = len(data[line_start : exc.start].decode("utf-8", "replace")) + 1
        raise _problem(
            file,
            line,
            column,
            f"cannot read {what}: not UTF-8 text (byte 0x{data[exc.start]:02x} "
            f"at offset {exc.start})",
        ) from None
    return text.replace("\r\n", "\n").replace("\r", "\n")


def _problem(file: str, line: int, column: int, message: str) -> SchemaError:
    return SchemaError([SchemaProblem(Location(file, line, column), "", message)])
