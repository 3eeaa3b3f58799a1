"""Safe writes: the one guard every writer goes through. A reader sees the old content or the new, never
half of it, and nothing is replaced that GROVE did not write.

Every output, a folder (a bundle, an export, an evaluation) or a single file (a Foxglove .mcap, a
picture, metrics.json, the dataset index), goes through `atomic_directory` or `atomic_file`:

- the new content is staged beside the target and swapped in by one rename (folders: an atomic
  exchange where the file system has one), so a crash leaves the old state or the new;
- what may be replaced is decided by the caller's `owned` test (a folder holding `scenario.yaml` is
  a bundle, one holding an export marker is an export, an .mcap carrying GROVE's metadata is a
  GROVE export): anything else is refused unless the user said `--overwrite`; an empty folder is
  used as is, and device nodes, pipes, sockets and mount points (which no rename can replace) are never
  touched;
- a symbolic link is never followed: writing through one could replace a file anywhere;
- a name that is one of a protected folder's own files (`protect_folders`: a bundle's scenario.yaml,
  trees/, grid.npz...) is refused to every writer but that folder's own;
- staging entries carry the writer's process id, so one left by a killed process (kill -9, a power
  cut) is recognised and removed the next time anything is written beside it (`sweep_stale`).

`write_point(label)` marks each step a crash could interrupt; the fault tests kill the process there.
"""

from __future__ import annotations

import contextlib
import ctypes
import errno
import hashlib
import os
import re
import shutil
import socket
import stat
import tempfile
import time
from collections.abc import Callable, Iterable, Iterator, Mapping
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, Required, TypedDict, Unpack

from grove_tui.errors import OutputError

OwnedTest = Callable[[Path], bool]

if TYPE_CHECKING:
    from numpy.typing import ArrayLike


class FileGuard(TypedDict, total=False):
    """check_output_file's keyword arguments, as the atomic writers pass them on."""

    owned: OwnedTest | None
    what: str
    overwrite: bool
    flag: str
    own_folder: str | os.PathLike[str] | None


class DirGuard(TypedDict, total=False):
    """check_output_dir's keyword arguments: a folder GROVE replaces must always be recognisable as its own."""

    owned: Required[OwnedTest]
    what: str
    overwrite: bool
    flag: str
    own_folder: str | os.PathLike[str] | None
# Zip entries of .npz files get this timestamp (the zip format's earliest), not the time of writing,
# so the same arrays always give the same bytes and bundles compare byte for byte.
NPZ_TIMESTAMP = (1980, 1, 1, 0, 0, 0)
# Failures of the storage itself while writing: reported as an OutputError naming the target.
WRITE_FAILURE_ERRNOS = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EROFS, errno.EIO})
# Staging entries: ".<target name, cut>.<host>-<pid>.<random>.<kind>" beside the target. The host tag
# keeps a writer on another machine of a shared file system (a Ray worker) from being judged by this
# machine's process table.
STAGING_KINDS = ("staging", "tmp", "old")
_STAGING_NAME = re.compile(r"^\.(?P<name>.+)\.(?P<host>[0-9a-f]{8})-(?P<pid>\d+)\.(?P<rand>[a-z0-9_]{8})"
                           r"\.(?P<kind>staging|tmp|old)$")
# Entries of versions that did not record their process, and other machines' entries: stale once this old.
_LEGACY_STAGING = re.compile(r"^\.(?P<name>.+)\.(?P<rand>[a-z0-9_]{8})\.(?P<kind>staging|tmp|old)$")
LEGACY_STALE_SECONDS = 3600.0
_HOST = hashlib.sha1(socket.gethostname().encode("utf-8", "replace")).hexdigest()[:8]
_NAME_IN_STAGING = 80  # characters of the target's name kept in a staging name (file names stop at 255 bytes)


# -- fault-test hook -------------------------------------------------------------------------------------

# Called with a label at every step a crash could interrupt ("file:metrics.json:written", ...); None in
# normal use. tests/helpers/faults.py sets it in a child process that kills itself at a chosen label.
WRITE_POINT_HOOK: Callable[[str], None] | None = None


def write_point(label: str) -> None:
    hook = WRITE_POINT_HOOK
    if hook is not None:
        hook(label)


# -- protected folders -------------------------------------------------------------------------------------

# (is it such a folder?, its own entries' names, what it is): registered by the modules that own them.
_PROTECTED: list[tuple[OwnedTest, frozenset[str], str]] = []


