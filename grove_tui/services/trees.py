"""Behavior trees as a front end shows them: a scenario's tree documents, their elements, their XML text
and the point lists in their ports, through the one owner of BT XML (bt.format), so the app needs no
import of it."""

from __future__ import annotations

from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.bt.format.ports import parse_point_list
from grove_tui.bt.format.xml import write_tree

__all__ = ["TreeDocument", "TreeElement", "behavior_trees", "parse_point_list", "tree_text"]


def behavior_trees(document: TreeDocument) -> list[TreeElement]:
    """The BehaviorTree elements of a tree document, main tree first."""
    return document.ordered_trees()


def tree_text(document: TreeDocument) -> str:
    """The document as the BT.CPP v4 XML its bundle file holds (the app's XML view; BTError if a value
    cannot be written in XML)."""
    return write_tree(document)
