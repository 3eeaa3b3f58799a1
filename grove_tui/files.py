"""Safe writes: a reader sees the old content or the new, never half of it, and nothing is replaced
that GROVE did not write.

Every output folder (a bundle, an export, an evaluation) goes through `atomic_directory`: the new
content is staged beside the target and swapped in by rename. What may be replaced is decided by the
caller's `owned` test (a folder holding `scenario.yaml` is a bundle, one holding an export marker is an
export): an existing folder that fails it is refused unless the user said `--overwrite`, an empty
folder is used as is, and files, device nodes, pipes and symbolic links are never touched.
"""

from __future__ import annotations

import contextlib
import errno
import os
import shutil
import stat
import tempfile
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path, PurePosixPath
from typing import Any

from grove_tui.errors import OutputError

OwnedTest = Callable[[Path], bool]
# Zip entries of .npz files get this timestamp (the zip format's earliest), not the time of writing,
# so the same arrays always give the same bytes and bundles compare byte for byte.
NPZ_TIMESTAMP = (1980, 1, 1, 0, 0, 0)


def npz_bytes(arrays: Mapping[str, Any]) -> bytes:
    """A compressed .npz (what np.load reads) whose bytes depend only on the arrays, in the given order."""
    import io
    import zipfile

    import numpy as np

    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for name, value in arrays.items():
            info = zipfile.ZipInfo(f"{name}.npy", date_time=NPZ_TIMESTAMP)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16  # fixed permissions, not the writer's umask
            with archive.open(info, "w", force_zip64=True) as member:
                np.lib.format.write_array(member, np.asanyarray(value), allow_pickle=False)
    return buffer.getvalue()


def write_text_atomic(path: str | os.PathLike[str], text: str, encoding: str = "utf-8") -> Path:
    return write_bytes_atomic(path, text.encode(encoding))


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes) -> Path:
    """Replace the file at `path` (a link is followed to its file); folders and special files are refused."""
    with atomic_file(path) as tmp:
        tmp.write_bytes(data)
    return _file_target(path)


def _file_target(path: str | os.PathLike[str]) -> Path:
    target = Path(path)
    if target.is_symlink():
        target = Path(os.path.realpath(target))
    try:
        mode = os.stat(target).st_mode
    except FileNotFoundError:
        return target
    except OSError as exc:
        raise OutputError(f"{target}: cannot inspect it: {exc.strerror}") from None
    if not stat.S_ISREG(mode):
        raise OutputError(f"{target}: is {'a folder' if stat.S_ISDIR(mode) else _kind(mode)}, not a file; "
                          "choose a file path")
    return target