def protect_folders(test: OwnedTest, names: Iterable[str], what: str) -> None:
    """Folders passing `test` keep their entries `names` for their own writer: any other output naming
    one of them (`--out BUNDLE/scenario.yaml`, a world file called scenario.yaml) is refused."""
    entry = (test, frozenset(names), what)
    if entry not in _PROTECTED:
        _PROTECTED.append(entry)


def _check_not_protected(target: Path, own_folder: str | os.PathLike[str] | None) -> None:
    own = None if own_folder is None else absolute_path(own_folder)
    for ancestor in target.parents:
        for test, names, what in _PROTECTED:
            if ancestor == own or not names:
                continue
            first = target.relative_to(ancestor).parts[0]
            if first in names and test(ancestor):
                raise OutputError(f"{target}: {first} is the {what} {ancestor}'s own; choose a path outside it "
                                  f"(or another name)")


# -- stale staging entries ---------------------------------------------------------------------------------


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True  # another user's live process
    except OSError:
        return True
    return True


def _staging_prefix(target: Path) -> str:
    return f".{target.name[:_NAME_IN_STAGING]}.{_HOST}-{os.getpid()}."


def sweep_stale(folder: str | os.PathLike[str], name: str | None = None) -> list[Path]:
    """Remove the staging entries in `folder` that a killed writer left (of target `name`, or of any).

    An entry is stale when the process that made it is gone. A target that a crash left moved aside
    (`.old`, the fallback swap's window) and missing is put back first: the old state, never none.
    Returns what was removed or restored.
    """
    root = Path(folder)
    try:
        entries = list(os.scandir(root))
    except OSError:
        return []
    cut = None if name is None else name[:_NAME_IN_STAGING]
    stale: list[tuple[str, str, str]] = []  # (entry, target name, kind)
    now = time.time()
    for entry in entries:
        match = _STAGING_NAME.match(entry.name)
        if match is not None and match["host"] == _HOST:
            if _alive(int(match["pid"])):
                continue
        else:
            match = match or _LEGACY_STAGING.match(entry.name)
            if match is None:
                continue
            try:
                if now - entry.stat(follow_symlinks=False).st_mtime < LEGACY_STALE_SECONDS:
                    continue
            except OSError:
                continue
        if cut is not None and match["name"] != cut:
            continue
        stale.append((entry.name, match["name"], match["kind"]))
    cleaned: list[Path] = []
    for entry_name, target_name, kind in sorted(stale, key=lambda item: item[2] != "old"):
        path = root / entry_name
        target = root / target_name
        if kind == "old" and len(target_name) < _NAME_IN_STAGING and not os.path.lexists(target):
            with contextlib.suppress(OSError):
                os.replace(path, target)
                cleaned.append(target)
                continue
        with contextlib.suppress(OSError):
            if path.is_dir() and not path.is_symlink():
                shutil.rmtree(path)
            else:
                path.unlink()
            cleaned.append(path)
    return cleaned


# -- single files --------------------------------------------------------------------------------------------


def npz_bytes(arrays: Mapping[str, ArrayLike]) -> bytes:
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


def write_text_atomic(path: str | os.PathLike[str], text: str, encoding: str = "utf-8", **guard: Unpack[FileGuard]) -> Path:
    return write_bytes_atomic(path, text.encode(encoding), **guard)


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes, **guard: Unpack[FileGuard]) -> Path:
    """Replace the file at `path` in one rename; `guard` as `atomic_file` takes it."""
    with atomic_file(path, **guard) as tmp:
        tmp.write_bytes(data)
    return absolute_path(path)


