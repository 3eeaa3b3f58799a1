"""Hardened parsing and validation of BehaviorTree.CPP v4 XML.

Trees come from a language model and from users, so the parser trusts nothing: no DTD, no entity
expansion, no network, bounded size and depth. Validation checks every node and port against the
manifest and reports *every* problem with its line, so one `grove bt validate` run shows them all.

Accepted format (BT.CPP v4):
    <root BTCPP_format="4" main_tree_to_execute="MainTree">
      <BehaviorTree ID="MainTree"> <Sequence> <GoTo target="pharmacy"/> ... </Sequence> </BehaviorTree>
      <BehaviorTree ID="Other"> ... </BehaviorTree>
      <TreeNodesModel> ... </TreeNodesModel>          (ignored)
    </root>
Nodes are written compactly (<GoTo .../>) or explicitly (<Action ID="GoTo" .../>). A port value is a
literal or a blackboard pointer "{key}". <SubTree ID="X" port="{key}" _autoremap="true"/> calls tree X.
Files: <include path="..."/> is inlined by load_tree_file/check_tree_file (bt/include.py: relative to the
including file, depth-limited, never outside its folder); in text it is rejected with a clear message.
Not supported (rejected with a clear message): scripting attributes (_skipIf, _while...).
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from grove_tui.bt.hunav_compat import checked_port, satisfied_by_goal_id
from grove_tui.bt.manifest import NODES, SUBTREE, NodeSpec, PortSpec
from grove_tui.errors import BTError

MAX_BYTES = 1_000_000
MAX_DEPTH = 64
MAX_NODES = 5_000

_EXPLICIT_TAGS = {"Action": "action", "Condition": "condition", "Control": "control", "Decorator": "decorator"}
_BLACKBOARD_POINTER = re.compile(r"^\{([A-Za-z_@][A-Za-z0-9_.@:-]*)\}$")
_ATTRIBUTES_ANY_NODE = {"name", "ID", "_description", "_uid", "_fullpath"}
_SCRIPTING_ATTRIBUTES = {"_skipIf", "_successIf", "_failureIf", "_while", "_onSuccess", "_onFailure", "_onHalted",
                         "_post"}


@dataclass(frozen=True)
class BTProblem:
    source: str
    line: int | None
    message: str

    def __str__(self) -> str:
        where = f"{self.source}:{self.line}" if self.line else self.source
        return f"{where}: {self.message}"


@dataclass(frozen=True)
class TreeElement:
    """One node of a parsed tree, before it is instantiated by the runtime."""

    id: str  # node type (manifest name, or SubTree)
    name: str  # instance name (the `name` attribute, else the id)
    ports: Mapping[str, str]
    children: tuple[TreeElement, ...]
    line: int | None
    subtree_id: str | None = None  # for SubTree: the called BehaviorTree ID
    autoremap: bool = False  # for SubTree

    def walk(self):
        yield self
        for child in self.children:
            yield from child.walk()


@dataclass(frozen=True)
class TreeDocument:
    source: str
    main_tree_id: str
    trees: Mapping[str, TreeElement]  # BehaviorTree ID -> its single root element
    tree_lines: Mapping[str, int | None] = field(default_factory=dict)

    @property
    def main(self) -> TreeElement:
        return self.trees[self.main_tree_id]


def blackboard_pointer(value: str) -> str | None:
    """The key of a "{key}" port value, else None."""
    m = _BLACKBOARD_POINTER.match(value.strip())
    return m.group(1) if m else None


def convert_literal(port: PortSpec, text: str):
    """Convert a port literal to its Python value; ValueError says what is expected."""
    t = port.type
    s = text.strip()
    if t in ("int", "agent"):
        try:
            value = int(s)
        except ValueError:
            raise ValueError(f"expected an integer, got {text!r}") from None
    elif t == "float":
        try:
            value = float(s)
        except ValueError:
            raise ValueError(f"expected a number, got {text!r}") from None
        if value != value or value in (float("inf"), float("-inf")):
            raise ValueError(f"expected a finite number, got {text!r}")
    elif t == "bool":
        low = s.lower()
        if low in ("true", "1"):
            value = True
        elif low in ("false", "0"):
            value = False
        else:
            raise ValueError(f"expected true or false, got {text!r}")
    elif t == "agents":
        value = parse_agent_list(s)
    elif t == "point_list":
        value = parse_point_list(s)
    else:  # string, target
        value = text
        if len(value) > 1000:
            raise ValueError("text longer than 1000 characters")
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if port.min is not None and value < port.min:
            raise ValueError(f"{value} is below the minimum {port.min}")
        if port.max is not None and value > port.max:
            raise ValueError(f"{value} is above the maximum {port.max}")
    if port.choices is not None and value not in port.choices:
        raise ValueError(f"{value!r} is not one of {', '.join(port.choices)}")
    return value


def parse_agent_list(text: str) -> tuple[int, ...]:
    if not text.strip():
        return ()
    try:
        return tuple(int(part) for part in text.replace(";", ",").split(",") if part.strip())
    except ValueError:
        raise ValueError(f"expected comma-separated agent ids like '2,3', got {text!r}") from None


def parse_point_list(text: str) -> tuple[tuple[float, float], ...]:
    if not text.strip():
        return ()
    points = []
    for part in text.split(";"):
        if not part.strip():
            continue
        xy = part.split(",")
        try:
            if len(xy) != 2:
                raise ValueError
            x, y = float(xy[0]), float(xy[1])
        except ValueError:
            raise ValueError(f"expected points like 'x1,y1;x2,y2', got {part.strip()!r}") from None
        if not (abs(x) < 1e6 and abs(y) < 1e6):
            raise ValueError(f"point {part.strip()!r} is not finite")
        points.append((x, y))
    return tuple(points)


def format_point_list(points) -> str:
    return ";".join(f"{float(x):.3f},{float(y):.3f}" for x, y in points)


# ---- parsing ----------------------------------------------------------------------------------

def _hardened_parser() -> etree.XMLParser:
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, dtd_validation=False,
                           huge_tree=False, remove_comments=True, remove_pis=True, collect_ids=False)


def _parse_root(data: bytes, source: str) -> etree._Element:
    if len(data) > MAX_BYTES:
        raise BTError(f"{source}: file is {len(data)} bytes; behavior trees are limited to {MAX_BYTES} bytes")
    lowered = data.lower()
    # DTDs are how entity bombs and external entities get in; BT.CPP never needs one.
    found = [i for i in (lowered.find(b"<!doctype"), lowered.find(b"<!entity")) if i >= 0]
    if found:
        line = data[: min(found)].count(b"\n") + 1
        raise BTError(f"{source}:{line}: DOCTYPE/ENTITY declarations are not allowed in behavior trees "
                      "(no DTDs, no entities)")
    try:
        root = etree.fromstring(data, _hardened_parser())
    except etree.XMLSyntaxError as exc:
        line = exc.lineno if exc.lineno else None
        msg = exc.msg if hasattr(exc, "msg") and exc.msg else str(exc)
        raise BTError(f"{source}:{line}: not well-formed XML: {msg}" if line else f"{source}: not well-formed XML: {msg}") from None
    docinfo = root.getroottree().docinfo
    if docinfo.internalDTD is not None or docinfo.externalDTD is not None or docinfo.doctype:
        raise BTError(f"{source}: DOCTYPE declarations are not allowed in behavior trees")
    for node in root.iter():
        if isinstance(node, etree._Entity):
            raise BTError(f"{source}:{node.sourceline}: entity references are not allowed in behavior trees")
    return root


def _element_depth_ok(root: etree._Element, source: str) -> None:
    stack = [(root, 1)]
    count = 0
    while stack:
        el, depth = stack.pop()
        count += 1
        if depth > MAX_DEPTH:
            raise BTError(f"{source}:{el.sourceline}: tree nesting is deeper than {MAX_DEPTH} levels")
        if count > MAX_NODES:
            raise BTError(f"{source}: more than {MAX_NODES} XML elements")
        stack.extend((child, depth + 1) for child in el if isinstance(child.tag, str))


class _Collector:
    def __init__(self, source: str):
        self.source = source
        self.problems: list[BTProblem] = []

    def add(self, line, message):
        self.problems.append(BTProblem(self.source, line, message))


def _a(word: str) -> str:
    return f"an {word}" if word[0] in "aeiou" else f"a {word}"


def _suggest(name: str, known) -> str:
    close = difflib.get_close_matches(name, list(known), n=3, cutoff=0.6)
    return f" (did you mean {', '.join(close)}?)" if close else ""


def _convert_element(el: etree._Element, nodes: Mapping[str, NodeSpec], tree_ids: set[str],
                     out: _Collector) -> TreeElement | None:
    tag = el.tag
    attrs = dict(el.attrib)
    line = el.sourceline
    if tag in _EXPLICIT_TAGS or tag == SUBTREE:
        node_id = attrs.pop("ID", None)
        if not node_id:
            out.add(line, f"<{tag}> needs an ID attribute naming the node")
            return None
    else:
        node_id = tag
        attrs.pop("ID", None)
    name = attrs.pop("name", None) or node_id
    for meta in ("_description", "_uid", "_fullpath"):
        attrs.pop(meta, None)
    for attr in list(attrs):
        if attr in _SCRIPTING_ATTRIBUTES:
            out.add(line, f"{node_id}: scripting attribute {attr} is not supported")
            attrs.pop(attr)
    element_children = [c for c in el if isinstance(c.tag, str)]

    if tag == SUBTREE:
        autoremap_text = attrs.pop("_autoremap", "false").strip().lower()
        if autoremap_text not in ("true", "false", "1", "0"):
            out.add(line, f"SubTree {node_id}: _autoremap must be true or false, got {autoremap_text!r}")
        if node_id not in tree_ids:
            out.add(line, f"SubTree refers to unknown BehaviorTree ID {node_id!r}{_suggest(node_id, tree_ids)}")
        if element_children:
            out.add(line, f"SubTree {node_id} must not have children")
        for attr in attrs:
            if attr.startswith("_"):
                out.add(line, f"SubTree {node_id}: unknown attribute {attr}")
        ports = {k: v for k, v in attrs.items() if not k.startswith("_")}
        return TreeElement(SUBTREE, name, ports, (), line, subtree_id=node_id,
                           autoremap=autoremap_text in ("true", "1"))

    spec = nodes.get(node_id)
    if spec is None:
        out.add(line, f"unknown node {node_id!r}{_suggest(node_id, nodes)}")
        for ch in element_children:  # still report the problems below an unknown node
            _convert_element(ch, nodes, tree_ids, out)
        return None
    if tag in _EXPLICIT_TAGS and _EXPLICIT_TAGS[tag] != spec.category:
        out.add(line, f"{node_id} is {_a(spec.category)}, not {_a(_EXPLICIT_TAGS[tag])}")

    ports: dict[str, str] = {}
    for attr, value in attrs.items():
        port = spec.port(attr)
        if port is None:
            known = ", ".join(spec.port_names) or "none"
            out.add(line, f"{node_id}: unknown port {attr!r}{_suggest(attr, spec.port_names)}; its ports are: {known}")
            continue
        ports[attr] = value
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
        if port.required and port.name not in ports and not satisfied_by_goal_id(port, ports):
            out.add(line, f"{node_id}: missing required port {port.name!r} ({port.type}: {port.description})")

    n = len(element_children)
    if spec.category == "control" and n == 0:
        out.add(line, f"{node_id} needs at least one child")
    elif spec.category == "decorator" and n != 1:
        out.add(line, f"{node_id} is a decorator and needs exactly one child, has {n}")
    elif spec.category in ("action", "condition") and n:
        out.add(line, f"{node_id} is {_a(spec.category)} and cannot have children")
    children = tuple(c for c in (_convert_element(ch, nodes, tree_ids, out) for ch in element_children) if c)
    return TreeElement(node_id, name, ports, children, line)


def _check_subtree_cycles(trees: Mapping[str, TreeElement], main: str, out: _Collector) -> None:
    calls = {tid: [(e.subtree_id, e.line) for e in root.walk() if e.id == SUBTREE] for tid, root in trees.items()}
    state: dict[str, int] = {}

    def visit(tid: str, chain: list[str]) -> None:
        state[tid] = 1
        for callee, line in calls.get(tid, ()):
            if callee not in trees:
                continue
            if state.get(callee) == 1:
                out.add(line, f"SubTree recursion: {' -> '.join(chain + [callee])}")
            elif callee not in state:
                visit(callee, chain + [callee])
        state[tid] = 2

    visit(main, [main])


def _check_document(data: bytes, source: str, nodes: Mapping[str, NodeSpec]) -> tuple[TreeDocument | None, list[BTProblem]]:
    root = _parse_root(data, source)
    _element_depth_ok(root, source)
    out = _Collector(source)
    if root.tag != "root":
        out.add(root.sourceline, f"the top element must be <root>, found <{root.tag}>")
        return None, out.problems
    fmt = root.get("BTCPP_format")
    if fmt is not None and fmt.strip() != "4":
        out.add(root.sourceline, f"BTCPP_format must be \"4\" (BehaviorTree.CPP v4), found {fmt!r}")
    tree_elements = []
    for child in root:
        if not isinstance(child.tag, str):
            continue
        if child.tag == "BehaviorTree":
            tree_elements.append(child)
        elif child.tag == "TreeNodesModel":
            continue
        elif child.tag == "include":
            out.add(child.sourceline, "<include> is resolved only for tree files (grove bt validate FILE), "
                                      "not in text: put every BehaviorTree in the same file")
        else:
            out.add(child.sourceline, f"unexpected <{child.tag}> under <root>; expected <BehaviorTree>")
    if not tree_elements:
        out.add(root.sourceline, "no <BehaviorTree> in the file")
        return None, out.problems
    tree_ids: set[str] = set()
    for el in tree_elements:
        tid = el.get("ID")
        if not tid:
            out.add(el.sourceline, "<BehaviorTree> needs an ID attribute")
        elif tid in tree_ids:
            out.add(el.sourceline, f"BehaviorTree ID {tid!r} is defined twice")
        else:
            tree_ids.add(tid)
    main = root.get("main_tree_to_execute")
    if main is None:
        if len(tree_ids) == 1:
            main = next(iter(tree_ids))
        else:
            out.add(root.sourceline, "several BehaviorTrees but no main_tree_to_execute attribute on <root>")
    elif main not in tree_ids:
        out.add(root.sourceline, f"main_tree_to_execute={main!r} names no BehaviorTree{_suggest(main, tree_ids)}")
    trees: dict[str, TreeElement] = {}
    lines: dict[str, int | None] = {}
    for el in tree_elements:
        tid = el.get("ID")
        kids = [c for c in el if isinstance(c.tag, str)]
        if len(kids) != 1:
            out.add(el.sourceline, f"BehaviorTree {tid!r} must have exactly one root node, has {len(kids)}")
        converted = [_convert_element(k, nodes, tree_ids, out) for k in kids]
        if tid and tid not in trees and converted and converted[0] is not None:
            trees[tid] = converted[0]
            lines[tid] = el.sourceline
    if main in trees:
        _check_subtree_cycles(trees, main, out)
    if out.problems or main not in trees:
        return None, out.problems
    return TreeDocument(source, main, trees, lines), []


def _as_bytes(text: str | bytes) -> bytes:
    if isinstance(text, bytes):
        return text
    if text.startswith("<?xml"):
        # lxml refuses str input with an encoding declaration
        text = text.split("?>", 1)[1] if "?>" in text else text
    return text.encode("utf-8")


def check_tree_text(text: str | bytes, source: str = "<string>",
                    nodes: Mapping[str, NodeSpec] = NODES) -> list[BTProblem]:
    """Every problem of a tree (empty when valid). Fatal XML problems give one entry."""
    try:
        _, problems = _check_document(_as_bytes(text), source, nodes)
    except BTError as exc:
        return [BTProblem(source, None, str(exc).removeprefix(f"{source}: "))]
    return problems


def parse_tree_text(text: str | bytes, source: str = "<string>",
                    nodes: Mapping[str, NodeSpec] = NODES) -> TreeDocument:
    """Parse and validate; BTError lists every problem with its line."""
    document, problems = _check_document(_as_bytes(text), source, nodes)
    if problems:
        listed = "\n".join(f"  line {p.line}: {p.message}" if p.line else f"  {p.message}" for p in problems)
        raise BTError(f"{source}: {len(problems)} problem(s) in behavior tree:\n{listed}")
    assert document is not None
    return document


def load_tree_file(path: str | Path, nodes: Mapping[str, NodeSpec] = NODES) -> TreeDocument:
    path = Path(path)
    try:
        size = path.stat().st_size
        if size > MAX_BYTES:
            raise BTError(f"{path}: file is {size} bytes; behavior trees are limited to {MAX_BYTES} bytes")
        data = path.read_bytes()
    except FileNotFoundError:
        raise BTError(f"{path}: no such behavior-tree file") from None
    except IsADirectoryError:
        raise BTError(f"{path}: is a directory, not a behavior-tree file") from None
    return parse_tree_text(_with_includes(path, data), str(path), nodes)


def _with_includes(path: Path, data: bytes) -> bytes:
    """`<include>`s of a tree file inlined, within its folder (bt/include.py)."""
    from grove_tui.bt.include import has_includes, resolve_includes

    return resolve_includes(path) if has_includes(data) else data


def check_tree_file(path: str | Path, nodes: Mapping[str, NodeSpec] = NODES) -> list[BTProblem]:
    path = Path(path)
    try:
        size = path.stat().st_size
        if size > MAX_BYTES:
            return [BTProblem(str(path), None, f"file is {size} bytes; the limit is {MAX_BYTES}")]
        data = path.read_bytes()
    except OSError as exc:
        return [BTProblem(str(path), None, f"cannot read: {exc.strerror or exc}")]
    try:
        data = _with_includes(path, data)
    except BTError as exc:
        return [BTProblem(str(path), None, str(exc))]
    return check_tree_text(data, str(path), nodes)
