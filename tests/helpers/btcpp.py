"""Load an exported tree in BehaviorTree.CPP v4 itself (PyPI `behaviortreepy`) and tick it once."""

from __future__ import annotations

import behaviortreepy as bt
from lxml import etree

from grove_tui.bt.format.manifest import NODES


def load_in_btcpp(xml: str) -> list[str]:
    """Load a tree in BehaviorTree.CPP v4 and tick it; return the leaf types it saw.

    behaviortreepy 0.1.4 registers Python leaves without a port list, and BT.CPP rejects ports a
    node type did not declare, so leaf attributes are dropped for this load (the ports themselves
    are checked against our manifest by check_tree_text). Built-in control nodes and decorators keep
    theirs and are checked by BT.CPP.
    """
    root = etree.fromstring(xml.encode())
    leaves = set()
    for el in root.iter():
        if isinstance(el.tag, str) and el.tag in NODES and NODES[el.tag].origin != "btcpp":
            leaves.add(el.tag)
            for attr in list(el.attrib):
                if attr != "name":
                    del el.attrib[attr]
    factory = bt.BehaviorTreeFactory()
    for name in sorted(leaves):
        if NODES[name].category == "condition":
            factory.register_simple_condition(name, lambda node: bt.NodeStatus.SUCCESS)
        else:
            factory.register_simple_action(name, lambda node: bt.NodeStatus.SUCCESS)
    tree = factory.create_tree_from_text(etree.tostring(root, encoding="unicode"))
    status = tree.tick_exactly_once()
    assert status.name in ("SUCCESS", "FAILURE", "RUNNING")
    return sorted(leaves)