def check_output_file(path: str | os.PathLike[str], *, owned: OwnedTest | None = None, what: str = "file",
                      overwrite: bool = False, flag: str = "--overwrite",
                      own_folder: str | os.PathLike[str] | None = None) -> Path:
    """Check, before any work, that `path` may become (or replace) an output file; its absolute path.

    Refused always: a symbolic link (never followed), a folder, device node, pipe or socket. With
    `owned` (a file the user named): an existing file `owned` does not recognise, unless `overwrite`,
    and a name that is a protected folder's own entry (unless that folder is `own_folder`). Without
    `owned`, a file GROVE manages itself (a cache, a staged member): any regular file is replaced.
    """
    target = absolute_path(path)
    if owned is not None:
        _check_not_protected(target, own_folder)
    try:
        mode = os.lstat(target).st_mode
    except FileNotFoundError:
        _writable_ancestor(target)
        return target
    except NotADirectoryError:
        raise OutputError(f"{target}: cannot create it, a part of its path is a file") from None
    except OSError as exc:
        raise OutputError(f"{target}: cannot inspect it: {exc.strerror}") from None
    if stat.S_ISLNK(mode):
        raise OutputError(f"{target}: is a symbolic link (to {os.readlink(target)}); GROVE never writes through "
                          "a link, which could replace a file elsewhere: remove the link or choose another path")
    if not stat.S_ISREG(mode):
        raise OutputError(f"{target}: is {'a folder' if stat.S_ISDIR(mode) else _kind(mode)}, not a file; "
                          f"choose a file path for the {what}")
    if _is_mount_point(target):  # a file bound over another: a rename onto it fails (EBUSY)
        raise OutputError(f"{target}: is a mount point, which cannot be replaced in one step; choose another path")
    if owned is None or overwrite or owned(target):
        return target
    raise OutputError(f"{target}: exists and is not a {what}; choose another path, or pass {flag} to replace it")


@contextlib.contextmanager
def atomic_file(path: str | os.PathLike[str], *, owned: OwnedTest | None = None, what: str = "file",
                overwrite: bool = False, flag: str = "--overwrite",
                own_folder: str | os.PathLike[str] | None = None) -> Iterator[Path]:
    """A temporary path beside `path` for the caller to write; on success it replaces `path` in one rename.

    `path` is checked with `check_output_file` first and again just before the rename. On any
    exception the temporary file is removed and `path` is left as it was; a storage failure (full
    disk, read-only file system) is an OutputError naming `path`. For writers that stream (CSV,
    sqlite); `write_bytes_atomic` for data already in memory.
    """
    guard = FileGuard(owned=owned, what=what, overwrite=overwrite, flag=flag, own_folder=own_folder)
    target = check_output_file(path, **guard)
    created = _make_parents(target)
    sweep_stale(target.parent, target.name)
    try:
        fd, tmp = tempfile.mkstemp(prefix=_staging_prefix(target), suffix=".tmp", dir=target.parent)
    except OSError as exc:
        _remove_created(created)
        raise OutputError(f"{target}: cannot write there: {exc.strerror}") from None
    os.close(fd)
    tmp_path = Path(tmp)
    try:
        _usual_mode(tmp_path, directory=False)
        yield tmp_path
        with open(tmp_path, "rb") as handle:
            os.fsync(handle.fileno())
        write_point(f"file:{target.name}:written")
        check_output_file(target, **guard)
        os.replace(tmp_path, target)
        write_point(f"file:{target.name}:replaced")
    except BaseException as exc:
        with contextlib.suppress(FileNotFoundError):
            tmp_path.unlink()
        _remove_created(created)
        if isinstance(exc, OSError) and exc.errno in WRITE_FAILURE_ERRNOS:
            raise OutputError(f"{target}: cannot write it: {exc.strerror}") from None
        raise


def append_line(path: str | os.PathLike[str], line: str) -> Path:
    """Append one line to a log such as batch-state.jsonl, as whole lines only.

    The line is written with one write() on an O_APPEND descriptor. A last line torn by an earlier
    crash (no newline at its end) is ended first, so the new record starts a line of its own instead
    of being glued to the torn one (and lost with it). A write that fails part-way (a full disk) is
    cut back off, and a log (and folders) this call created and could not fill is removed.
    """
    target = check_output_file(path)
    text = line if line.endswith("\n") else line + "\n"
    created = _make_parents(target)
    new_file = not os.path.lexists(target)
    try:
        fd = os.open(target, os.O_WRONLY | os.O_APPEND | os.O_CREAT | os.O_NOFOLLOW, 0o666)
    except OSError as exc:
        _remove_created(created)
        raise OutputError(f"{target}: cannot write it: {exc.strerror}") from None
    size = 0
    try:
        size = os.fstat(fd).st_size
        if size:
            with open(target, "rb") as reader:
                reader.seek(size - 1)
                if reader.read(1) != b"\n":
                    text = "\n" + text
        write_point(f"append:{target.name}:before")
        data = text.encode("utf-8")
        written = os.write(fd, data)
        while written < len(data):  # a short write (a signal, a nearly full disk): finish the line
            written += os.write(fd, data[written:])
        write_point(f"append:{target.name}:after")
    except OSError as exc:
        with contextlib.suppress(OSError):
            os.ftruncate(fd, size)  # no half line
        os.close(fd)
        if new_file and os.path.getsize(target) == 0:  # nothing written: leave no empty log (or folder) behind
            with contextlib.suppress(OSError):
                target.unlink()
            _remove_created(created)
        raise OutputError(f"{target}: cannot write it: {exc.strerror}") from None
    os.close(fd)
    return target


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


