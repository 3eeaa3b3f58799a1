"""A look tied to the moment the robot passes is checked in that moment, not at any time.

"A guide looks up as the robot passes the desk": the look claim was checked as a glance at any time the
robot was within LOOK_RANGE, and in one run the robot was within 10 m of the guide for 2 s and never came by
the desk while they looked, yet the look read ✓. A reaction the sentence ties to the robot passing
(language/passing_moment.py) now carries that moment: the claim's `moment` is "pass", and its `point` the
place passed (within PASS_AT of it), else the people themselves (within PASS_BY of them). The probe
(analysis/outcomes._RobotLookProbe) counts only looks in those frames and says when the robot passed and
when they looked.
"""

from __future__ import annotations

from dataclasses import replace

from grove_tui.scenario.reach import PASS_AT, PASS_BY
from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.generation.draft import DraftNode
from grove_tui.language.model import GroupReading, PromptReading
from grove_tui.scenario.report import Claim
from grove_tui.world.model import Door, Entity, World


def _point(world: World, place: str) -> tuple[float, float] | None:
    try:
        obj = world.find(place)
    except Exception:
        return None
    if isinstance(obj, Entity):
        return obj.interaction_point
    if isinstance(obj, Door):
        return obj.inward_point(0.6)
    return None  # a zone: the people themselves are the moment's place


# People who look as the robot passes them where they stay (a queue, a wait) look once there: the cue is marked
# with an IsAtPosition (no point) and react_once_there moves the reaction after the walk.
IN_PLACE = 1.5
_STAYING = frozenset({"queue", "wait", "converse"})
_WALKS = frozenset({"GoTo", "JoinGroup"})  # the way there, before the stay the reaction goes round


def cued_as_it_passes(tree: DraftNode, group: GroupReading, reading: PromptReading) -> DraftNode:
    """A look tied to the robot passing turns them to it as it passes (within PASS_AT), not as soon as it is
    within a look's 10 m: a glance cued at 10 m fired at t = 0 and was over before the robot came by the desk.
    People who stay somewhere look once there: a patient who spawned beside the robot's start looked at the
    waiting robot at t = 0, once only, and never as it passed the queue (marked here, moved by react_once_there)."""
    if group.robot_interaction != "look" or not group.reacts_as_robot_passes:
        return tree
    # as it passes a place: within PASS_AT; as it passes them: within PASS_BY, the window the look is checked in
    # (cued at PASS_AT, queueing patients the robot passed at 4.2 m never turned: 2/6 looked)
    cued = _cued(tree, PASS_AT if group.passed_place else PASS_BY)
    return _once_there(cued) if (group.routine or group.intent) in _STAYING else cued


def _cued(tree: DraftNode, reach: float) -> DraftNode:
    ports = dict(tree.ports)
    if tree.node == "IsRobotClose" and float(ports.get("threshold", 0.0)) > reach:
        ports["threshold"] = reach
    return DraftNode(tree.node, ports, tuple(_cued(c, reach) for c in tree.children))


def _once_there(tree: DraftNode) -> DraftNode:
    children = tuple(_once_there(c) for c in tree.children)
    if children and children[0].node == "IsRobotClose" and not any(c.node == "IsAtPosition" for c in children):
        children = (children[0], DraftNode("IsAtPosition", {"tolerance": IN_PLACE}), *children[1:])
    return DraftNode(tree.node, dict(tree.ports), children)


def react_once_there(document: TreeDocument) -> None:
    """A look cued once they are there (cued_as_it_passes marks its cue with an IsAtPosition): the reaction
    moves inside the routine, after the walk there, in place. "ReactiveFallback[cue, Sequence[GoTo, Queue]]"
    becomes "Sequence[GoTo, ReactiveFallback[cue, Queue]]": the patient who walked past the waiting robot
    on the way to the counter no longer spends the look then (HuNavSim reactions fire once), and looks as it
    passes the queue. A routine that is no walk and a stay keeps the reaction around it, unmarked."""
    marked = False
    for element in document.nodes():  # the mark goes whatever the shape: an IsAtPosition with no point fails
        kids = element.children
        if kids and kids[0].id == "IsRobotClose":
            kept = [c for c in kids if not (c.id == "IsAtPosition" and c.get("target_x") is None
                                            and c.get("goal_id") is None)]
            marked |= len(kept) < len(kids)
            element.children = kept
    root = document.main
    if not marked or root.id != "ReactiveFallback" or len(root.children) != 2:
        return
    cue, routine = root.children
    if routine.id not in ("Sequence", "SequenceWithMemory"):
        return
    steps = routine.children
    walks = next((i for i, c in enumerate(steps) if c.id not in _WALKS), len(steps))
    if walks == 0 or walks == len(steps):
        return
    stay = steps[walks:]
    inner = stay[0] if len(stay) == 1 else TreeElement(routine.id, dict(routine.attributes), list(stay))
    document.trees[document.main_tree_id].children[0] = TreeElement(
        routine.id, dict(routine.attributes), [*steps[:walks], TreeElement("ReactiveFallback", {}, [cue, inner])])


def passing_looks(claims: list[Claim], group: GroupReading, reading: PromptReading, world: World) -> list[Claim]:
    """The group's look claim tied to the moment the robot passes, when the sentence ties it there."""
    if not any(c.kind == "robot_look" for c in claims):
        return claims
    passed = group.passed_place
    if not group.reacts_as_robot_passes:
        return claims
    point = _point(world, passed) if passed else None
    out = []
    for c in claims:
        if c.kind != "robot_look":
            out.append(c)
            continue
        if point is None and passed and world.zone_of_place(passed) == passed:
            # "as it passes the gateline", a zone: while the robot is in it, not near them anywhere
            out.append(replace(c, asked=c.asked + f", as the robot passes {passed}", moment="pass",
                               place=passed, point=None))
        elif point is not None:
            out.append(replace(c, asked=c.asked + f", as the robot passes {passed}", moment="pass",
                               place=passed, point=(round(point[0], 3), round(point[1], 3)), radius=PASS_AT))
        else:
            out.append(replace(c, asked=c.asked + ", as the robot passes them", moment="pass", radius=PASS_BY,
                               distance=PASS_BY))  # checked within PASS_BY of them, cued there
    return out
