"""The draft: the compact, bounded text the model writes instead of XML (ARCHITECTURE.md section 5).

One line per group, `COUNT LABEL from SPAWN: TREE`, and a tree node as `Name(required values,
optional port=value, children)`:

    10 patients from pharmacy: Sequence(GoTo(pharmacy_counter), Queue(pharmacy_counter, spacing=0.6))
    3 visitors from lobby: Sequence(GoTo(cafe), Wait(duration=30))

When the reading has groups, the model writes the lean draft instead: one line per reading group,
only its tree (`tree_grammar`, `parse_trees`), and each group's label, count and spawn come from the
reading (`GroupHead`), so the Draft that comes back has the same types either way:

    Sequence(GoTo(pharmacy_counter), Queue(pharmacy_counter))

The line starts with the count because a chat model's first words are otherwise chat ("Here is a
sample of a ..." filled the label when it came first, with SmolLM2): a digit first puts it straight
into the scenario, and "3 visitors from lobby" is how English says it.

Every token of the answer is a decode step, including the ones the grammar forces (issue 20). The
JSON draft this replaces spent about two thirds of its tokens on keys, quotes and braces the grammar
already knew ("node", "children", "label", ...). Here nothing is written that the grammar could
infer: required ports are positional (manifest order), and only optional ports the model chooses to
set carry their name. A node without written ports is its bare name.

This module is the one owner of the syntax: `draft_grammar` builds the GBNF for one request (only
the offered node types, only the selected RoI names, every number, string, list and the tree depth
bounded, so the model always finishes), `parse_draft` is the strict check of the text that comes
back, whether it was grammar-constrained or not, and `draft_to_text` writes a Draft in the same
form (parse_draft(draft_to_text(d)) == d).

What the model writes per node: the node type and the non-auto input ports of that node in the
manifest, except ports typed agent/agents/point_list (ids and point lists are post-processing's
job: the model never writes ids). Ports without a manifest default are required; the others are
optional and post-processing fills the manifest default. Numbers are chosen from a short list of
sensible values inside the port's bounds (the grammar cannot bound free digits); parse_draft
accepts any number within the bounds, so a hand-written draft is not held to that list. A label is
one word of letters and `_'-` (`elderly_patients`): SmolLM2 given room for several words wrote on
into the sentence ("patients queue at the") until the length bound cut it off, tokens spent on a
label the reading usually replaces anyway.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, TypeAlias

from grove_tui.errors import DraftError
from grove_tui.limits import MAX_GROUP_COUNT, MAX_GROUPS
from grove_tui.jsontypes import JSONObject, Parsed
from grove_tui.llm.grammar import GbnfRules, bounded_repeat, gbnf_literal

if TYPE_CHECKING:
    from grove_tui.bt.format.manifest import NodeSpec, PortSpec

LABEL_MAX_LENGTH = 24
STRING_PORT_MAX_LENGTH = 48
MAX_CHILDREN = 4
# A quoted text value (SaySomething's message): no quote, backslash or newline, so it cannot end early
# or break the line structure; what the grammar lets through is what the parser accepts.
SAFE_STRING_CHARS = "A-Za-z0-9 _.,'()/:-"
_SAFE_STRING = re.compile(f"^[{SAFE_STRING_CHARS}]*$")
# A label: one word (so " from " always ends it) without digits, so it reads as who the people are.
LABEL_FIRST_CHARS = "A-Za-z"
LABEL_CHARS = "A-Za-z_'-"
_LABEL = re.compile(f"^[{LABEL_FIRST_CHARS}][{LABEL_CHARS}]*$")
# A bare value (place names, true/false) is one word; RoI names are snake_case (world/model.py).
_BARE = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
# Port types the model never writes: agent ids and point lists come from post-processing.
POST_PROCESSED_TYPES = frozenset({"agent", "agents", "point_list"})
WRITTEN_TYPES = frozenset({"int", "float", "bool", "string", "target"})
BRANCH_CATEGORIES = frozenset({"control", "decorator"})

_SENSIBLE_FLOATS = (0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.6, 0.75, 1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0,
                    8.0, 10.0, 15.0, 20.0, 30.0, 45.0, 60.0, 90.0, 120.0, 180.0, 300.0, 600.0, 1800.0, 3600.0)
_SENSIBLE_INTS = (-1, 0, 1, 2, 3, 4, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 3000, 5000, 10000, 20000,
                  30000, 60000, 120000, 300000, 600000, 1800000, 3600000)
_ENUMERATE_ALL_INTS_UP_TO = 24


# A port value as a draft writes it: a place or text, a number, true or false.
DraftValue: TypeAlias = str | int | float | bool


@dataclass(frozen=True)
class DraftNode:
    node: str
    ports: dict[str, DraftValue] = field(default_factory=dict)  # only the ports the model wrote
    children: tuple[DraftNode, ...] = ()

    def walk(self) -> Iterable[DraftNode]:
        yield self
        for child in self.children:
            yield from child.walk()


def place_at(node: DraftNode, port: str) -> str:
    """The value of a target port: always a place name (the parser takes only the selected places there)."""
    return str(node.ports[port])


def place_of(node: DraftNode, port: str) -> str | None:
    """The value of a target port when the node has it, else None."""
    value = node.ports.get(port)
    return None if value is None else str(value)


@dataclass(frozen=True)
class DraftGroup:
    label: str
    count: int
    spawn: str
    tree: DraftNode


@dataclass(frozen=True)
class Draft:
    groups: tuple[DraftGroup, ...]

    def node_types(self) -> set[str]:
        return {node.node for group in self.groups for node in group.tree.walk()}

    def places(self, nodes: Mapping[str, NodeSpec] | None = None) -> set[str]:
        """Every RoI name the draft uses: spawns and the values of target-typed ports."""
        table = _manifest() if nodes is None else nodes
        names = {group.spawn for group in self.groups}
        for group in self.groups:
            for node in group.tree.walk():
                spec = table.get(node.node)
                for port in spec.ports if spec is not None else ():
                    if port.type == "target" and port.name in node.ports:
                        names.add(place_at(node, port.name))
        return names


def _manifest() -> Mapping[str, NodeSpec]:
    from grove_tui.bt.format.manifest import NODES

    return NODES


def _specs(node_names: Iterable[str], nodes: Mapping[str, NodeSpec] | None) -> dict[str, NodeSpec]:
    table = _manifest() if nodes is None else nodes
    names = list(dict.fromkeys(node_names))
    unknown = [name for name in names if name not in table]
    if unknown:
        raise DraftError(f"unknown node type(s) {', '.join(unknown)}; the manifest has {', '.join(sorted(table))}")
    if not names:
        raise DraftError("no node types given for the draft")
    return {name: table[name] for name in names}


def written_ports(spec: NodeSpec) -> tuple[PortSpec, ...]:
    """The ports of a node the model writes in a draft, in manifest order."""
    return tuple(port for port in spec.ports
                 if port.direction == "in" and not port.auto and port.type in WRITTEN_TYPES)


def _sensible_ints(port: PortSpec) -> list[int]:
    low = int(port.min) if port.min is not None else 0
    high = int(port.max) if port.max is not None else 100
    if high - low <= _ENUMERATE_ALL_INTS_UP_TO:
        return list(range(low, high + 1))
    values = {low, high} | {value for value in _SENSIBLE_INTS if low <= value <= high}
    if isinstance(port.default, int) and not isinstance(port.default, bool) and low <= port.default <= high:
        values.add(port.default)
    return sorted(values)


def _sensible_floats(port: PortSpec) -> list[float]:
    low = float(port.min) if port.min is not None else 0.0
    high = float(port.max) if port.max is not None else 3600.0
    values = {round(low, 4), round(high, 4)} | {value for value in _SENSIBLE_FLOATS if low <= value <= high}
    if isinstance(port.default, (int, float)) and not isinstance(port.default, bool) and low <= port.default <= high:
        values.add(round(float(port.default), 4))
    return sorted(values)


def _check_request(node_names: Iterable[str], roi_names: Iterable[str], max_groups: int, max_count: int,
                   max_depth: int, max_children: int,
                   nodes: Mapping[str, NodeSpec] | None) -> tuple[dict[str, NodeSpec], list[str]]:
    """The node specs and place names of one request, refused when no bounded draft could be written."""
    specs = _specs(node_names, nodes)
    rois = list(dict.fromkeys(roi_names))
    if not rois:
        raise DraftError("no RoI names given: a draft needs at least one place to spawn")
    bare = [name for name in rois if not _BARE.match(name)]
    if bare:
        raise DraftError(f"place name(s) {', '.join(map(repr, bare))} are not single words, which a draft writes bare")
    if not (1 <= max_groups <= MAX_GROUPS and 1 <= max_count <= MAX_GROUP_COUNT and 1 <= max_depth <= 6
            and 1 <= max_children <= 8):
        raise DraftError(f"draft limits out of range: max_groups={max_groups} (1..{MAX_GROUPS}), max_count={max_count} "
                         f"(1..{MAX_GROUP_COUNT}), "
                         f"max_depth={max_depth} (1..6), max_children={max_children} (1..8)")
    if not any(spec.category not in BRANCH_CATEGORIES for spec in specs.values()):
        raise DraftError(f"the node types {', '.join(specs)} include no action or condition, so no tree can end")
    for spec in specs.values():
        for port in written_ports(spec):
            if port.type not in WRITTEN_TYPES:
                raise DraftError(f"port {port.name!r} has type {port.type!r}, which a draft never writes")
            if port.choices and not all(_BARE.match(str(choice)) for choice in port.choices):
                raise DraftError(f"{spec.name}.{port.name}: choices {port.choices} are not single words")
    return specs, rois


def _required(spec: NodeSpec) -> tuple[PortSpec, ...]:
    return tuple(port for port in written_ports(spec) if port.default is None)


def _optional(spec: NodeSpec) -> tuple[PortSpec, ...]:
    return tuple(port for port in written_ports(spec) if port.default is not None)


def number_text(value: float) -> str:
    """A number as the draft writes it: whole numbers without a fraction (2, not 2.0), the shortest form tokenizers see."""
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return repr(value) if isinstance(value, float) else str(int(value))


# ---- the grammar -------------------------------------------------------------------------------

def _bounded(item: str, low: int, high: int, separator: str = "") -> str:
    """`item` low..high times (low >= 1): llm.grammar.bounded_repeat, so every length parses one way and ends."""
    return bounded_repeat(item, low, high, separator)


def _alternatives(literals: Iterable[str]) -> str:
    return " | ".join(dict.fromkeys(gbnf_literal(text) for text in literals))


class _GrammarBuilder:
    def __init__(self, specs: dict[str, NodeSpec], rois: list[str], max_count: int, max_depth: int, max_children: int):
        self.specs, self.rois = specs, rois
        self.max_count, self.max_depth, self.max_children = max_count, max_depth, max_children
        self.rules = GbnfRules()
        self.sep = self.rules.add("sep", '"," " "?')
        self.place = self.rules.add("place", _alternatives(rois))

    def value(self, spec: NodeSpec, port: PortSpec) -> str:
        if port.choices:
            return self.rules.add(f"{spec.name}-{port.name}", _alternatives(map(str, port.choices)))
        if port.type == "target":
            return self.place
        if port.type == "bool":
            return self.rules.add("bool", '"true" | "false"')
        if port.type == "int":
            return self.rules.add(f"{spec.name}-{port.name}", _alternatives(str(v) for v in _sensible_ints(port)))
        if port.type == "float":
            return self.rules.add(f"{spec.name}-{port.name}", _alternatives(number_text(v) for v in _sensible_floats(port)))
        if port.type == "string":
            char = self.rules.add("text-char", f"[{SAFE_STRING_CHARS}]")
            return self.rules.add("text", f'"\\"" ({_bounded(char, 1, STRING_PORT_MAX_LENGTH)})? "\\""')
        raise DraftError(f"port {port.name!r} has type {port.type!r}, which a draft never writes")

    def keyed(self, spec: NodeSpec, port: PortSpec) -> str:
        return f"{gbnf_literal(port.name + '=')} {self.value(spec, port)}"

    def optional_ports(self, spec: NodeSpec) -> str | None:
        """One or more optional ports in manifest order, comma-separated: one alternative per first port written."""
        ports = _optional(spec)
        if not ports:
            return None
        options = []
        for index, port in enumerate(ports):
            rest = " ".join(f"({self.sep} {self.keyed(spec, later)})?" for later in ports[index + 1:])
            options.append(f"{self.keyed(spec, port)} {rest}".strip())
        return self.rules.add(f"{spec.name}-options", " | ".join(f"({option})" for option in options))

    def node(self, spec: NodeSpec, level: int) -> str | None:
        """The rule of `spec` at tree level `level`; None for a branch that has no room for children there."""
        branch = spec.category in BRANCH_CATEGORIES
        if branch and level >= self.max_depth:
            return None
        required = [self.value(spec, port) for port in _required(spec)]
        options = self.optional_ports(spec)
        name = gbnf_literal(spec.name)
        opened = gbnf_literal(spec.name + "(")
        if branch:
            most = 1 if spec.category == "decorator" else self.max_children
            child = self.level(level + 1)
            children = _bounded(child, 1, most, f"{self.sep} ")
            if required:
                inside = f" {self.sep} ".join(required) + (f" ({self.sep} {options})?" if options else "") + f" {self.sep} {children}"
            else:
                inside = (f"({options} {self.sep})? " if options else "") + children
            return self.rules.add(f"{spec.name}-{level}", f'{opened} {inside} ")"')
        if required:
            inside = f" {self.sep} ".join(required) + (f" ({self.sep} {options})?" if options else "")
            return self.rules.add(spec.name, f'{opened} {inside} ")"')
        if options:
            return self.rules.add(spec.name, f'{name} ("(" {options} ")")?')
        return self.rules.add(spec.name, name)

    def level(self, level: int) -> str:
        options = [rule for spec in self.specs.values() if (rule := self.node(spec, level)) is not None]
        return self.rules.add(f"level-{level}", " | ".join(options))

    def trees(self, groups: int) -> str:
        """Exactly `groups` lines, each one tree: the lean draft, whose headers the reading fills in."""
        return self.rules.text(_bounded(self.level(1), groups, groups, '"\\n" '))

    def grammar(self, max_groups: int) -> str:
        label_char = self.rules.add("label-char", f"[{LABEL_CHARS}]")
        label = self.rules.add("label", f"[{LABEL_FIRST_CHARS}] ({_bounded(label_char, 1, LABEL_MAX_LENGTH - 1)})?")
        count = self.rules.add("count", _alternatives(str(n) for n in range(self.max_count, 0, -1)))
        group = self.rules.add("group", f'{count} " " {label} " from " {self.place} ": " {self.level(1)}')
        return self.rules.text(_bounded(group, 1, max_groups, '"\\n" '))


def draft_grammar(node_names: Iterable[str], roi_names: Iterable[str], max_groups: int = 6, max_count: int = 60,
                  max_depth: int = 3, max_children: int = MAX_CHILDREN,
                  nodes: Mapping[str, NodeSpec] | None = None) -> str:
    """The GBNF (root rule `root`) of every draft this request allows; recursion is unrolled into one rule per tree level."""
    specs, rois = _check_request(node_names, roi_names, max_groups, max_count, max_depth, max_children, nodes)
    return _GrammarBuilder(specs, rois, max_count, max_depth, max_children).grammar(max_groups)


def tree_grammar(node_names: Iterable[str], roi_names: Iterable[str], groups: int, max_depth: int = 3,
                 max_children: int = MAX_CHILDREN, nodes: Mapping[str, NodeSpec] | None = None) -> str:
    """The GBNF of a lean draft: exactly `groups` lines, each the tree of one group (GroupHead gives the rest)."""
    specs, rois = _check_request(node_names, roi_names, max(1, groups), 1, max_depth, max_children, nodes)
    return _GrammarBuilder(specs, rois, 1, max_depth, max_children).trees(groups)


# ---- the parser --------------------------------------------------------------------------------

# COUNT LABEL from SPAWN, three words around "from".
_HEADER = re.compile(r"^(\S+)\s+(\S+)\s+from\s+(\S+)$")
_TOKEN = re.compile(r'\s*(?:(?P<name>[A-Za-z_][A-Za-z0-9_]*)|(?P<number>-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?)'
                    r'|(?P<text>"[^"\n]*")|(?P<punct>[(),=])|(?P<bad>\S))')


@dataclass(frozen=True)
class _Token:
    kind: str  # name, number, text, punct, end
    value: str
    column: int  # 1-based, in the whole line


def _tokens(text: str, offset: int) -> list[_Token]:
    found = []
    position = 0
    while position < len(text):
        match = _TOKEN.match(text, position)
        if match is None:  # only whitespace was left
            break
        kind = match.lastgroup or "bad"
        found.append(_Token(kind, match.group(kind), offset + match.start(kind) + 1))
        position = match.end()
    found.append(_Token("end", "", offset + len(text) + 1))
    return found


def _shown(token: _Token) -> str:
    return "the end of the line" if token.kind == "end" else repr(token.value)


class _Parser:
    def __init__(self, specs: dict[str, NodeSpec], rois: list[str], max_groups: int, max_count: int, max_depth: int,
                 max_children: int):
        self.specs, self.rois = specs, rois
        self.roi_set = set(rois)
        self.max_groups, self.max_count, self.max_depth = max_groups, max_count, max_depth
        self.max_children = max_children
        self.line = 0
        self.tokens: list[_Token] = []
        self.at = 0

    def fail(self, path: str, problem: str, token: _Token | None = None) -> DraftError:
        where = f"line {self.line}" + (f", column {token.column}" if token is not None else "")
        return DraftError(f"draft {path} ({where}): {problem}")

    def draft(self, text: str) -> Draft:
        lines = [(number, line) for number, line in enumerate(text.splitlines(), 1) if line.strip()]
        if not lines:
            raise DraftError("draft is empty: expected one line per group, `COUNT LABEL from SPAWN: TREE`")
        if len(lines) > self.max_groups:
            self.line = lines[self.max_groups][0]
            raise self.fail("groups", f"{len(lines)} groups, at most {self.max_groups} allowed")
        groups = []
        for index, (number, line) in enumerate(lines):
            self.line = number
            groups.append(self.group(line, f"groups[{index}]"))
        return Draft(tuple(groups))

    def trees(self, text: str, heads: Sequence[GroupHead]) -> Draft:
        lines = [(number, line) for number, line in enumerate(text.splitlines(), 1) if line.strip()]
        if len(lines) != len(heads):
            self.line = lines[-1][0] if lines else 0
            raise self.fail("groups", f"{len(lines)} line(s), expected one tree per group: {len(heads)}")
        groups = []
        for index, ((number, line), head) in enumerate(zip(lines, heads)):
            self.line = number
            path = f"groups[{index}].tree"
            offset = 0
            header, colon, _ = line.partition(":")
            if colon and _HEADER.match(header.strip()):
                # A full draft's line (an unconstrained or scripted answer): the reading's head wins over it.
                offset = len(header) + 1
            self.tokens, self.at = _tokens(line[offset:], offset), 0
            node = self.node(path, 1)
            if self.peek().kind != "end":
                raise self.fail(path, f"unexpected {_shown(self.peek())} after the tree", self.peek())
            groups.append(DraftGroup(head.label, head.count, head.spawn, node))
        return Draft(tuple(groups))

    def group(self, line: str, path: str) -> DraftGroup:
        header, colon, tree = line.partition(":")
        if not colon:
            raise self.fail(path, f"expected `COUNT LABEL from SPAWN: TREE`, found no ':' in {line.strip()[:60]!r}")
        parts = _HEADER.match(header.strip())
        if parts is None:
            raise self.fail(path, f"expected `COUNT LABEL from SPAWN` before ':', got {header.strip()!r}")
        count_text, label, spawn = parts.group(1), parts.group(2).strip(), parts.group(3)
        if len(label) > LABEL_MAX_LENGTH:
            raise self.fail(f"{path}.label", f"longer than {LABEL_MAX_LENGTH} characters")
        if not _LABEL.match(label):
            raise self.fail(f"{path}.label", f"{label!r} must be one word: a letter, then letters and _'-")
        if not count_text.isdigit() or not 1 <= int(count_text) <= self.max_count:
            raise self.fail(f"{path}.count", f"{count_text!r} is not a whole number in 1..{self.max_count}")
        if spawn not in self.roi_set:
            raise self.fail(f"{path}.spawn", f"{spawn!r} is not one of the selected places: {', '.join(self.rois)}")
        self.tokens, self.at = _tokens(tree, len(header) + 1), 0
        node = self.node(f"{path}.tree", 1)
        if self.peek().kind != "end":
            raise self.fail(f"{path}.tree", f"unexpected {_shown(self.peek())} after the tree", self.peek())
        return DraftGroup(label, int(count_text), spawn, node)

    def peek(self, ahead: int = 0) -> _Token:
        return self.tokens[min(self.at + ahead, len(self.tokens) - 1)]

    def take(self) -> _Token:
        token = self.peek()
        self.at = min(self.at + 1, len(self.tokens) - 1)
        return token

    def expect(self, value: str, path: str, what: str) -> None:
        token = self.take()
        if token.value != value or token.kind != "punct":
            raise self.fail(path, f"expected {what}, found {_shown(token)}", token)

    def node(self, path: str, level: int) -> DraftNode:
        token = self.take()
        if token.kind != "name" or token.value not in self.specs:
            raise self.fail(path, f"{_shown(token)} is not one of the allowed node types: {', '.join(self.specs)}", token)
        kind = token.value
        spec = self.specs[kind]
        path = f"{path} ({kind})"
        branch = spec.category in BRANCH_CATEGORIES
        if branch and level >= self.max_depth:
            raise self.fail(path, f"{kind} needs children, but the tree may only be {self.max_depth} levels deep", token)
        required, ports = _required(spec), {port.name: port for port in written_ports(spec)}
        values: dict[str, DraftValue] = {}
        children: list[DraftNode] = []
        if self.peek().value == "(" and self.peek().kind == "punct":
            self.take()
            positional, named = 0, False  # required values come first, by position, then port=value, then children
            while True:
                item = self.peek()
                keyed = item.kind == "name" and self.peek(1).value == "=" and self.peek(1).kind == "punct"
                if keyed:
                    if children:
                        raise self.fail(path, f"port {item.value} comes after the children; ports come first", item)
                    if item.value not in ports:
                        raise self.fail(path, f"{kind} has no port {item.value!r} to write; it takes "
                                        f"{', '.join(ports) or 'none'}", item)
                    if item.value in values:
                        raise self.fail(path, f"port {item.value} is written twice", item)
                    self.take(), self.take()
                    values[item.value] = self.value(ports[item.value], f"{path}.{item.value}")
                    named = True
                elif not named and not children and positional < len(required):
                    port = required[positional]
                    values[port.name] = self.value(port, f"{path}.{port.name}")
                    positional += 1
                elif branch:
                    most = 1 if spec.category == "decorator" else self.max_children
                    if len(children) == most:
                        raise self.fail(path, f"{kind} takes {'exactly 1 child' if most == 1 else f'1..{most} children'}", item)
                    children.append(self.node(f"{path}.children[{len(children)}]", level + 1))
                else:
                    wanted = f"{len(required)} value(s) ({', '.join(p.name for p in required)})" if required else "no values"
                    raise self.fail(path, f"unexpected {_shown(item)}: {kind} takes {wanted}, then optional port=value",
                                    item)
                separator = self.take()
                if separator.kind == "punct" and separator.value == ")":
                    break
                if separator.kind != "punct" or separator.value != ",":
                    raise self.fail(path, f"expected ',' or ')', found {_shown(separator)}", separator)
        missing = [port.name for port in required if port.name not in values]
        if missing:
            raise self.fail(path, f"missing required port(s) {', '.join(missing)}", token)
        if branch and not children:
            most = 1 if spec.category == "decorator" else self.max_children
            raise self.fail(path, f"{kind} takes {'exactly 1 child' if most == 1 else f'1..{most} children'}", token)
        ordered = {port.name: values[port.name] for port in written_ports(spec) if port.name in values}
        return DraftNode(kind, ordered, tuple(children))

    def value(self, port: PortSpec, path: str) -> DraftValue:
        token = self.take()
        if port.choices:
            if token.value not in port.choices:
                raise self.fail(path, f"{_shown(token)} is not one of {', '.join(map(str, port.choices))}", token)
            return token.value
        if port.type == "target":
            if token.kind != "name" or token.value not in self.roi_set:
                raise self.fail(path, f"{_shown(token)} is not one of the selected places: {', '.join(self.rois)}", token)
            return token.value
        if port.type == "bool":
            if token.kind != "name" or token.value not in ("true", "false"):
                raise self.fail(path, f"expected true or false, found {_shown(token)}", token)
            return token.value == "true"
        if port.type == "string":
            if token.kind != "text":
                raise self.fail(path, f'expected a quoted text ("..."), found {_shown(token)}', token)
            text = token.value[1:-1]
            if len(text) > STRING_PORT_MAX_LENGTH:
                raise self.fail(path, f"longer than {STRING_PORT_MAX_LENGTH} characters", token)
            if not _SAFE_STRING.match(text):
                raise self.fail(path, f"{token.value} uses characters outside [{SAFE_STRING_CHARS}]", token)
            return text
        if token.kind != "number":
            raise self.fail(path, f"expected a number, found {_shown(token)}", token)
        if port.type == "int" and not re.fullmatch(r"-?\d+", token.value):
            raise self.fail(path, f"expected a whole number, found {token.value}", token)
        value = float(token.value)
        if not math.isfinite(value):
            raise self.fail(path, f"expected a finite number, found {token.value}", token)
        if (port.min is not None and value < port.min) or (port.max is not None and value > port.max):
            low = number_text(port.min) if port.min is not None else ""
            high = number_text(port.max) if port.max is not None else ""
            raise self.fail(path, f"{token.value} is outside {low}..{high}", token)
        return int(token.value) if port.type == "int" else value


def parse_draft(text: str, node_names: Iterable[str], roi_names: Iterable[str], max_groups: int = 6,
                max_count: int = 60, max_depth: int = 3, max_children: int = MAX_CHILDREN,
                nodes: Mapping[str, NodeSpec] | None = None) -> Draft:
    """Strictly parse and validate the model's draft; DraftError names the line, column and the draft path."""
    specs, rois = _check_request(node_names, roi_names, max_groups, max_count, max_depth, max_children, nodes)
    return _Parser(specs, rois, max_groups, max_count, max_depth, max_children).draft(text)


