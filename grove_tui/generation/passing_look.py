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

from grove_tui.analysis.outcomes import PASS_AT, PASS_BY
from grove_tui.bt.format.document import TreeDocument
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


# People who look as the robot passes them where they stay (a queue, a wait) look once there: within this many
# metres of the place their routine walks them to, or of their queue's counter with the line behind it.
IN_PLACE = 1.5
_STAYING = frozenset({"queue", "wait", "converse"})
_HELD_REACTIONS = frozenset({"ApproachRobot", "BlockRobot"})  # their own posts (approach/block_at_place.py)


def cued_as_it_passes(tree: DraftNode, group: GroupReading, reading: PromptReading) -> DraftNode:
    """A look tied to the robot passing turns them to it as it passes (within PASS_AT), not as soon as it is
    within a look's 10 m: a glance cued at 10 m fired at t = 0 and was over before the robot came by the desk.
    People who stay somewhere look once there: a patient who spawned beside the robot's start looked at the
    waiting robot at t = 0, once only, and never as it passed the queue (an IsAtPosition, pointed by in_place)."""
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


def in_place(document: TreeDocument, members: int) -> None:
    """Point the IsAtPosition of a look cued once they are there (cued_as_it_passes) at the place their routine
    puts them: the queue's counter, with the line of `members` behind it, else the last place they walk to;
    without such a place the check is dropped (they look wherever they are), in place."""
    places = [e for e in document.nodes() if e.id in ("Queue", "GoTo") and e.get("x") is not None]
    queue = next((e for e in places if e.id == "Queue"), None)
    there = queue or (places[-1] if places else None)
    for element in list(document.nodes()):
        kids = element.children
        for i, check in enumerate(kids):
            if (check.id != "IsAtPosition" or i == 0 or kids[i - 1].id != "IsRobotClose"
                    or check.get("target_x") is not None or check.get("goal_id") is not None
                    or any(k.id in _HELD_REACTIONS for k in kids)):
                continue
            if there is None:
                del kids[i]
                break
            line = float(queue.get("spacing") or 0.6) * max(members - 1, 0) if queue is not None else 0.0
            check.set("target_x", str(there.get("x")))
            check.set("target_y", str(there.get("y")))
            check.set("tolerance", f"{min(IN_PLACE + line, 10.0):.2f}")


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
