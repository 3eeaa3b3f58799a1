"""BehaviorTree.CPP's `<include path="..."/>`, resolved safely, so HuNavSim's own tree files load.

HuNavSim's shipped trees include each other (BTSurprisedNav.xml includes BTRegularNav.xml and calls
it as a SubTree). BT.CPP resolves a relative include against the folder of the including file
(XMLParser::PImpl::loadDocImpl, `current_path`); so does this module. Since tree files come from
users and other tools, it also refuses what BT.CPP would follow blindly:

- a path that leaves the allowed folders (by default the folder of the first file), through `..`,
  an absolute path or a symbolic link;
- include chains deeper than MAX_INCLUDE_DEPTH, and cycles;
- `ros_pkg` includes (a ROS package path needs a ROS installation to resolve);
- more than MAX_INCLUDED_FILES files, or files over bt/format/source.py's MAX_BYTES (read_file_bytes).

A file included twice (two trees including the same helper) is inlined once. The result is one
document whose <BehaviorTree> elements are the including file's followed by the included ones.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from lxml import etree

from grove_tui.bt.format.source import read_file_bytes
from grove_tui.errors import BTError

MAX_INCLUDE_DEPTH = 8
MAX_INCLUDED_FILES = 64


def _parser() -> etree.XMLParser:
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False,
                           remove_comments=True)


def _read(path: Path) -> etree._Element:
    if not path.exists():
        raise BTError(f"{path}: no such behavior-tree file")
    data = read_file_bytes(path)  # regular files only, size-limited (bt/format/source.py)
    try:
        return etree.fromstring(data, _parser())
    except etree.XMLSyntaxError as exc:
        raise BTError(f"{path}:{exc.lineno}: not well-formed XML: {exc.msg}") from None


def _inside(path: Path, roots: Sequence[Path]) -> bool:
    return any(path == root or root in path.parents for root in roots)


def has_includes(data: bytes) -> bool:
    return b"<include" in data


def _resolve(first: Path, allowed_roots: Sequence[str | Path] | None,
             max_depth: int) -> tuple[etree._Element, list[Path]]:
    roots = [Path(os.path.realpath(r)) for r in (allowed_roots or [first.parent])]
    seen: set[Path] = set()
    document = _read(first)
    seen.add(Path(os.path.realpath(first)))
    collected: list[etree._Element] = []
    order: list[Path] = []
    _inline(document, first, roots, seen, collected, depth=0, max_depth=max_depth, chain=(first,), order=order)
    for tree in collected:
        document.append(tree)
    return document, order


def resolve_includes(path: str | os.PathLike[str], allowed_roots: Sequence[str | Path] | None = None,
                     max_depth: int = MAX_INCLUDE_DEPTH) -> bytes:
    """The tree file with every <include> inlined (see the module docstring); BTError says why not."""
    document, _files = _resolve(Path(path), allowed_roots, max_depth)
    return etree.tostring(document, encoding="utf-8")


def included_files(path: str | os.PathLike[str], allowed_roots: Sequence[str | Path] | None = None,
                   max_depth: int = MAX_INCLUDE_DEPTH) -> list[Path]:
    """The files `resolve_includes` reads for `path` besides it, in the order it reads them (each once)."""
    return _resolve(Path(path), allowed_roots, max_depth)[1]


def _inline(root: etree._Element, source: Path, roots: Sequence[Path], seen: set[Path],
            collected: list[etree._Element], *, depth: int, max_depth: int, chain: tuple[Path, ...],
            order: list[Path]) -> None:
    for include in [el for el in root if el.tag == "include"]:
        where = f"{source}:{include.sourceline}"
        root.remove(include)
        if include.get("ros_pkg"):
            raise BTError(f"{where}: <include ros_pkg=...> needs ROS to find the package; copy the file beside "
                          "this one and include it by a relative path")
        target = include.get("path")
        if not target:
            raise BTError(f"{where}: <include> needs a path attribute")
        if depth + 1 > max_depth:
            raise BTError(f"{where}: includes nest deeper than {max_depth} files "
                          f"({' -> '.join(p.name for p in chain)} -> {target})")
        resolved = Path(os.path.realpath(source.parent / target))
        if not _inside(resolved, roots):
            allowed = ", ".join(str(r) for r in roots)
            raise BTError(f"{where}: <include path={target!r}> leaves the allowed folders ({allowed})")
        if resolved in (Path(os.path.realpath(p)) for p in chain):
            raise BTError(f"{where}: include cycle: {' -> '.join(p.name for p in chain)} -> {resolved.name}")
        if resolved in seen:
            continue
        if len(seen) >= MAX_INCLUDED_FILES:
            raise BTError(f"{where}: more than {MAX_INCLUDED_FILES} included files")
        seen.add(resolved)
        order.append(source.parent / target)
        included = _read(resolved)
        _inline(included, resolved, roots, seen, collected, depth=depth + 1, max_depth=max_depth,
                chain=chain + (resolved,), order=order)
        collected.extend(el for el in included if el.tag == "BehaviorTree")