def _is_mount_point(path: Path) -> bool:
    """Whether `path` is a mount point, bind mounts on the same file system included (os.path.ismount
    compares devices and misses those; the kernel's mount table does not)."""
    if os.path.ismount(path):
        return True
    try:
        with open("/proc/self/mountinfo", "rb") as table:
            points = {line.split(b" ")[4] for line in table if line.count(b" ") >= 5}
    except OSError:
        return False
    # The table escapes space, tab, newline and backslash in octal.
    real = os.fsencode(os.path.realpath(path))
    for char in (b"\\", b" ", b"\t", b"\n"):
        real = real.replace(char, b"\\%03o" % ord(char))
    return real in points


def _make_parents(target: Path) -> list[Path]:
    """Create the missing folders above `target`; the ones created, outermost first (to undo on failure)."""
    missing: list[Path] = []
    probe = target.parent
    while not os.path.lexists(probe) and probe.parent != probe:
        missing.append(probe)
        probe = probe.parent
    missing.reverse()
    created: list[Path] = []
    for folder in missing:
        try:
            os.mkdir(folder)
        except FileExistsError:
            continue  # made meanwhile by someone else: not ours to remove
        except OSError as exc:
            _remove_created(created)
            raise OutputError(f"{target}: cannot create {folder}: {exc.strerror}") from None
        created.append(folder)
    return created


def _remove_created(created: list[Path]) -> None:
    """Remove the folders `_make_parents` created, innermost first, if they stayed empty."""
    for folder in reversed(created):
        try:
            os.rmdir(folder)
        except OSError:
            break


def _writable_ancestor(path: Path) -> Path:
    """The nearest existing ancestor of `path`, which must let us create entries."""
    probe = path.parent
    while not os.path.lexists(probe):
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
        os.rmdir(tempfile.mkdtemp(prefix=f".grove-probe.{_HOST}-{os.getpid()}.", suffix=".tmp", dir=probe))
    except OSError as exc:
        raise OutputError(f"{path}: cannot write there ({probe}: {exc.strerror})") from None
    return probe


# -- folders --------------------------------------------------------------------------------------------------


def check_output_dir(path: str | os.PathLike[str], *, owned: OwnedTest, what: str = "GROVE output",
                     overwrite: bool = False, flag: str = "--overwrite",
                     own_folder: str | os.PathLike[str] | None = None) -> Path:
    """Check, before any work, that `path` may become (or replace) an output folder; its absolute path.

    Allowed: a path that does not exist yet (its parent writable), an empty folder, a folder `owned`
    says GROVE wrote, or any folder when `overwrite`. Refused: files, device nodes, pipes, sockets,
    symbolic links, the file system root, a non-empty folder GROVE did not write, and a protected
    folder's own entry (a bundle's trees/) unless that folder is `own_folder`.
    """
    target = absolute_path(path)
    if target.parent == target:
        raise OutputError(f"{target}: the file system root cannot be an output folder")
    _check_not_protected(target, own_folder)
    try:
        mode = os.lstat(target).st_mode
    except FileNotFoundError:
        _writable_ancestor(target)
        return target
    except NotADirectoryError:
        raise OutputError(f"{target}: cannot create it, a part of its path is a file") from None
    except OSError as exc:
        raise OutputError(f"{target}: cannot inspect it: {exc.strerror}") from None
    if not stat.S_ISDIR(mode):
        raise OutputError(f"{target}: is {_kind(mode)}, not a folder; choose a folder path for the {what}")
    if _is_mount_point(target):
        # An output folder is replaced in one rename, which the kernel refuses for a mount point (EBUSY).
        raise OutputError(f"{target}: is a mount point, which cannot be replaced in one step; choose a new "
                          f"folder inside it for the {what}")
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


def refuse_overlap(output: str | os.PathLike[str], source: str | os.PathLike[str], what: str) -> None:
    """An output folder must be neither its own input nor a folder holding it: replacing it (even with
    --overwrite) would delete what is being read."""
    out, src = Path(os.path.realpath(output)), Path(os.path.realpath(source))
    if out == src or out in src.parents:
        raise OutputError(f"{absolute_path(output)}: is {what}" + (" itself" if out == src else f" or holds it ({src})")
                          + "; choose an output folder outside it")


