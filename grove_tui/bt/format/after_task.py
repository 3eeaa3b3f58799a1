"""What a person does once their task is over: stand where it ended, and keep reacting to the robot.

HuNavSim ticks every agent's root on every step for the whole run (bt_node.cpp `tree_tick`), and its own
trees (behavior_trees/BTSurprisedNav.xml and the other *Nav trees) put the reaction to the robot first in
a fallback around the agent's navigation: whoever was made to react to the robot does so for as long as
they are in the scene. A GROVE tree runs once; the export makes it "run once, then hold" so the routine
is not started again. Both GROVE's simulation and the HuNavSim export therefore put the hold *inside* a
reaction pattern at the root of the tree:

    ReactiveFallback[ <robot cue branch>..., SequenceWithMemory "run_once_then_hold"[ForceSuccess[routine],
                                                                                     hold_final_state] ]

so that the served patient at the head of a queue, the students who reached the reading room, still get
out of the robot's way when it comes. A tree without such a reaction ends as it always did (GROVE) or
holds without reacting (the export).
"""

from __future__ import annotations

from grove_tui.bt.format.document import TreeDocument, TreeElement, node

HOLD_NAME = "hold_final_state"
RUN_ONCE_NAME = "run_once_then_hold"
# Conditions that cue a reaction to the robot, and the nodes through which a person responds to it.
ROBOT_CUES = frozenset({"IsRobotVisible", "IsRobotClose", "IsRobotFacingAgent"})
ROBOT_RESPONSES = frozenset({"SurprisedNav", "CuriousNav", "ScaredNav", "ThreateningNav",
                             "ApproachRobot", "BlockRobot", "AvoidRobot", "LookAtRobot"})
_SEQUENCES = frozenset({"Sequence", "ReactiveSequence", "SequenceWithMemory"})


def hold_forever(wait_seconds: float) -> TreeElement:
    """A subtree that stands still and never completes.

    HuNavSim ticks every agent's root on every step and BT.CPP 4 resets a root that returned SUCCESS
    or FAILURE, so a tree that simply ends is started again (bt_node.cpp `tree_tick`, every
    ComputeAgents call). KeepRunningUntilFailure turns each completed wait into RUNNING and restarts it.
    """
    hold = node("KeepRunningUntilFailure", [node("StopAndWaitTimerAction", agent_id="{id}",
                                                 wait_duration=f"{wait_seconds:g}")])
    hold.set("name", HOLD_NAME)
    return hold


def run_once_then_hold(routine: TreeElement, hold_seconds: float) -> TreeElement:
    """The routine once (a failing step ends it, as in GROVE), then standing where it ended."""
    wrapped = node("SequenceWithMemory", [node("ForceSuccess", [routine]), hold_forever(hold_seconds)])
    wrapped.set("name", RUN_ONCE_NAME)
    return wrapped


def is_reaction_branch(element: TreeElement) -> bool:
    """A sequence that starts on a robot cue and responds to the robot: [IsRobotClose, ForceFailure(ScaredNav)]."""
    return (element.id in _SEQUENCES and bool(element.children) and element.children[0].id in ROBOT_CUES
            and any(n.id in ROBOT_RESPONSES for n in element.walk()))


def standing_reaction(document: TreeDocument) -> TreeElement | None:
    """The main tree's root when it is a reaction around a routine: a ReactiveFallback whose children
    but the last are robot cue branches and whose last child is the routine (or such a fallback last in a
    root sequence, after the walk there: generation/passing_look.react_once_there); else None."""
    root = document.main
    if root.id in _SEQUENCES and root.children and root.children[-1].id == "ReactiveFallback":
        root = root.children[-1]  # the walk there, then the reaction around the stay (a look once in place)
    if root.id != "ReactiveFallback" or len(root.children) < 2:
        return None
    *reactions, routine = root.children
    if not all(is_reaction_branch(r) for r in reactions) or is_reaction_branch(routine):
        return None
    return root


def keep_reacting_after_task(document: TreeDocument, hold_seconds: float) -> bool:
    """Put run-once-then-hold inside the tree's reaction to the robot (in place; module doc). True when
    the tree has such a reaction (and now keeps it after its routine), False when it is left as it was."""
    if any(e.get("name") == RUN_ONCE_NAME for e in document.nodes()):
        return False
    root = standing_reaction(document)
    if root is None:
        return False
    root.children[-1] = run_once_then_hold(root.children[-1], hold_seconds)
    return True
