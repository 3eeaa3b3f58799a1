"""Behavior-tree XML in and out: the only place GROVE reads or writes BehaviorTree.CPP v4 text.

Trees come from a language model and from users, so the reader trusts nothing: no DTD, no entity
expansion, no XInclude, no network, bounded size, depth and SubTree expansion; files must be regular
files and are read with a limit. `read_tree` gives a structurally sound `TreeDocument` (for stages
that edit trees); `parse_tree_text` also validates every node and port against the manifest, and
`check_tree_text` reports *every* problem with its line, so one `grove bt validate` run shows them all.
`write_tree` is the one serialisation: two-space indentation, one element per line, attributes in
document order, so a tree read and written again is byte-identical.

Accepted format (BT.CPP v4):
    <root BTCPP_format="4" main_tree_to_execute="MainTree">
      <BehaviorTree ID="MainTree"> <Sequence> <GoTo target="pharmacy"/> ... </Sequence> </BehaviorTree>
      <BehaviorTree ID="Other"> ... </BehaviorTree>
      <TreeNodesModel> ... </TreeNodesModel>          (kept, not validated)
    </root>
Nodes are written compactly (<GoTo .../>) or explicitly (<Action ID="GoTo" .../>). A port value is a
literal or a blackboard pointer "{key}". <SubTree ID="X" port="{key}" _autoremap="true"/> calls tree X.
Files: <include path="..."/> is inlined by load_tree_file/check_tree_file (bt/format/include.py: relative to the
including file, depth-limited, never outside its folder); in text it is rejected with a clear message.
Not supported (rejected with a clear message): scripting attributes (_skipIf, _while...).
"""

from __future__ import annotations

import difflib
import heapq
import os
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from grove_tui.bt.format.document import (
    BEHAVIOR_TREE, EXPLICIT_TAGS, TREE_NODES_MODEL, TreeDocument, TreeElement,
)
from grove_tui.bt.format.manifest import NODES, SUBTREE, NodeSpec
from grove_tui.bt.format.include import has_includes, resolve_includes
from grove_tui.bt.format.ports import blackboard_pointer, checked_port, convert_literal, satisfied_by_goal_id
from grove_tui.bt.format.source import MAX_BYTES, located_error, read_file_bytes
from grove_tui.errors import BTError

MAX_DEPTH = 64  # element nesting inside one file
MAX_NODES = 5_000  # elements in one file
# A SubTree call puts the called tree below the caller: nesting and node count after expanding every
# call are bounded too, or a short chain of SubTrees (each calling the next twice) grows exponentially
# and a long one overflows the runtime's recursion when it is built or ticked.
MAX_EXPANDED_DEPTH = 128
MAX_EXPANDED_NODES = 20_000
# "Did you mean" costs one string comparison per candidate: beyond these, a file of thousands of
# misspelt names would spend minutes on suggestions nobody reads.
MAX_SUGGESTIONS = 20
MAX_SUGGESTION_CANDIDATES = 500
MAX_PROBLEMS = 200

_SCRIPTING_ATTRIBUTES = {"_skipIf", "_successIf", "_failureIf", "_while", "_onSuccess", "_onFailure", "_onHalted",
                         "_post"}
_FORMAT = "4"


@dataclass(frozen=True)
class BTProblem:
    source: str
    line: int | None
    message: str

    def __str__(self) -> str:
        where = f"{self.source}:{self.line}" if self.line else self.source
        return f"{where}: {self.message}"


# ---- reading ----------------------------------------------------------------------------------

def _hardened_parser() -> etree.XMLParser:
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, dtd_validation=False,
                           huge_tree=False, remove_comments=True, remove_pis=True, collect_ids=False)


def _as_bytes(text: str | bytes, source: str) -> bytes:
    if isinstance(text, bytes):
        return text
    if text.lstrip().startswith("<?xml"):
        # lxml refuses str input with an encoding declaration
        text = text.split("?>", 1)[1] if "?>" in text else text
    try:
        return text.encode("utf-8")
    except UnicodeEncodeError as exc:  # a lone surrogate, e.g. from a JSON "\ud800" escape
        raise located_error(source, None, f"not valid Unicode text ({exc.reason} at character {exc.start})") from None