@contextlib.contextmanager
def atomic_directory(path: str | os.PathLike[str], *, owned: OwnedTest, what: str = "GROVE output",
                     overwrite: bool = False, flag: str = "--overwrite",
                     own_folder: str | os.PathLike[str] | None = None) -> Iterator[Path]:
    """Yield a staging folder beside `path`; on success it takes `path`'s place in one rename.

    `path` is checked with `check_output_dir` first (and again just before the swap, in case it
    changed meanwhile). On any exception, Ctrl-C included, the staging folder and any parent folder
    made for it are removed and `path` is left as it was; a storage failure (full disk, read-only
    file system) is an OutputError naming `path`. A staging folder a killed process left is removed
    by the next write beside it.
    """
    guard = DirGuard(owned=owned, what=what, overwrite=overwrite, flag=flag, own_folder=own_folder)
    target = check_output_dir(path, **guard)
    created = _make_parents(target)
    sweep_stale(target.parent, target.name)
    try:
        staging = Path(tempfile.mkdtemp(prefix=_staging_prefix(target), suffix=".staging", dir=target.parent))
    except OSError as exc:
        _remove_created(created)
        raise OutputError(f"{target}: cannot write there: {exc.strerror}") from None
    try:
        _usual_mode(staging, directory=True)
        write_point(f"dir:{target.name}:created")
        yield staging
        write_point(f"dir:{target.name}:staged")
        check_output_dir(target, **guard)
        _swap_in(staging, target)
    except BaseException as exc:
        shutil.rmtree(staging, ignore_errors=True)
        _remove_created(created)
        if isinstance(exc, OSError) and exc.errno in WRITE_FAILURE_ERRNOS:
            raise OutputError(f"{target}: cannot write it: {exc.strerror}") from None
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


# renameat2(2) with RENAME_EXCHANGE swaps two paths in one step (Linux 3.15+, most local file systems).
_AT_FDCWD = -100
_RENAME_EXCHANGE = 2
_NO_EXCHANGE = frozenset({errno.EINVAL, errno.ENOSYS, errno.EOPNOTSUPP, errno.ENOTSUP})


def _libc_renameat2() -> Callable[..., int] | None:
    try:
        libc = ctypes.CDLL(None, use_errno=True)
    except OSError:
        return None
    return getattr(libc, "renameat2", None)


_RENAMEAT2 = _libc_renameat2()


def _exchange(first: Path, second: Path) -> bool:
    """Swap two existing paths atomically; False where the system or file system cannot."""
    if _RENAMEAT2 is None:
        return False
    if _RENAMEAT2(_AT_FDCWD, os.fsencode(first), _AT_FDCWD, os.fsencode(second), _RENAME_EXCHANGE) == 0:
        return True
    code = ctypes.get_errno()
    if code in _NO_EXCHANGE:
        return False
    raise OSError(code, os.strerror(code), str(second))


def _swap_in(staging: Path, target: Path) -> None:
    """Put `staging` at `target` in one step; an existing `target` folder is removed afterwards.

    With an atomic exchange, `target` always names a complete folder (the old one, then the new);
    the old one, left at the staging name, is removed (or swept, if the process dies first).
    Without it, the old folder is moved aside first; a crash in that window leaves it at `.old`,
    which `sweep_stale` puts back.
    """
    try:
        if os.path.lexists(target):
            if _exchange(staging, target):
                write_point(f"dir:{target.name}:exchanged")
                shutil.rmtree(staging, ignore_errors=True)
                return
            backup = Path(tempfile.mkdtemp(prefix=_staging_prefix(target), suffix=".old", dir=target.parent))
            os.rmdir(backup)  # a unique free name for the old folder, on the same file system
            os.replace(target, backup)
            write_point(f"dir:{target.name}:moved-aside")
            try:
                os.replace(staging, target)
            except BaseException:
                os.replace(backup, target)
                raise
            shutil.rmtree(backup, ignore_errors=True)
        else:
            os.replace(staging, target)
        write_point(f"dir:{target.name}:swapped")
    except OSError as exc:
        if exc.errno in (errno.EACCES, errno.EPERM, errno.EROFS, errno.EBUSY, errno.EXDEV):
            raise OutputError(f"{target}: cannot write there: {exc.strerror}") from None
        raise


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