@dataclass(frozen=True)
class GroupHead:
    """What the reading fixes for a group of a lean draft: the model writes only its tree."""

    label: str
    count: int
    spawn: str


def parse_trees(text: str, heads: Sequence[GroupHead], node_names: Iterable[str], roi_names: Iterable[str],
                max_depth: int = 3, max_children: int = MAX_CHILDREN,
                nodes: Mapping[str, NodeSpec] | None = None) -> Draft:
    """Strictly parse a lean draft (one tree per line, in the order of `heads`) into a Draft.

    A line that still carries the full draft's `COUNT LABEL from SPAWN:` (an answer written without the
    lean grammar) is read for its tree; its head comes from `heads` all the same."""
    specs, rois = _check_request(node_names, roi_names, max(1, len(heads)), 1, max_depth, max_children, nodes)
    return _Parser(specs, rois, len(heads), MAX_GROUP_COUNT, max_depth, max_children).trees(text, heads)


# ---- writing drafts ----------------------------------------------------------------------------

def _value_text(port: PortSpec | None, value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return number_text(value)
    if port is not None and port.type == "string":
        return f'"{value}"'
    return str(value)


def tree_text(node: Parsed, nodes: Mapping[str, NodeSpec] | None = None) -> str:
    """A draft node given as a mapping ({"node": ..., ports..., "children": [...]}: node_db templates) in draft syntax.

    Written as the model must write it, without checking the values: templates hold placeholders
    such as `<destination>` for the model to fill in."""
    table = _manifest() if nodes is None else nodes
    name = str(node.get("node"))
    spec = table.get(name)
    ports = {port.name: port for port in written_ports(spec)} if spec is not None else {}
    required = [port.name for port in _required(spec)] if spec is not None else []
    given = {key: value for key, value in node.items() if key not in ("node", "children")}
    items = [_value_text(ports.get(key), given[key]) for key in required if key in given]
    positional = all(key in given for key in required)
    if not positional:  # a required port missing: name every port so nothing shifts into the wrong place
        items = []
    items += [f"{key}={_value_text(ports.get(key), value)}" for key, value in given.items()
              if not (positional and key in required)]
    items += [tree_text(child, table) for child in node.get("children") or ()]
    return f"{name}({', '.join(items)})" if items else name


def node_to_text(node: DraftNode, nodes: Mapping[str, NodeSpec] | None = None) -> str:
    """One draft node (and its subtree) as the model writes it."""
    return tree_text(node_to_dict(node), nodes)


def draft_to_text(draft: Draft, nodes: Mapping[str, NodeSpec] | None = None) -> str:
    """The draft as the model writes it, one line per group (parse_draft(draft_to_text(d)) == d)."""
    unwritable = [group.label for group in draft.groups if not _LABEL.match(group.label)]
    if unwritable:
        raise DraftError(f"label(s) {', '.join(map(repr, unwritable))} cannot be written in a draft: "
                         "a label is one word of letters and _'-")
    return "\n".join(f"{group.count} {group.label} from {group.spawn}: {node_to_text(group.tree, nodes)}"
                     for group in draft.groups)


def node_to_dict(node: DraftNode) -> JSONObject:
    result: JSONObject = {"node": node.node, **node.ports}
    if node.children:
        result["children"] = [node_to_dict(child) for child in node.children]
    return result


