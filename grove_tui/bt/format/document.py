"""The behavior-tree document every stage passes on: BT.CPP v4 trees as plain, editable Python objects.

Post-processing builds one, waypoint injection and the exports edit one, the runtime instantiates
one and the app shows one; only `bt/format/xml.py` turns text into a document and back, so the hardened
parser is on every path and every tree file is written the same way.

    TreeDocument                      <root BTCPP_format="4" main_tree_to_execute=...>
      .trees[id] -> TreeElement         <BehaviorTree ID=id>  (tag "BehaviorTree")
        .children[0] -> TreeElement       its root node: <Sequence>, <GoTo target=... x=... y=.../>, ...
      .models -> [TreeElement]          <TreeNodesModel> elements, kept as they are

A node is written compactly (<GoTo .../>) or explicitly (<Action ID="GoTo" .../>); `node_id` is the
node type either way, and a <SubTree ID="X"/> has node_id "SubTree" and subtree_id "X".
Walks are iterative: a document read from a hostile file may be deep, and Python's recursion limit
must never be what stops it.
"""

from __future__ import annotations

import copy
from collections.abc import Iterator
from dataclasses import dataclass, field

from grove_tui.bt.format.manifest import SUBTREE

EXPLICIT_TAGS = {"Action": "action", "Condition": "condition", "Control": "control", "Decorator": "decorator"}
BEHAVIOR_TREE = "BehaviorTree"
TREE_NODES_MODEL = "TreeNodesModel"
# Attributes any node may carry that are not ports (BT.CPP: name, ID and Groot2's metadata).
NON_PORT_ATTRIBUTES = frozenset({"name", "ID", "_description", "_uid", "_fullpath", "_autoremap"})


@dataclass(eq=True)
class TreeElement:
    """One XML element of a tree file: a node, a <BehaviorTree>, or part of a <TreeNodesModel>."""

    tag: str
    attributes: dict[str, str] = field(default_factory=dict)
    children: list[TreeElement] = field(default_factory=list)
    # where it was read from, for messages (None for elements built in code); not part of equality
    line: int | None = field(default=None, compare=False)
    text: str = ""  # character content (TreeNodesModel port descriptions); behavior nodes have none

    @property
    def id(self) -> str:
        """The node type: the manifest name, or "SubTree" for a SubTree call."""
        if self.tag == SUBTREE:
            return SUBTREE
        if self.tag in EXPLICIT_TAGS:
            return self.attributes.get("ID", "")
        return self.tag

    @property
    def name(self) -> str:
        """The instance name: the `name` attribute, else the node type (the called tree for a SubTree)."""
        return self.attributes.get("name") or (self.subtree_id or "" if self.tag == SUBTREE else self.id)

    @property
    def subtree_id(self) -> str | None:
        return self.attributes.get("ID") if self.tag == SUBTREE else None

    @property
    def autoremap(self) -> bool:
        return self.attributes.get("_autoremap", "false").strip().lower() in ("true", "1")

    @property
    def ports(self) -> dict[str, str]:
        """Port name -> text as written ("{key}" pointers included), without name, ID and metadata."""
        return {k: v for k, v in self.attributes.items() if k not in NON_PORT_ATTRIBUTES}

    def get(self, attribute: str, default: str | None = None) -> str | None:
        return self.attributes.get(attribute, default)

    def set(self, attribute: str, value: str) -> None:
        self.attributes[attribute] = str(value)

    def walk(self) -> Iterator[TreeElement]:
        """This element and everything below it, depth-first in document (tick) order."""
        stack = [self]
        while stack:
            element = stack.pop()
            yield element
            stack.extend(reversed(element.children))

    def walk_with_parents(self) -> Iterator[tuple[TreeElement | None, int, TreeElement]]:
        """(parent, index in the parent, element) depth-first; the parent of this element is None.

        Take a list of it before replacing elements, so the walk does not see its own edits."""
        stack: list[tuple[TreeElement | None, int, TreeElement]] = [(None, -1, self)]
        while stack:
            parent, index, element = stack.pop()
            yield parent, index, element
            stack.extend((element, i, child) for i, child in reversed(list(enumerate(element.children))))

    def walk_with_paths(self, path: tuple[int, ...] = ()) -> Iterator[tuple[tuple[int, ...], TreeElement]]:
        """(index path, element) for this element and its descendants, depth-first."""
        stack = [(path, self)]
        while stack:
            where, element = stack.pop()
            yield where, element
            stack.extend((where + (i,), child) for i, child in reversed(list(enumerate(element.children))))

    def describe(self) -> str:
        """'<GoTo> name='x' target='desk' line 4': how messages point at a node."""
        parts = [f"<{self.id or self.tag}>"]
        for attribute in ("name", "target"):
            if self.attributes.get(attribute):
                parts.append(f"{attribute}={self.attributes[attribute]!r}")
        if self.line is not None:
            parts.append(f"line {self.line}")
        return " ".join(parts)