def _parse_lxml(data: bytes, source: str) -> etree._Element:
    if len(data) > MAX_BYTES:
        raise located_error(source, None, f"file is {len(data)} bytes; behavior trees are limited to {MAX_BYTES} bytes")
    if not data.strip():
        raise located_error(source, None, 'empty file; a behavior tree is <root BTCPP_format="4"><BehaviorTree ID=...>')
    lowered = data.lower()
    # DTDs are how entity bombs and external entities get in; BT.CPP never needs one.
    found = [i for i in (lowered.find(b"<!doctype"), lowered.find(b"<!entity")) if i >= 0]
    if found:
        line = data[: min(found)].count(b"\n") + 1
        raise located_error(source, line, "DOCTYPE/ENTITY declarations are not allowed in behavior trees "
                                   "(no DTDs, no entities)")
    try:
        root = etree.fromstring(data, _hardened_parser())
    except etree.XMLSyntaxError as exc:
        msg = (exc.msg if getattr(exc, "msg", None) else str(exc)).splitlines()[0]
        raise located_error(source, exc.lineno or None, f"not well-formed XML: {msg}") from None
    docinfo = root.getroottree().docinfo
    if docinfo.internalDTD is not None or docinfo.externalDTD is not None or docinfo.doctype:
        raise located_error(source, None, "DOCTYPE declarations are not allowed in behavior trees")
    return root


def _refuse_namespaces(element: etree._Element, source: str) -> None:
    """BT.CPP files use no XML namespaces; a namespaced name (<xi:include>) could not be written back as read."""
    names = [str(element.tag), *(str(name) for name in element.attrib)]
    if any(name.startswith("{") for name in names):
        raise located_error(source, element.sourceline, f"<{element.prefix}:{etree.QName(element).localname}>: XML "
                                                       "namespaces are not used in behavior trees"
                            if element.prefix else "XML namespaces are not used in behavior trees")


def _to_elements(root: etree._Element, source: str) -> TreeElement:
    """lxml tree -> TreeElement tree, iteratively, refusing entities, namespaces, depth and size beyond the limits."""
    _refuse_namespaces(root, source)
    top = TreeElement(str(root.tag), dict(root.attrib), [], root.sourceline, (root.text or "").strip())
    stack = [(root, top, 1)]
    count = 0
    while stack:
        el, converted, depth = stack.pop()
        count += 1
        if depth > MAX_DEPTH:
            raise located_error(source, el.sourceline, f"tree nesting is deeper than {MAX_DEPTH} levels")
        if count > MAX_NODES:
            raise located_error(source, None, f"more than {MAX_NODES} XML elements")
        for child in el:
            if isinstance(child, etree._Entity):
                raise located_error(source, child.sourceline, "entity references are not allowed in behavior trees")
            if not isinstance(child.tag, str):
                continue
            _refuse_namespaces(child, source)
            kid = TreeElement(child.tag, dict(child.attrib), [], child.sourceline, (child.text or "").strip())
            converted.children.append(kid)
            stack.append((child, kid, depth + 1))
    return top


def _read_elements(text: str | bytes, source: str) -> TreeElement:
    return _to_elements(_parse_lxml(_as_bytes(text, source), source), source)


def _document(root: TreeElement, source: str) -> TreeDocument:
    """The TreeDocument of a structurally sound element tree (the checks of `_check_structure` passed)."""
    trees = {el.attributes["ID"]: el for el in root.children if el.tag == BEHAVIOR_TREE}
    models = [el for el in root.children if el.tag == TREE_NODES_MODEL]
    main = root.attributes.get("main_tree_to_execute") or next(iter(trees))
    return TreeDocument(main, trees, source, models)


def read_tree(text: str | bytes, source: str = "<string>") -> TreeDocument:
    """Hardened read of a tree for stages that edit it: structure checked, nodes not (see parse_tree_text).

    BTError on XML that is not well-formed, hostile, over a limit, or not <root> with BehaviorTrees.
    """
    root = _read_elements(text, source)
    out = _Collector(source)
    _check_structure(root, out)
    if out.problems:
        raise out.error()
    return _document(root, source)


def read_tree_file(path: str | os.PathLike[str]) -> TreeDocument:
    return read_tree(read_file_bytes(path), str(path))


# ---- writing ----------------------------------------------------------------------------------

# Characters XML 1.0 cannot carry at all, not even as character references.
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")
_ATTRIBUTE_ESCAPES = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "\n": "&#10;",
                                    "\r": "&#13;", "\t": "&#9;"})
