"""Input limits checked before anything is built: bounded reads, bounded YAML, bounded .npz files.

Every file GROVE reads may come from a careless or hostile user. These helpers refuse, with one
line naming the file and the limit, what would otherwise hang or exhaust memory: device nodes and
pipes given as files, oversized files, YAML alias bombs and recursive aliases, deep nesting,
zip bombs inside `.npz` files. The limits leave ample room above the largest legitimate input.
"""

from __future__ import annotations

import os
import stat
import zipfile
import zlib
from pathlib import Path
from typing import Any

import yaml

from grove_tui.errors import InputLimitError

# Nodes counted with aliases expanded: a 500-byte "billion laughs" file expands to billions.
MAX_YAML_NODES = 5_000_000
# A world's zones[i].entities[j].footprint[k][0] is 6 deep; nothing GROVE reads nests deeper than ~10.
MAX_YAML_DEPTH = 32
# Digits in one YAML number: the interpreter refuses ints past 4,300 digits, floats overflow far sooner.
MAX_NUMBER_DIGITS = 1000

# People in one group of one prompt ("500 people evacuate"): the bound of every preset's
# limits.max_count and of the draft grammar's counts. A preset may allow fewer (presets/*.yaml); the
# emergency preset allows this many, spread over the building when the prompt places them nowhere.
# 500 is the dense hospital evacuation of bench/evacuation.py (docs/HOSTILE.md).
MAX_GROUP_COUNT = 500
# Groups in one scenario: the draft grammar's bound (generation/draft.py), so generation never writes
# more than MAX_GROUPS * MAX_GROUP_COUNT people; an imported scenario is held to the same.
MAX_GROUPS = 16
MAX_SCENARIO_AGENTS = MAX_GROUPS * MAX_GROUP_COUNT

# Coordinates in metres a scenario can use: the bound of the behavior-tree ports that carry points
# (GoTo x/y, bt/format/manifest.py). A world, an imported scenario or a bundle beyond it would load and then
# fail at generation ("GoTo port x above maximum 10000"), so every reader refuses it up front.
MAX_COORDINATE = 10_000.0
# Grids and velocity fields pad the world by a few cells: their stored origins may lie this far out.
MAX_PADDED_COORDINATE = MAX_COORDINATE + 100.0

YamlPath = tuple[str | int, ...]

