"""Behavior trees as a front end reads them: the trees of a bundle's XML, their elements and the point
lists in their ports, through the one owner of BT XML (bt.format), so the app needs no import of it."""

from __future__ import annotations

from grove_tui.bt.format.document import TreeElement
from grove_tui.bt.format.ports import parse_point_list
from grove_tui.bt.format.xml import read_tree

__all__ = ["TreeElement", "behavior_trees", "parse_point_list"]


def behavior_trees(xml_text: str) -> list[TreeElement]:
    """The BehaviorTree elements of a BT.CPP v4 document, main tree first (hardened reader: BTError)."""
    return read_tree(xml_text, "tree").ordered_trees()
