"""Reading a file genparams was given: bounded, decoded, and named in every error.

Schemas, params files, manifests, generate_parameter_library files and rclpy
sources are all read here. The size limit is enforced while reading (at most one
byte past it is read), never by asking the file system first: a FIFO, a pipe
from ``<(...)`` or a file under ``/proc`` reports a size of 0 and reads on.

The file is opened without blocking (a FIFO nobody writes to would block
``open`` for ever), then must be a regular file or a pipe. Devices
(``/dev/zero``, a terminal) and sockets are refused. A pipe must be written
whole within ``PIPE_TIMEOUT_S``.
"""

from __future__ import annotations

import os
import select
import stat
import time
from collections.abc import Callable

from genparams.schema.errors import Location, SchemaError, SchemaProblem
from genparams.schema.loader import MAX_BYTES

# A pipe such as <(generate-params) is written by a command that runs meanwhile.
PIPE_TIMEOUT_S = 30.0
_CHUNK = 1 << 16


def read_input_file(path: str | os.PathLike[str], what: str) -> str:
    """The text of ``path`` (``what`` it is: "schema", "params file"...), as UTF-8.

    Line ends are read as Python's text files read them (``\\r\\n`` and ``\\r``
    become ``\\n``). Raises SchemaError with one problem naming the file when it
    cannot be opened or read, is larger than MAX_BYTES, or is not UTF-8.
    """
    file = os.fsdecode(path)
    try:
        data = _read_bounded(path, file, what)
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


def _read_bounded(path: str | os.PathLike[str], file: str, what: str) -> bytes:
    """At most ``MAX_BYTES + 1`` bytes of a regular file or a pipe; OSError as it comes."""
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    try:
        mode = os.fstat(fd).st_mode
        if stat.S_ISDIR(mode):
            raise IsADirectoryError(21, "Is a directory")
        if stat.S_ISREG(mode):
            os.set_blocking(fd, True)
            return _read_until(fd, lambda: None)
        if stat.S_ISFIFO(mode):
            deadline = time.monotonic() + PIPE_TIMEOUT_S
            return _read_until(fd, lambda: _wait(fd, deadline, file, what))
        raise _problem(file, 1, 1, f"cannot read {what}: {_kind(mode)}, not a file or a pipe")
    finally:
        os.close(fd)


def _read_until(fd: int, wait: Callable[[], None]) -> bytes:
    """Read ``fd`` to its end or one byte past the limit, calling ``wait`` before each read."""
    chunks: list[bytes] = []
    size = 0
    while size <= MAX_BYTES:
        wait()
        try:
            chunk = os.read(fd, min(_CHUNK, MAX_BYTES + 1 - size))
        except BlockingIOError:
            continue
        if not chunk:
            break
        chunks.append(chunk)
        size += len(chunk)
    return b"".join(chunks)


def _wait(fd: int, deadline: float, file: str, what: str) -> None:
    """Until the pipe ``fd`` has data or its writer left; refused once ``deadline`` passes."""
    poller = select.poll()
    poller.register(fd, select.POLLIN)
    left = deadline - time.monotonic()
    if left <= 0 or not poller.poll(left * 1000):
        raise _problem(
            file,
            1,
            1,
            f"cannot read {what}: the pipe was not written whole within {PIPE_TIMEOUT_S:g} s",
        )


def _kind(mode: int) -> str:
    if stat.S_ISCHR(mode):
        return "a character device"
    if stat.S_ISBLK(mode):
        return "a block device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def _problem(file: str, line: int, column: int, message: str) -> SchemaError:
    return SchemaError([SchemaProblem(Location(file, line, column), "", message)])