def node(node_id: str, children: list[TreeElement] | tuple[TreeElement, ...] = (), /, **ports: str) -> TreeElement:
    """A behavior node written compactly, e.g. node("GoTo", target="desk", x="1", y="2")."""
    return TreeElement(node_id, {k: str(v) for k, v in ports.items()}, list(children))


def subtree_call(tree_id: str, *, autoremap: bool = False, **ports: str) -> TreeElement:
    attributes = {"ID": tree_id, **{k: str(v) for k, v in ports.items()}}
    if autoremap:
        attributes["_autoremap"] = "true"
    return TreeElement(SUBTREE, attributes)


@dataclass(eq=True)
class TreeDocument:
    """A BT.CPP v4 file: BehaviorTrees by ID (file order) and which one runs."""

    main_tree_id: str
    trees: dict[str, TreeElement]  # ID -> the <BehaviorTree> element; its one child is the tree's root node
    source: str = field(default="<tree>", compare=False)  # file name or label, for messages
    models: list[TreeElement] = field(default_factory=list)  # <TreeNodesModel> elements

    @classmethod
    def single(cls, tree_id: str, root: TreeElement, source: str = "<tree>") -> TreeDocument:
        """A document with one BehaviorTree, as post-processing writes one per agent."""
        return cls(tree_id, {tree_id: TreeElement(BEHAVIOR_TREE, {"ID": tree_id}, [root])}, source)

    def copy(self) -> TreeDocument:
        """A deep copy, for a stage that edits a document another stage still holds."""
        return copy.deepcopy(self)

    def root_of(self, tree_id: str) -> TreeElement:
        """The root node of BehaviorTree `tree_id` (KeyError if there is no such tree)."""
        return self.trees[tree_id].children[0]

    @property
    def main(self) -> TreeElement:
        return self.root_of(self.main_tree_id)

    def add_tree(self, tree_id: str, root: TreeElement) -> None:
        self.trees[tree_id] = TreeElement(BEHAVIOR_TREE, {"ID": tree_id}, [root])

    def tree_line(self, tree_id: str) -> int | None:
        return self.trees[tree_id].line

    def ordered_trees(self) -> list[TreeElement]:
        """The <BehaviorTree> elements, the main tree first, then file order."""
        return sorted(self.trees.values(), key=lambda t: t.attributes.get("ID") != self.main_tree_id)

    def nodes_with_parents(self) -> list[tuple[TreeElement, int, TreeElement]]:
        """(parent, index, node) for every behavior node, depth-first; a list, so callers may replace nodes."""
        return [(parent, index, element)
                for tree in self.trees.values()
                for parent, index, element in tree.walk_with_parents() if parent is not None]

    def nodes(self) -> Iterator[TreeElement]:
        """Every behavior node of every BehaviorTree, depth-first, file order."""
        for tree in self.trees.values():
            for child in tree.children:
                yield from child.walk()


# A scenario's trees as generation hands them on: bundle-relative path ("trees/agent_1.xml") -> document.
# Planning, refinement, analysis, the exports and the app take these; the text is written only where a
# file is (the bundle writer, an export, the app's XML view) and read only where one is read.
TreeFiles = dict[str, TreeDocument]