_TEXT_ESCAPES = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;"})


def _unwritable(element: TreeElement) -> str | None:
    """Why `element` cannot be written as XML (a character XML cannot carry), or None."""
    for name, value in [("<tag>", element.tag), ("<text>", element.text), *element.attributes.items()]:
        bad = _NOT_XML.search(str(name) + str(value))
        if bad:
            return f"<{element.tag}> {name}: character U+{ord(bad.group()):04X} cannot be written in XML"
    return None


def _check_writable(element: TreeElement, source: str) -> None:
    problem = _unwritable(element)
    if problem is not None:
        raise BTError(f"{source}: {problem}")


def _write_element(element: TreeElement, depth: int, lines: list[str], source: str) -> None:
    # an explicit stack, not recursion: documents are bounded by MAX_DEPTH but code-built ones are not
    stack: list[tuple[TreeElement, int, bool]] = [(element, depth, False)]
    while stack:
        el, level, closing = stack.pop()
        pad = "  " * level
        if not closing:
            _check_writable(el, source)
        if closing:
            lines.append(f"{pad}</{el.tag}>")
            continue
        attributes = "".join(f' {k}="{str(v).translate(_ATTRIBUTE_ESCAPES)}"' for k, v in el.attributes.items())
        text = el.text.translate(_TEXT_ESCAPES)
        if not el.children:
            lines.append(f"{pad}<{el.tag}{attributes}>{text}</{el.tag}>" if text else f"{pad}<{el.tag}{attributes}/>")
            continue
        lines.append(f"{pad}<{el.tag}{attributes}>{text}")
        stack.append((el, level, True))
        stack.extend((child, level + 1, False) for child in reversed(el.children))


def write_tree(document: TreeDocument) -> str:
    """The document as BT.CPP v4 XML text (UTF-8 declaration, two-space indentation, trailing newline).

    BTError when a value holds a character XML cannot carry (control characters, lone surrogates)."""
    if _NOT_XML.search(document.main_tree_id):
        raise BTError(f"{document.source}: main tree ID {document.main_tree_id!r} cannot be written in XML")
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             f'<root BTCPP_format="{_FORMAT}" main_tree_to_execute="'
             f'{document.main_tree_id.translate(_ATTRIBUTE_ESCAPES)}">']
    for tree in document.trees.values():
        _write_element(tree, 1, lines, document.source)
    for model in document.models:
        _write_element(model, 1, lines, document.source)
    lines.append("</root>")
    return "\n".join(lines) + "\n"


# ---- validation -------------------------------------------------------------------------------

class _Collector:
    def __init__(self, source: str):
        self.source = source
        self.problems: list[BTProblem] = []
        self.dropped = 0
        self.suggestions_left = MAX_SUGGESTIONS

    def add(self, line: int | None, message: str) -> None:
        if len(self.problems) < MAX_PROBLEMS:
            self.problems.append(BTProblem(self.source, line, message))
        else:
            self.dropped += 1

    def finish(self) -> list[BTProblem]:
        if self.dropped:
            return self.problems + [BTProblem(self.source, None, f"... and {self.dropped} more problem(s)")]
        return self.problems

    def error(self) -> BTError:
        problems = self.finish()
        if len(problems) == 1:
            return BTError(str(problems[0]))
        listed = "\n".join(f"  line {p.line}: {p.message}" if p.line else f"  {p.message}" for p in problems)
        return BTError(f"{self.source}: {len(problems)} problem(s) in behavior tree:\n{listed}")

    def suggest(self, name: str, known: Iterable[str]) -> str:
        """' (did you mean X?)' for a misspelt name, within the suggestion budget."""
        if self.suggestions_left <= 0:
            return ""
        self.suggestions_left -= 1
        # difflib's ratio is at most 2*min(len)/(len a + len b): names whose lengths rule out the cutoff
        # are skipped; of the rest, only the closest by the cheap character-count bound (quick_ratio)
        # get the full comparison. Sorted first, so the suggestions do not depend on set order.
        candidates = sorted(k for k in known if 2 * min(len(k), len(name)) >= 0.6 * (len(k) + len(name)))
        if len(candidates) > MAX_SUGGESTION_CANDIDATES:
            matcher = difflib.SequenceMatcher(b=name)

            def bound(candidate: str) -> float:
                matcher.set_seq1(candidate)
                return matcher.quick_ratio()

            candidates = heapq.nlargest(MAX_SUGGESTION_CANDIDATES, candidates, key=bound)
        close = difflib.get_close_matches(name, candidates, n=3, cutoff=0.6)
        return f" (did you mean {', '.join(close)}?)" if close else ""


