"""Every leaf implementation, keyed by manifest name, and the factory that builds agents' trees."""

from __future__ import annotations

from grove_tui.bt.manifest import NODES
from grove_tui.bt.leaves.grove import GROVE_LEAVES
from grove_tui.bt.leaves.hunav import HUNAV_LEAVES
from grove_tui.bt.runtime import BTCPP_LEAVES, CONTROL_CLASSES, DECORATOR_CLASSES, TreeFactory

LEAF_CLASSES = {**HUNAV_LEAVES, **GROVE_LEAVES}


def tree_factory() -> TreeFactory:
    return TreeFactory(LEAF_CLASSES, NODES)


def unimplemented_nodes() -> list[str]:
    """Manifest nodes without an implementation (must stay empty; a test checks it)."""
    implemented = set(LEAF_CLASSES) | set(BTCPP_LEAVES) | set(CONTROL_CLASSES) | set(DECORATOR_CLASSES)
    return sorted(set(NODES) - implemented)