@contextlib.contextmanager
def atomic_file(path: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary path beside `path` for the caller to write; on success it replaces `path`.

    For writers that stream (CSV, sqlite); `write_bytes_atomic` for data already in memory.
    """
    target = _file_target(path)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    except OSError as exc:
        raise OutputError(f"{target}: cannot write there: {exc.strerror}") from None
    os.close(fd)
    tmp_path = Path(tmp)
    try:
        _usual_mode(tmp_path, directory=False)
        yield tmp_path
        with open(tmp_path, "rb") as handle:
            os.fsync(handle.fileno())
        os.replace(tmp_path, target)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            tmp_path.unlink()
        raise


def _umask() -> int:
    # Read without a window where another thread could create files under a zero umask.
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    return 0o022


def _usual_mode(path: Path, directory: bool) -> None:
    """mkstemp/mkdtemp make private 0600/0700 entries; outputs get what `open`/`mkdir` would give."""
    os.chmod(path, (0o777 if directory else 0o666) & ~_umask())


def absolute_path(path: str | os.PathLike[str]) -> Path:
    # abspath, not resolve: `--out .` must name the current folder, and a symbolic link in the last
    # component must be seen as a link (and refused), not followed.
    return Path(os.path.abspath(os.path.expanduser(os.fspath(path))))


def _kind(mode: int) -> str:
    if stat.S_ISLNK(mode):
        return "a symbolic link"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device node"
    if stat.S_ISFIFO(mode):
        return "a named pipe"
    if stat.S_ISSOCK(mode):
        return "a socket"
    if stat.S_ISREG(mode):
        return "a file"
    return "not a folder"


def _writable_ancestor(path: Path) -> Path:
    """The nearest existing ancestor of `path`, which must let us create entries."""
    probe = path.parent
    while not probe.exists():
        if probe.parent == probe:
            break
        probe = probe.parent
    if not probe.is_dir():
        raise OutputError(f"{path}: cannot create it, {probe} is {_kind(os.lstat(probe).st_mode)}")
    if not os.access(probe, os.W_OK | os.X_OK):
        raise OutputError(f"{path}: cannot write there ({probe} is not writable)")
    # access() says yes to root on a read-only mount and on /proc: create and remove a probe folder,
    # so an unwritable --out fails now, not after a whole generation.
    try:
        os.rmdir(tempfile.mkdtemp(prefix=".grove-probe-", dir=probe))
    except OSError as exc:
        raise OutputError(f"{path}: cannot write there ({probe}: {exc.strerror})") from None
    return probe


def check_output_dir(path: str | os.PathLike[str], *, owned: OwnedTest, what: str = "GROVE output",
                     overwrite: bool = False, flag: str = "--overwrite") -> Path:
    """Check, before any work, that `path` may become (or replace) an output folder; its absolute path.

    Allowed: a path that does not exist yet (its parent writable), an empty folder, a folder `owned`
    says GROVE wrote, or any folder when `overwrite`. Refused: files, device nodes, pipes, sockets,
    symbolic links, the file system root, and a non-empty folder GROVE did not write.
    """
    target = absolute_path(path)
    if target.parent == target:
        raise OutputError(f"{target}: the file system root cannot be an output folder")
    try:
        mode = os.lstat(target).st_mode
    except FileNotFoundError:
        _writable_ancestor(target)
        return target
    except OSError as exc:
        raise OutputError(f"{target}: cannot inspect it: {exc.strerror}") from None
    if not stat.S_ISDIR(mode):
        raise OutputError(f"{target}: is {_kind(mode)}, not a folder; choose a folder path for the {what}")
    if not os.access(target.parent, os.W_OK | os.X_OK):
        raise OutputError(f"{target}: cannot replace it ({target.parent} is not writable)")
    try:
        empty = not any(os.scandir(target))
    except OSError as exc:
        raise OutputError(f"{target}: cannot read it: {exc.strerror}") from None
    if empty or owned(target) or overwrite:
        return target
    raise OutputError(f"{target}: exists and is not a {what}; choose another path, or pass {flag} to replace "
                      f"the folder and everything in it")


@contextlib.contextmanager
def atomic_directory(path: str | os.PathLike[str], *, owned: OwnedTest, what: str = "GROVE output",
                     overwrite: bool = False, flag: str = "--overwrite") -> Iterator[Path]:
    """Yield a staging folder beside `path`; on success it takes `path`'s place in one rename.

    `path` is checked with `check_output_dir` first (and again just before the swap, in case it
    changed meanwhile). On any exception, Ctrl-C included, the staging folder is removed and `path`
    is left as it was.
    """
    target = check_output_dir(path, owned=owned, what=what, overwrite=overwrite, flag=flag)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".staging", dir=target.parent))
    except OSError as exc:
        raise OutputError(f"{target}: cannot write there: {exc.strerror}") from None
    try:
        _usual_mode(staging, directory=True)
        yield staging
        check_output_dir(target, owned=owned, what=what, overwrite=overwrite, flag=flag)
        _swap_in(staging, target)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise


def relative_file(rel: str) -> PurePosixPath:
    """`rel` as a path inside a folder: relative, no `..`, `.` or empty parts; else an OutputError."""
    path = PurePosixPath(rel)
    if (not rel or "\\" in rel or "\x00" in rel or path.is_absolute()
            or any(part in ("", ".", "..") for part in rel.split("/"))):
        raise OutputError(f"{rel!r}: not a plain relative file path (no leading '/', no '.' or '..' parts)")
    return path


def write_files_atomic(path: str | os.PathLike[str], files: Mapping[str, bytes], *, owned: OwnedTest,
                       what: str = "GROVE output", overwrite: bool = False) -> Path:
    """A folder holding exactly `files` (relative path -> bytes) takes `path`'s place in one rename.

    For a folder written elsewhere and sent here as bytes (a Ray worker without the driver's disk):
    the same checks and swap as `atomic_directory`, so a reader never sees half of it.
    """
    checked = {relative_file(rel): data for rel, data in files.items()}
    target = absolute_path(path)
    with atomic_directory(target, owned=owned, what=what, overwrite=overwrite) as stage:
        for rel, data in sorted(checked.items()):
            member = stage.joinpath(*rel.parts)
            try:
                member.parent.mkdir(parents=True, exist_ok=True)
                with open(member, "xb") as handle:  # "x": two entries naming one file are refused, not merged
                    handle.write(data)
            except (FileExistsError, NotADirectoryError):
                raise OutputError(f"{target}: {rel} is named twice (as a file and as a folder)") from None
            except OSError as exc:
                raise OutputError(f"{target}: cannot write {rel}: {exc.strerror}") from None
    return target


def _swap_in(staging: Path, target: Path) -> None:
    """Rename `staging` to `target`; an existing `target` folder is moved aside and removed afterwards."""
    backup: Path | None = None
    if os.path.lexists(target):
        backup = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".old", dir=target.parent))
        os.rmdir(backup)  # a unique free name for the old folder, on the same file system
        os.replace(target, backup)
    try:
        os.replace(staging, target)
    except BaseException as exc:
        if backup is not None:
            os.replace(backup, target)
        if isinstance(exc, OSError) and exc.errno in (errno.EACCES, errno.EPERM, errno.EROFS):
            raise OutputError(f"{target}: cannot write there: {exc.strerror}") from None
        raise
    if backup is not None:
        shutil.rmtree(backup, ignore_errors=True)


def link_or_copy(src: Path, dst: Path) -> None:
    """Put `src`'s content at `dst` cheaply: a hard link where the file system allows, else a copy."""
    dst.parent.mkdir(parents=True, exist_ok=True)
    try:
        os.link(src, dst)
    except OSError:
        shutil.copy2(src, dst)


def safe_file_name(name: str, what: str = "name") -> str:
    """`name` if it is one plain file name (no folder separators, not `.`/`..`), else an OutputError."""
    text = str(name)
    if (not text or text in (".", "..") or "/" in text or "\\" in text or "\x00" in text
            or text != text.strip() or len(text.encode("utf-8", "surrogateescape")) > 200):
        raise OutputError(f"{what} {text!r} must be a plain file name (no '/', not '.' or '..', "
                          "at most 200 bytes)")
    return text