def _a(word: str) -> str:
    return f"an {word}" if word[0] in "aeiou" else f"a {word}"


def _check_structure(root: TreeElement, out: _Collector) -> set[str]:
    """<root>, its BehaviorTrees (IDs, one root node each) and main tree; returns the tree IDs."""
    if root.tag != "root":
        out.add(root.line, f"the top element must be <root>, found <{root.tag}>")
        return set()
    fmt = root.attributes.get("BTCPP_format")
    if fmt is not None and fmt.strip() != _FORMAT:
        out.add(root.line, f"BTCPP_format must be \"4\" (BehaviorTree.CPP v4), found {fmt!r}")
    trees: list[TreeElement] = []
    for child in root.children:
        if child.tag == BEHAVIOR_TREE:
            trees.append(child)
        elif child.tag == TREE_NODES_MODEL:
            continue
        elif child.tag == "include":
            out.add(child.line, "<include> is resolved only for tree files (grove bt validate FILE), "
                                "not in text: put every BehaviorTree in the same file")
        else:
            out.add(child.line, f"unexpected <{child.tag}> under <root>; expected <BehaviorTree>")
    if not trees:
        out.add(root.line, "no <BehaviorTree> in the file")
        return set()
    tree_ids: set[str] = set()
    for el in trees:
        tid = el.attributes.get("ID")
        if not tid:
            out.add(el.line, "<BehaviorTree> needs an ID attribute")
        elif tid in tree_ids:
            out.add(el.line, f"BehaviorTree ID {tid!r} is defined twice")
        else:
            tree_ids.add(tid)
        if len(el.children) != 1:
            out.add(el.line, f"BehaviorTree {tid!r} must have exactly one root node, has {len(el.children)}")
    main = root.attributes.get("main_tree_to_execute")
    if main is None:
        if len(tree_ids) > 1:
            out.add(root.line, "several BehaviorTrees but no main_tree_to_execute attribute on <root>")
    elif main not in tree_ids:
        out.add(root.line, f"main_tree_to_execute={main!r} names no BehaviorTree{out.suggest(main, tree_ids)}")
    return tree_ids


def _check_node(el: TreeElement, nodes: Mapping[str, NodeSpec], tree_ids: set[str], out: _Collector) -> None:
    """Problems of one node (not its children); unknown nodes are reported, their children still checked."""
    tag = el.tag
    line = el.line
    attrs = dict(el.attributes)
    if tag in EXPLICIT_TAGS or tag == SUBTREE:
        node_id = attrs.pop("ID", None)
        if not node_id:
            out.add(line, f"<{tag}> needs an ID attribute naming the node")
            return
    else:
        node_id = tag
        attrs.pop("ID", None)
    for meta in ("name", "_description", "_uid", "_fullpath"):
        attrs.pop(meta, None)
    for attr in list(attrs):
        if attr in _SCRIPTING_ATTRIBUTES:
            out.add(line, f"{node_id}: scripting attribute {attr} is not supported")
            attrs.pop(attr)
    n = len(el.children)

    if tag == SUBTREE:
        autoremap_text = attrs.pop("_autoremap", "false").strip().lower()
        if autoremap_text not in ("true", "false", "1", "0"):
            out.add(line, f"SubTree {node_id}: _autoremap must be true or false, got {autoremap_text!r}")
        if node_id not in tree_ids:
            out.add(line, f"SubTree refers to unknown BehaviorTree ID {node_id!r}{out.suggest(node_id, tree_ids)}")
        if n:
            out.add(line, f"SubTree {node_id} must not have children")
        for attr in attrs:
            if attr.startswith("_"):
                out.add(line, f"SubTree {node_id}: unknown attribute {attr}")
        return

    spec = nodes.get(node_id)
    if spec is None:
        out.add(line, f"unknown node {node_id!r}{out.suggest(node_id, nodes)}")
        return
    if tag in EXPLICIT_TAGS and EXPLICIT_TAGS[tag] != spec.category:
        out.add(line, f"{node_id} is {_a(spec.category)}, not {_a(EXPLICIT_TAGS[tag])}")
    present: set[str] = set()
    for attr, value in attrs.items():
        port = spec.port(attr)
        if port is None:
            known = ", ".join(spec.port_names) or "none"
            out.add(line, f"{node_id}: unknown port {attr!r}{out.suggest(attr, spec.port_names)}; "
                          f"its ports are: {known}")
            continue
        present.add(attr)
        key = blackboard_pointer(value)
        if port.direction == "out":
            if key is None:
                out.add(line, f"{node_id}: output port {attr!r} must name a blackboard entry like '{{{attr}}}', "
                              f"got {value!r}")
            continue
        if key is not None:
            continue
        if value.strip().startswith("{"):
            out.add(line, f"{node_id}: port {attr!r} value {value!r} is not a valid blackboard pointer '{{key}}'")
            continue
        try:
            convert_literal(checked_port(spec, port), value)
        except ValueError as exc:
            out.add(line, f"{node_id}: port {attr!r} ({port.type}): {exc}")
    for port in spec.ports:
        if port.required and port.name not in present and not satisfied_by_goal_id(port, present):
            out.add(line, f"{node_id}: missing required port {port.name!r} ({port.type}: {port.description})")
    if spec.category == "control" and n == 0:
        out.add(line, f"{node_id} needs at least one child")
    elif spec.category == "decorator" and n != 1:
        out.add(line, f"{node_id} is a decorator and needs exactly one child, has {n}")
    elif spec.category in ("action", "condition") and n:
        out.add(line, f"{node_id} is {_a(spec.category)} and cannot have children")


