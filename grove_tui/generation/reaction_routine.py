"""The routine a group that reacts to the robot does besides reacting, as generation builds it.

The reader gives a group of intent "robot" its routine when the sentence says both ("six patients queue
at the pharmacy and look at the robot": routine "queue" at the pharmacy; language/routine_reactions.py).
Generation builds that routine's plain tree (the queue at its service point, the wait there for its
time, the walk to the destination; reconcile.tree_for) and puts the reaction around it as HuNavSim's own
trees do: the robot cue first in a ReactiveFallback around the navigation (reconcile.with_reaction;
bt/format/after_task.py keeps it reacting once the routine is over). The report then claims both: the
routine's outcome (queued, waited, reached) and the reaction.

Two readings stay the reaction alone: following the robot (they go where it goes), and blocking it where
they stand with no time of their own (their stay is the block, held at the place: block_at_place.py).
"""

from __future__ import annotations

from grove_tui.language.model import ROUTINES, GroupReading


def routine_of(group: GroupReading) -> str | None:
    """What a group reacting to the robot does besides reacting, for generation and the report; None for
    a group that only reacts (or reacts not at all)."""
    if group.intent != "robot" or not group.robot_interaction or group.routine not in ROUTINES:
        return None
    if group.robot_interaction == "follow":
        return None
    if group.robot_interaction == "block" and group.routine == "wait" and not group.wait_seconds:
        return None
    return group.routine
