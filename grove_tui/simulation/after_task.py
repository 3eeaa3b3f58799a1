"""GROVE's simulation side of bt/format/after_task.py: a tree that reacts to the robot around its routine
keeps reacting once the routine is over, as the HuNavSim export does and as HuNavSim's own trees do."""

from __future__ import annotations

from grove_tui.bt.format.after_task import ROBOT_CUES, RUN_ONCE_NAME, keep_reacting_after_task, standing_reaction
from grove_tui.bt.format.document import TreeDocument
from grove_tui.bt.runtime.controls import SequenceWithMemory
from grove_tui.bt.runtime.factory import BehaviorTree

# How long each wait of the hold lasts before it starts again (it never ends: the number only matters
# to the status shown for the agent).
AFTER_TASK_HOLD_SECONDS = 60.0


def with_hold_after_task(document: TreeDocument, hold_seconds: float = AFTER_TASK_HOLD_SECONDS) -> TreeDocument:
    """The document with its routine run once and then held inside its reaction to the robot; the same
    document when it has no such reaction (a copy is edited: callers may hold the original)."""
    if standing_reaction(document) is None:
        return document
    held = document.copy()
    return held if keep_reacting_after_task(held, hold_seconds) else document


def holding_node(tree: BehaviorTree) -> SequenceWithMemory | None:
    """The run-once-then-hold sequence of a built tree that reacts to the robot: past its first child, the
    routine is over. None for a tree without one, or one that never reacts to the robot (an imported
    export's plain hold: nothing is left to happen to that agent)."""
    if not any(n.node_id in ROBOT_CUES for n in tree.nodes):
        return None
    return next((n for n in tree.nodes if isinstance(n, SequenceWithMemory) and n.name == RUN_ONCE_NAME), None)