def _check_subtree_calls(document: TreeDocument, out: _Collector) -> None:
    """Recursion, and nesting/size after expanding SubTree calls, from the main tree; iterative."""
    calls: dict[str, list[tuple[str, int | None, int]]] = {}  # tree -> (callee, line, depth of the call)
    own: dict[str, tuple[int, int]] = {}  # tree -> (its own depth, its own node count)
    for tid, tree in document.trees.items():
        depth_of = {id(tree): 0}
        deepest, count, found = 0, 0, []
        for el in tree.walk():
            d = depth_of[id(el)]
            for child in el.children:
                depth_of[id(child)] = d + 1
            if el is tree:
                continue
            count += 1
            deepest = max(deepest, d)
            if el.tag == SUBTREE and el.subtree_id in document.trees:
                found.append((el.subtree_id, el.line, d))
        calls[tid], own[tid] = found, (deepest, count)

    # depth-first over the call graph with an explicit stack; state 1 = on the stack, 2 = done
    state: dict[str, int] = {}
    depth: dict[str, int] = {}
    size: dict[str, int] = {}
    stack: list[tuple[str, int]] = [(document.main_tree_id, 0)]
    chain: list[str] = []
    while stack:
        tid, next_call = stack.pop()
        if next_call == 0:
            state[tid] = 1
            chain.append(tid)
        callees = calls[tid]
        if next_call < len(callees):
            stack.append((tid, next_call + 1))
            callee, line, _ = callees[next_call]
            if state.get(callee) == 1:
                out.add(line, f"SubTree recursion: {' -> '.join(chain[chain.index(callee):] + [callee])}")
            elif callee not in state:
                stack.append((callee, 0))
            continue
        # every callee is done: this tree's expanded depth and size
        own_depth, own_count = own[tid]
        depth[tid] = max([own_depth] + [d + depth.get(c, 0) for c, _, d in callees])
        size[tid] = min(own_count + sum(size.get(c, 0) for c, _, _ in callees), MAX_EXPANDED_NODES + 1)
        state[tid] = 2
        chain.pop()
    main = document.main_tree_id
    if depth.get(main, 0) > MAX_EXPANDED_DEPTH:
        out.add(document.tree_line(main), f"SubTree calls nest {depth[main]} levels deep from {main!r}; "
                                          f"the limit is {MAX_EXPANDED_DEPTH}")
    if size.get(main, 0) > MAX_EXPANDED_NODES:
        out.add(document.tree_line(main), f"expanding the SubTree calls of {main!r} gives more than "
                                          f"{MAX_EXPANDED_NODES} nodes")


