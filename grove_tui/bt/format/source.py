"""Where tree text comes from: the one bounded read of a tree file, and errors that name their place.

Apart from the codec (xml.py) so the `<include>` resolver (include.py), which the codec calls, reads
files through the same limits without importing the codec back."""

from __future__ import annotations

import os

from grove_tui.errors import BTError
from grove_tui.limits import InputLimitError, read_bytes_bounded

MAX_BYTES = 1_000_000


def located_error(source: str, line: int | None, detail: str) -> BTError:
    """A BTError about one place of a file; it also carries the place apart (`line`, `detail`), so
    `check_tree_text` can list it like any other problem."""
    where = f"{source}:{line}" if line else source
    error = BTError(f"{where}: {detail}")
    error.line, error.detail = line, detail
    return error


def read_file_bytes(path: str | os.PathLike[str], limit: int = MAX_BYTES) -> bytes:
    """The bytes of a tree file through the one bounded reader (grove_tui.limits): regular files only
    (links followed, so a link to /dev/zero is refused as what it points at), at most `limit` bytes."""
    what = "behavior-tree file"
    try:
        return read_bytes_bounded(path, limit, what)
    except InputLimitError as exc:
        # "behavior-tree file PATH is a device, not a file" -> "PATH: is a device, not a file"
        message = str(exc)
        prefix = f"{what} {path}"
        detail = message[len(prefix):].lstrip(":").strip() if message.startswith(prefix) else message
        raise located_error(str(path), None, detail) from None