# libyaml's loader has the same safe semantics and keeps node marks, and it is ~20x faster.
_SAFE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def _describe_mode(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISFIFO(mode):
        return "a pipe"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def check_regular_file(path: str | os.PathLike[str], max_bytes: int, what: str) -> int:
    """The size of `path` after checking it is a regular file (links followed) of at most `max_bytes`.

    A device such as /dev/zero reads forever and a pipe blocks, so both are refused before opening.
    """
    file = Path(path)
    try:
        mode = os.stat(file)
    except FileNotFoundError:
        raise InputLimitError(f"{what} {file} does not exist") from None
    except OSError as exc:
        raise InputLimitError(f"{what} {file}: cannot read it: {exc.strerror}") from None
    if not stat.S_ISREG(mode.st_mode):
        raise InputLimitError(f"{what} {file} is {_describe_mode(mode.st_mode)}, not a file")
    if mode.st_size > max_bytes:
        raise InputLimitError(f"{what} {file} is {_human(mode.st_size)}; the limit is {_human(max_bytes)}")
    return mode.st_size


def read_bytes_bounded(path: str | os.PathLike[str], max_bytes: int, what: str) -> bytes:
    """The whole file, refusing special files and anything over `max_bytes` (checked again while reading,
    because the file can grow between the check and the read)."""
    check_regular_file(path, max_bytes, what)
    try:
        with open(path, "rb") as handle:
            data = handle.read(max_bytes + 1)
    except OSError as exc:
        raise InputLimitError(f"{what} {path}: cannot read it: {exc.strerror}") from None
    if len(data) > max_bytes:
        raise InputLimitError(f"{what} {path} is larger than {_human(max_bytes)}")
    return data


def read_text_bounded(path: str | os.PathLike[str], max_bytes: int, what: str) -> str:
    data = read_bytes_bounded(path, max_bytes, what)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputLimitError(f"{what} {path} is not UTF-8 text (byte {exc.start} cannot be decoded)") from None


def _human(size: int) -> str:
    for unit, scale in (("GB", 1 << 30), ("MB", 1 << 20), ("kB", 1 << 10)):
        if size >= scale:
            return f"{size / scale:.1f} {unit}"
    return f"{size} bytes"


# --------------------------------------------------------------------------------------------
# YAML


def compose_yaml(text: str, locate: bool = True) -> tuple[Any, dict[YamlPath, int], list[YamlPath]]:  # Any: YAML before validation
    """Parse YAML with safe semantics, checking the node graph against the limits first.

    Returns (data, line of every node by its path, paths of repeated mapping keys, each ending in
    "#repeat"). The node graph is walked before Python objects are constructed, so a recursive alias
    or an alias bomb never reaches the constructor or the caller's validators. Broken YAML raises
    yaml.YAMLError (with marks); a limit raises InputLimitError. Without `locate` the limits are checked
    but no line map is made (lines and repeated come back empty): several times faster on big files.
    """
    loader = _SAFE_LOADER(text)
    try:
        try:
            node = loader.get_single_node()
        except RecursionError:
            # The composer recurses per nesting level; past Python's limit the file is hostile.
            raise InputLimitError(f"the YAML nests more than {MAX_YAML_DEPTH} levels deep") from None
        if node is None:
            return None, {}, []
        if locate:
            lines, repeated = _walk_nodes(node)
        else:
            lines, repeated = {}, []
            _check_limits(node)
        try:
            data = loader.construct_document(node)
        except (ValueError, OverflowError) as exc:
            # A scalar the constructor cannot convert, such as the timestamp 2020-13-45.
            text_of = str(exc)
            raise InputLimitError(f"a value cannot be read: {text_of[:120]}") from None
    finally:
        loader.dispose()
    return data, lines, repeated


def _measure(root: yaml.Node) -> None:
    """Check the expanded size, depth and recursion of the node graph in time linear in its
    *distinct* nodes: each collection's expanded size and depth are computed once (post-order) and
    reused wherever an alias repeats it, so a billion-laughs file is refused without expanding it.
    An explicit stack, not recursion, so a 10,000-deep file is reported instead of crashing."""
    size: dict[int, int] = {}
    depth: dict[int, int] = {}
    on_path: set[int] = set()
    stack: list[tuple[yaml.Node, list[yaml.Node] | None]] = [(root, None)]
    while stack:
        node, kids = stack.pop()
        key = id(node)
        if kids is not None:
            # Second visit: every child is measured.
            on_path.discard(key)
            total, deepest = 1, 0
            for kid in kids:
                kid_key = id(kid)
                if kid_key in size:
                    total += size[kid_key]
                    deepest = max(deepest, depth[kid_key])
                else:  # a scalar
                    total += 1
                    if isinstance(kid, yaml.ScalarNode) and len(kid.value) > MAX_NUMBER_DIGITS \
                            and kid.tag.endswith((":int", ":float")):
                        raise InputLimitError(f"a number with {len(kid.value):,} digits is out of range",
                                              kid.start_mark.line + 1)
            size[key], depth[key] = total, deepest + 1
            line = node.start_mark.line + 1
            if total > MAX_YAML_NODES:
                raise InputLimitError(f"the YAML expands to more than {MAX_YAML_NODES:,} values (an alias counts "
                                      f"each time it is used); is an alias repeated many times?", line)
            if deepest + 1 > MAX_YAML_DEPTH:
                raise InputLimitError(f"the YAML nests more than {MAX_YAML_DEPTH} levels deep", line)
            continue
        if key in size:
            continue
        if key in on_path:
            raise InputLimitError("an alias refers to a value that contains it (recursive alias)",
                                  node.start_mark.line + 1)
        if isinstance(node, yaml.MappingNode):
            kids = [child for pair in node.value for child in pair]
        elif isinstance(node, yaml.SequenceNode):
            kids = list(node.value)
        else:
            continue
        on_path.add(key)
        stack.append((node, kids))
        stack.extend((kid, None) for kid in kids if not isinstance(kid, yaml.ScalarNode) and id(kid) not in size)


def _check_limits(root: yaml.Node) -> None:
    if isinstance(root, yaml.ScalarNode):
        if len(root.value) > MAX_NUMBER_DIGITS and root.tag.endswith((":int", ":float")):
            raise InputLimitError(f"a number with {len(root.value):,} digits is out of range", 1)
    else:
        _measure(root)


def _walk_nodes(root: yaml.Node) -> tuple[dict[YamlPath, int], list[YamlPath]]:
    """Line of every node by its YAML path, and repeated keys; the graph is measured first, so the
    walk is bounded in size and depth and has no cycles."""
    _check_limits(root)
    lines: dict[YamlPath, int] = {}
    repeated: list[YamlPath] = []
    stack: list[tuple[yaml.Node, YamlPath]] = [(root, ())]
    while stack:
        current, path = stack.pop()
        lines.setdefault(path, current.start_mark.line + 1)
        if isinstance(current, yaml.MappingNode):
            seen_keys: set[str] = set()
            for key_node, value_node in current.value:
                if isinstance(key_node, yaml.ScalarNode):
                    if key_node.value in seen_keys:
                        lines[path + (key_node.value, "#repeat")] = key_node.start_mark.line + 1
                        repeated.append(path + (key_node.value, "#repeat"))
                    seen_keys.add(key_node.value)
                    stack.append((value_node, path + (key_node.value,)))
        elif isinstance(current, yaml.SequenceNode):
            stack.extend((item, path + (index,)) for index, item in enumerate(current.value))
    return lines, repeated


def load_yaml_bounded(text: str, what: str) -> Any:  # Any: YAML before the caller validates it
    """The data of a YAML text under the limits; any problem is one InputLimitError naming `what`."""
    try:
        return compose_yaml(text, locate=False)[0]
    except InputLimitError as exc:
        where = f" (line {exc.line})" if exc.line else ""
        raise InputLimitError(f"{what}{where}: {exc}", exc.line) from None
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        where = f" (line {mark.line + 1})" if mark is not None else ""
        detail = " ".join(part for part in (exc.context, exc.problem) if part)
        if "maximum nesting depth" in detail:
            # PyYAML 6.0.4 and later stop deep nesting in the parser, before our own depth check sees it:
            # the same refusal, in the same words, whichever version is installed.
            raise InputLimitError(f"{what}{where}: the YAML nests more than its parser allows ({detail})",
                                  mark.line + 1 if mark is not None else None) from None
        raise InputLimitError(f"{what}{where}: not valid YAML: {detail}") from None
    except yaml.YAMLError as exc:
        raise InputLimitError(f"{what}: not valid YAML: {exc}") from None


# --------------------------------------------------------------------------------------------
# .npz


def check_npz(path: str | os.PathLike[str], max_file_bytes: int, max_unpacked_bytes: int, what: str) -> None:
    """Refuse an .npz that is not a regular file, is not a zip, or would unpack to more than
    `max_unpacked_bytes`, reading only the zip's central directory (no member is decompressed).

    zipfile never returns more bytes for a member than its header declares, so the declared sizes
    bound what `np.load` can allocate: a 3 MB zip bomb of 3 GB is refused here in microseconds.
    """
    check_regular_file(path, max_file_bytes, what)
    try:
        with zipfile.ZipFile(path) as archive:
            members = archive.infolist()
    except (zipfile.BadZipFile, OSError, EOFError, ValueError) as exc:
        raise InputLimitError(f"{what} {path} is not a readable .npz file (truncated or not a zip: {exc})") from None
    unpacked = sum(member.file_size for member in members)
    if unpacked > max_unpacked_bytes:
        raise InputLimitError(f"{what} {path} unpacks to {_human(unpacked)}; the limit is {_human(max_unpacked_bytes)}")


# What np.load and zipfile raise on truncated, corrupt or mislabelled arrays.
NPZ_READ_ERRORS: tuple[type[BaseException], ...] = (OSError, KeyError, ValueError, EOFError, zipfile.BadZipFile,
                                                    TypeError, IndexError, OverflowError, zlib.error)
