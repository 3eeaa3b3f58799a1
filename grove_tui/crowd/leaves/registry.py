"""Every leaf implementation, keyed by manifest name, and the factory that builds agents' trees."""

from __future__ import annotations

from grove_tui.bt.format.manifest import NODES
from grove_tui.crowd.leaves.grove import GROVE_LEAVES
from grove_tui.crowd.leaves.hunav import HUNAV_LEAVES
from grove_tui.bt.runtime.controls import CONTROL_CLASSES
from grove_tui.bt.runtime.decorators import DECORATOR_CLASSES
from grove_tui.bt.runtime.factory import TreeFactory
from grove_tui.bt.runtime.leaves import BTCPP_LEAVES

LEAF_CLASSES = {**HUNAV_LEAVES, **GROVE_LEAVES}


def tree_factory() -> TreeFactory:
    return TreeFactory(LEAF_CLASSES, NODES)


def unimplemented_nodes() -> list[str]:
    """Manifest nodes without an implementation (must stay empty; a test checks it)."""
    implemented = set(LEAF_CLASSES) | set(BTCPP_LEAVES) | set(CONTROL_CLASSES) | set(DECORATOR_CLASSES)
    return sorted(set(NODES) - implemented)