def _validate(root: TreeElement, source: str, nodes: Mapping[str, NodeSpec]) -> tuple[TreeDocument | None, _Collector]:
    out = _Collector(source)
    tree_ids = _check_structure(root, out)
    if not tree_ids:
        return None, out
    for tree in root.children:
        if tree.tag != BEHAVIOR_TREE:
            continue
        for child in tree.children:
            for el in child.walk():
                _check_node(el, nodes, tree_ids, out)
    if out.problems:
        return None, out
    document = _document(root, source)
    _check_subtree_calls(document, out)
    return (None if out.problems else document), out


def check_tree_text(text: str | bytes, source: str = "<string>",
                    nodes: Mapping[str, NodeSpec] = NODES) -> list[BTProblem]:
    """Every problem of a tree (empty when valid). Fatal XML problems give one entry."""
    try:
        root = _read_elements(text, source)
    except BTError as exc:
        return [BTProblem(source, exc.line, exc.detail or str(exc))]
    return _validate(root, source, nodes)[1].finish()


def parse_tree_text(text: str | bytes, source: str = "<string>",
                    nodes: Mapping[str, NodeSpec] = NODES) -> TreeDocument:
    """Read and validate against the manifest; BTError lists every problem with its line."""
    document, out = _validate(_read_elements(text, source), source, nodes)
    if document is None:
        raise out.error()
    return document


def _as_root(document: TreeDocument, out: _Collector) -> TreeElement:
    """The <root> element a document is written as, its elements checked as reading checks a file's: every
    value writable in XML, nesting and size within the limits. Problems go to `out`."""
    root = TreeElement("root", {"BTCPP_format": _FORMAT, "main_tree_to_execute": document.main_tree_id},
                       [*document.trees.values(), *document.models])
    count = 0
    stack = [(root, 1)]
    while stack:
        element, depth = stack.pop()
        count += 1
        if depth > MAX_DEPTH:
            out.add(element.line, f"tree nesting is deeper than {MAX_DEPTH} levels")
            break
        if count > MAX_NODES:
            out.add(None, f"more than {MAX_NODES} XML elements")
            break
        problem = _unwritable(element)
        if problem is not None:
            out.add(element.line, problem)
        stack.extend((child, depth + 1) for child in element.children)
    return root


def check_document(document: TreeDocument, nodes: Mapping[str, NodeSpec] = NODES,
                   source: str | None = None) -> list[BTProblem]:
    """Every problem of a document built or edited in code (empty when valid): what `check_tree_text`
    would report of it written out, without writing and reading it back. `source` names it in the
    problems (default: the document's own source)."""
    where = document.source if source is None else source
    out = _Collector(where)
    root = _as_root(document, out)
    if out.problems:
        return out.finish()
    return _validate(root, where, nodes)[1].finish()


def validate_document(document: TreeDocument, nodes: Mapping[str, NodeSpec] = NODES) -> TreeDocument:
    """`document` itself when it is valid against the manifest (as `parse_tree_text` would find it written
    out); BTError listing every problem otherwise."""
    out = _Collector(document.source)
    root = _as_root(document, out)
    if not out.problems:
        out = _validate(root, document.source, nodes)[1]
    if out.problems:
        raise out.error()
    return document


def load_tree_file(path: str | os.PathLike[str], nodes: Mapping[str, NodeSpec] = NODES) -> TreeDocument:
    return parse_tree_text(_with_includes(path, read_file_bytes(path)), str(path), nodes)


def check_tree_file(path: str | os.PathLike[str], nodes: Mapping[str, NodeSpec] = NODES) -> list[BTProblem]:
    try:
        data = read_file_bytes(path)
    except BTError as exc:
        return [BTProblem(str(path), exc.line, exc.detail or str(exc))]
    return check_tree_bytes(path, data, nodes)


def check_tree_bytes(path: str | os.PathLike[str], data: bytes,
                     nodes: Mapping[str, NodeSpec] = NODES) -> list[BTProblem]:
    """Every problem of a tree file already read (read_file_bytes); its `<include>`s are read from its folder.

    Apart from check_tree_file so `grove bt validate` can tell a file it could not read (exit 2)
    from a file with problems (exit 1)."""
    try:
        data = _with_includes(path, data)
    except BTError as exc:
        return [BTProblem(str(path), exc.line, exc.detail or str(exc))]
    return check_tree_text(data, str(path), nodes)


def _with_includes(path: str | os.PathLike[str], data: bytes) -> bytes:
    """A tree file's `<include>`s inlined, within its folder (bt/format/include.py)."""
    return resolve_includes(path) if has_includes(data) else data
